"""Physical-optics ray-tube kernels: reflection, currents, shape function."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.targets.po import (
    local_basis,
    po_components,
    po_vector,
    reflect,
    shape_function,
    tube_footprint,
)


def _random_geometry(n, rng):
    d = rng.standard_normal((n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    nrm = rng.standard_normal((n, 3))
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    nrm *= -np.sign(np.einsum("ij,ij->i", d, nrm))[:, None]  # facing the ray
    s = rng.standard_normal((n, 3))
    s /= np.linalg.norm(s, axis=1, keepdims=True)
    return d, nrm, s


def test_pec_reflection_reverses_the_tangential_field():
    # A perfect conductor (R_h = -1, R_v = +1 in the local FSA bases) reflects E into
    # E_r = -E + 2 (E . n) n at the surface (tangential E vanishes; Balanis 2012, 7.8),
    # for any incidence and polarisation.
    rng = np.random.default_rng(1)
    d, n, _ = _random_geometry(200, rng)
    e = rng.standard_normal((200, 2, 3)) + 1j * rng.standard_normal((200, 2, 3))
    e -= np.einsum("ipk,ik->ip", e, d)[..., None] * d[:, None, :]  # transverse to d
    ones = np.ones(200, dtype=complex)
    d_r, e_r = reflect(d, n, e, -ones, ones)
    expected = -e + 2 * np.einsum("ipk,ik->ip", e, n)[..., None] * n[:, None, :]
    np.testing.assert_allclose(e_r, expected, atol=1e-12)
    np.testing.assert_allclose(d_r, d - 2 * np.einsum("ij,ij->i", d, n)[:, None] * n,
                               atol=1e-15)
    # and the PO magnetic current vanishes, J = 2 n x H_i
    v = po_vector(d, d_r, n, e, e_r, -d)
    eta_j = 2 * np.cross(n[:, None, :], np.cross(d[:, None, :], e))
    proj = eta_j - np.einsum("ipk,ik->ip", eta_j, -d)[..., None] * (-d)[:, None, :]
    np.testing.assert_allclose(v, proj, atol=1e-12)


def test_scalar_form_equals_vector_form():
    # Parity: po_components (TE/TM amplitudes on real bases, used by the trace) gives the
    # components of po_vector (eqs O3-O4 written with vectors) on the receive basis, for
    # lossy and perfect materials.
    rng = np.random.default_rng(2)
    n_r = 300
    d, n, s = _random_geometry(n_r, rng)
    h_l, v_i = local_basis(d, n)
    alpha = rng.standard_normal((n_r, 2)) + 1j * rng.standard_normal((n_r, 2))
    beta = rng.standard_normal((n_r, 2)) + 1j * rng.standard_normal((n_r, 2))
    e = alpha[..., None] * h_l[:, None, :] + beta[..., None] * v_i[:, None, :]
    r_h = rng.uniform(-1, 0, n_r) + 0.1j * rng.standard_normal(n_r)
    r_v = rng.uniform(0, 1, n_r) + 0.1j * rng.standard_normal(n_r)
    d_r, e_r = reflect(d, n, e, r_h, r_v)
    vec = po_vector(d, d_r, n, e, e_r, s)
    h_s, v_s = local_basis(s, np.broadcast_to([0.0, 0.0, 1.0], s.shape))
    v_r = np.cross(h_l, d_r)
    vh, vv = po_components(alpha, beta, r_h, r_v, n, h_l, v_i, v_r, h_s, v_s)
    np.testing.assert_allclose(vh, np.einsum("ipk,ik->ip", vec, h_s), atol=1e-12)
    np.testing.assert_allclose(vv, np.einsum("ipk,ik->ip", vec, v_s), atol=1e-12)
    # V is transverse to s (a far field)
    assert np.abs(np.einsum("ipk,ik->ip", vec, s)).max() < 1e-12


def test_shape_function_is_the_parallelogram_integral():
    # F A = integral of exp(j w . r) over the parallelogram of edges a, b centred on the
    # origin, against a midpoint rule on 400 x 400 points (Ling et al. 1989, sec. III)
    rng = np.random.default_rng(3)
    a = np.array([[0.01, 0.002, 0.0]])
    b = np.array([[0.001, 0.008, 0.003]])
    for _ in range(3):
        w = rng.normal(0, 300, (1, 3))
        u = (np.arange(400) + 0.5) / 400 - 0.5
        pts = u[:, None, None] * a[0] + u[None, :, None] * b[0]
        area = np.linalg.norm(np.cross(a[0], b[0]))
        numeric = np.mean(np.exp(1j * pts @ w[0])) * area
        assert shape_function(w, a, b)[0] * area == pytest.approx(numeric, abs=1e-5 * area)


def test_footprint_area_is_cross_section_over_cosine():
    rng = np.random.default_rng(4)
    d, n, _ = _random_geometry(50, rng)
    a_p = np.cross(d, rng.standard_normal((50, 3)))
    b_p = np.cross(d, a_p)
    a, b, area = tube_footprint(a_p, b_p, d, n)
    cross = np.linalg.norm(np.cross(a_p, b_p), axis=1)
    np.testing.assert_allclose(area, cross / np.abs(np.einsum("ij,ij->i", d, n)), rtol=1e-9)
    assert np.abs(np.einsum("ij,ij->i", a, n)).max() < 1e-12  # in the facet's plane
