"""Tests of the polarisation frames (seaecho.geometry.frames).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.geometry import frames

angles = st.floats(0.0, np.pi / 2)
azimuths = st.floats(-np.pi, np.pi)


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_basis_matches_paper_fig2():
    # Paper Fig. 2 / eq 9 geometry: n_i along azimuth phi_i, h_i = z x n_i / |z x n_i|.
    n_i, n_s = frames.directions_from_angles(0.3, 0.7, 0.5, 2.0)
    h, v = frames.polarisation_basis(n_i)
    np.testing.assert_allclose(h, [-np.sin(0.7), np.cos(0.7), 0.0], atol=1e-15)
    # v_i points down-and-back for a downgoing wave: -(cos t cos p, cos t sin p, sin t).
    np.testing.assert_allclose(
        v, -np.array([np.cos(0.3) * np.cos(0.7), np.cos(0.3) * np.sin(0.7), np.sin(0.3)]),
        atol=1e-15)
    hs, vs = frames.polarisation_basis(n_s)
    np.testing.assert_allclose(
        vs, [np.cos(0.5) * np.cos(2.0), np.cos(0.5) * np.sin(2.0), -np.sin(0.5)], atol=1e-15)


@settings(max_examples=200, deadline=None)
@given(angles, azimuths, st.floats(-0.5, 0.5), st.floats(-0.5, 0.5))
def test_basis_orthonormal_and_rotation_proper(theta, phi, zx, zy):
    n_i, _ = frames.directions_from_angles(theta, phi, 0.0, 0.0)
    normal = _unit(np.array([-zx, -zy, 1.0]))
    for nn in (frames.Z_HAT, normal):
        h, v = frames.polarisation_basis(n_i, nn)
        for a, b in ((h, h), (v, v)):
            assert abs(np.dot(a, b) - 1.0) < 1e-12
        for a, b in ((h, v), (h, n_i), (v, n_i)):
            assert abs(np.dot(a, b)) < 1e-12
        np.testing.assert_allclose(np.cross(h, v), -n_i, atol=1e-12)
    a = frames.basis_rotation(n_i, frames.Z_HAT, normal)
    np.testing.assert_allclose(a @ a.T, np.eye(2), atol=1e-12)
    assert abs(np.linalg.det(a) - 1.0) < 1e-12


def test_local_angles_mean_plane_equal_input_angles():
    ti, pi_, ts, ps = 0.4, 0.3, 1.1, -2.5
    n_i, n_s = frames.directions_from_angles(ti, pi_, ts, ps)
    a, b, phi = frames.local_angles(n_i, n_s)
    np.testing.assert_allclose([a, b, phi], [ti, ts, ps - pi_], atol=1e-12)


def test_local_angles_of_tilted_facet_equal_rotated_geometry():
    # Rotating the whole configuration (directions and normal) leaves local angles fixed.
    ti, ts, dphi = 0.6, 0.9, 1.3
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ts, dphi)
    c, s = np.cos(0.2), np.sin(0.2)
    rot = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    a, b, phi = frames.local_angles(n_i @ rot.T, n_s @ rot.T, rot @ frames.Z_HAT)
    np.testing.assert_allclose([a, b, phi], [ti, ts, dphi], atol=1e-12)


def test_degenerate_nadir_is_limit_from_reference_azimuth():
    # At nadir the basis is the limit from azimuth 0 (reference = x).
    h, v = frames.polarisation_basis(np.array([0.0, 0.0, -1.0]))
    h_lim, v_lim = frames.polarisation_basis(_unit(np.array([1e-6, 0.0, -1.0])))
    np.testing.assert_allclose(h, h_lim, atol=1e-6)
    np.testing.assert_allclose(v, v_lim, atol=1e-6)
    ti, ts, phi = frames.local_angles([0.0, 0.0, -1.0], [0.0, 0.0, 1.0])
    assert np.isfinite([ti, ts, phi]).all() and phi == 0.0


def test_tilt_rotation_identity_for_flat_facet_and_composes():
    n_i, n_s = frames.directions_from_angles(0.5, 0.1, 0.7, 2.0)
    a_i, a_s = frames.tilt_rotation(n_i, n_s, frames.Z_HAT)
    np.testing.assert_allclose(a_i, np.eye(2), atol=1e-12)
    s = np.array([[1 + 2j, 3j], [-1, 0.5]])
    np.testing.assert_allclose(frames.to_global(s, a_i, a_s), s, atol=1e-12)
    # A field expressed in global components, rotated to local and back, is unchanged.
    normal = _unit(np.array([0.2, -0.1, 1.0]))
    a_i, a_s = frames.tilt_rotation(n_i, n_s, normal)
    np.testing.assert_allclose(a_i.T @ a_i, np.eye(2), atol=1e-12)


def test_beta_zero_at_specular_and_pi_half_without_q():
    n_i, n_s = frames.directions_from_angles(0.5, 0.0, 0.5, 0.0)
    assert frames.beta_angle(n_i, n_s) < 1e-7
    assert abs(frames.beta_angle(n_i, n_i) - np.pi / 2) < 1e-12
