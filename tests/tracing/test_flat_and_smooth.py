"""Ray-traced facets on closed-form surfaces: a flat sea and a smooth sinusoid."""

import numpy as np
import pytest

from seaecho.geometry.facets import analytic_facets
from seaecho.geometry.frames import local_angles
from seaecho.tracing.tracer import FacetTracer

N = 32
X = (np.arange(N) - N / 2) * 2.0
TX = np.array([-40.0, -300.0, 120.0])
RX = np.array([250.0, 60.0, 45.0])


@pytest.fixture(scope="module")
def tracer():
    return FacetTracer(X, X)


@pytest.mark.parametrize("rx", [None, RX], ids=["monostatic", "bistatic"])
def test_flat_sea_all_visible_local_equals_global(tracer, rx):
    f = tracer.facets(np.zeros((N, N)), None, TX, rx)
    assert f.n_facets == 2 * (N - 1) ** 2
    assert f.lit.min() == 1 and f.seen.min() == 1 and f.visibility.min() == 1
    np.testing.assert_array_equal(f.normal, np.tile([0.0, 0.0, 1.0], (f.n_facets, 1)))
    np.testing.assert_allclose(f.theta_i, f.theta_i_global, atol=1e-12)
    np.testing.assert_allclose(f.theta_s, f.theta_s_global, atol=1e-12)
    np.testing.assert_allclose(np.angle(np.exp(1j * (f.phi - f.phi_global))), 0.0, atol=1e-12)
    # local bases equal the global ones: the tilt rotations are identities
    np.testing.assert_allclose(f.rot_i, np.broadcast_to(np.eye(2), f.rot_i.shape), atol=1e-12)
    np.testing.assert_allclose(f.rot_s, np.broadcast_to(np.eye(2), f.rot_s.shape), atol=1e-12)
    # float64 ranges: exact distances
    rr = TX if rx is None else rx
    np.testing.assert_allclose(f.r_tx, np.linalg.norm(f.centroid - TX, axis=1), rtol=1e-15)
    np.testing.assert_allclose(f.r_rx, np.linalg.norm(f.centroid - rr, axis=1), rtol=1e-15)
    if rx is None:
        np.testing.assert_allclose(np.abs(f.phi), np.pi)  # backscatter


def test_flat_sea_global_angles_closed_form(tracer):
    """theta_i at a facet = atan(horizontal distance / height) for a flat sea."""
    f = tracer.facets(np.zeros((N, N)), None, TX, RX)
    d = f.centroid - TX
    np.testing.assert_allclose(f.theta_i_global, np.arctan2(np.hypot(d[:, 0], d[:, 1]), TX[2]),
                               atol=1e-12)


def test_smooth_surface_normals_match_analytic(tracer):
    """Ray-traced (mesh) normals vs analytic normals of z = A sin(k x) cos(k y).

    Tolerance: the facet slope is a one-cell finite difference, off from the exact slope
    at the centroid by at most |z''| h <= 2 A k^2 h (Taylor remainder; h = 2 m).
    """
    a, k = 0.5, 0.08
    xx, yy = np.meshgrid(X, X)
    z = a * np.sin(k * xx) * np.cos(k * yy)
    sx = a * k * np.cos(k * xx) * np.cos(k * yy)
    sy = -a * k * np.sin(k * xx) * np.sin(k * yy)
    ft = tracer.facets(z, None, TX, RX)
    fa = analytic_facets(X, X, z, sx, sy, None, TX, RX, shadowing="none")
    angle = np.arccos(np.clip(np.einsum("ij,ij->i", ft.normal, fa.normal), -1, 1))
    assert angle.max() < 2 * a * k**2 * 2.0
    # and the local angles are those of frames.local_angles with the ray-traced normals
    ti, ts, ph = local_angles(ft.n_i, ft.n_s, ft.normal)
    np.testing.assert_allclose(ft.theta_i, ti)
    np.testing.assert_allclose(ft.phi, ph)
    # smooth, gentle surface seen from above: nothing shadowed in either mode
    assert ft.visibility.min() == 1 and fa.visibility.min() == 1


@pytest.mark.parametrize("rx", [None, RX], ids=["monostatic", "bistatic"])
def test_drjit_frames_kernel_equals_numpy_reference(rx):
    """The Dr.Jit kernel reproduces geometry.facets.facet_frames (geometry.frames),
    degenerate directions included (a transmitter straight above flat facets)."""
    from seaecho.geometry.facets import facet_frames
    from seaecho.tracing.kernels import facet_frames_drjit

    rng = np.random.default_rng(3)
    n = rng.normal(size=(500, 3)) * 0.2
    n[:, 2] = 1.0
    n[:5] = (0.0, 0.0, 1.0)
    n /= np.linalg.norm(n, axis=1)[:, None]
    c = rng.uniform(-100, 100, (500, 3))
    c[:5] = (0.0, 0.0, 0.0)  # directly below the transmitter: n_i along -N
    tx = np.array([0.0, 0.0, 500.0])
    rr = tx if rx is None else rx
    a = facet_frames_drjit(c, n, tx, rr)
    b = facet_frames(c, n, tx, rr)
    assert a.keys() == b.keys()
    for key in a:
        if key.startswith("phi"):  # +-pi are the same azimuth (sign of a zero in atan2)
            np.testing.assert_allclose(np.angle(np.exp(1j * (a[key] - b[key]))), 0.0,
                                       atol=1e-12, err_msg=key)
        else:
            np.testing.assert_allclose(a[key], b[key], rtol=1e-12, atol=1e-12, err_msg=key)
