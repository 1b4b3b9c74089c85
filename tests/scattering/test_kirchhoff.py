"""Kirchhoff / geometric optics (eq 7) and slope densities against closed forms."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from seaecho.geometry import frames
from seaecho.scattering.fresnel import fresnel_coefficients
from seaecho.scattering.kirchhoff import kirchhoff_matrix, kirchhoff_sigma
from seaecho.scattering.slopes import (
    cox_munk_parameters,
    cox_munk_pdf,
    gaussian_slope_pdf,
    u12_5_from_u19_5,
)
from seaecho.scattering.validity import KirchhoffValidityWarning

EPS = 55.9 - 37.0j


def test_nadir_backscatter_equals_fresnel_over_mss():
    # Classic GO result (Barrick 1968; Valenzuela 1978): at nadir backscatter
    # sigma0 = |R(0)|^2 / mss for isotropic Gaussian slopes of total mss = 2 s^2.
    s2 = 0.012
    sig = kirchhoff_sigma(0.0, 0.0, 0.0, np.pi, EPS, s2, s2)
    r0 = abs(fresnel_coefficients(1.0, EPS)[0]) ** 2
    np.testing.assert_allclose(sig[[0, 3]], r0 / (2 * s2), rtol=1e-12)
    assert sig[1] == 0 and sig[2] == 0


def test_monostatic_go_closed_form():
    # Monostatic GO (Barrick 1968; Valenzuela 1978): sigma0 = |R(0)|^2 sec^4(t) / mss
    # exp(-tan^2(t) / mss) for isotropic slopes; at backscatter the specular facet is
    # normal to the ray, so R is taken at normal incidence.
    s2 = 0.01
    th = np.radians(np.array([5.0, 10.0, 15.0]))
    sig = kirchhoff_sigma(th, 0.3, th, 0.3 + np.pi, EPS, s2, s2, warn=False)
    r0 = abs(fresnel_coefficients(1.0, EPS)[0]) ** 2
    ref = r0 / np.cos(th) ** 4 / (2 * s2) * np.exp(-np.tan(th) ** 2 / (2 * s2))
    np.testing.assert_allclose(sig[:, 0], ref, rtol=1e-10)
    np.testing.assert_allclose(sig[:, 3], ref, rtol=1e-10)


def test_forward_specular_channels_are_fresnel():
    # Forward specular of the mean plane: the specular facet is flat, F = diag(R_h, R_v).
    th = 0.6
    n_i, n_s = frames.directions_from_angles(th, 0.2, th, 0.2)
    f = kirchhoff_matrix(n_i, n_s, EPS)
    r_h, r_v = fresnel_coefficients(np.cos(th), EPS)
    np.testing.assert_allclose(f, [[r_h, 0], [0, r_v]], atol=1e-14)


angle = st.floats(0.0, np.radians(88.0))
azim = st.floats(-np.pi, np.pi)


@settings(max_examples=150, deadline=None)
@given(angle, azim, angle, azim)
def test_reciprocity_and_passivity(ti, pi_, ts, ps):
    assume(all(t == 0.0 or np.sin(t) > 1e-7 for t in (ti, ts)))
    kw = dict(mss_upwind=0.02, mss_crosswind=0.01, wind_direction=0.4, warn=False)
    s1 = kirchhoff_sigma(ti, pi_, ts, ps, EPS, **kw)
    s2 = kirchhoff_sigma(ts, ps + np.pi, ti, pi_ + np.pi, EPS, **kw)
    # Reciprocity: sigma_mn(i -> s) = sigma_nm(-s -> -i).
    np.testing.assert_allclose(s1, s2[[0, 2, 1, 3]], rtol=1e-8, atol=1e-12 * s1.max() + 1e-300)
    # F is a rotation of diag(R_h, R_v): each column's power is at most max |R|^2 <= 1.
    n_i, n_s = frames.directions_from_angles(ti, pi_, ts, ps)
    f = kirchhoff_matrix(n_i, n_s, EPS)
    assert np.all(np.sum(np.abs(f) ** 2, axis=0) <= 1.0 + 1e-12)
    assert np.all(np.isfinite(s1)) and np.all(s1 >= 0)


def test_grazing_and_qz_zero_are_finite():
    for ti, ts, ps in [(np.pi / 2, np.pi / 2, 0.0), (np.pi / 2, np.pi / 2, np.pi),
                       (np.pi / 2, 0.0, 0.0), (1.5707, 1.5707, 0.001)]:
        s = kirchhoff_sigma(ti, 0.0, ts, ps, EPS, 0.01, 0.01, warn=False)
        assert np.all(np.isfinite(s)) and np.all(s >= 0)


def test_warns_far_from_specular():
    # theta_i = 20 deg, theta_s = 69 deg back towards the transmitter: beta = 44 deg.
    with pytest.warns(KirchhoffValidityWarning):
        kirchhoff_sigma(0.35, 0.0, 1.2, np.pi, EPS, 0.01, 0.01)


@pytest.mark.parametrize("u", [1.0, 5.0, 10.0, 14.0])
def test_cox_munk_density_moments(u):
    # Cox & Munk (1954) eq 2: unit integral, the variances sigma_u^2, sigma_c^2, and the
    # skewness of the downwind slope equal to c03 (sign convention of slopes.py).
    p = cox_munk_parameters(u)
    x = np.linspace(-12, 12, 1201)
    zu, zc = np.meshgrid(x * np.sqrt(p.mss_upwind), x * np.sqrt(p.mss_crosswind), indexing="ij")
    dz = (x[1] - x[0]) ** 2 * np.sqrt(p.mss_upwind * p.mss_crosswind)
    pdf = cox_munk_pdf(zu, zc, p) * dz
    # Clipping the negative tail of the series changes the total by < 1e-3 up to 14 m/s.
    assert abs(pdf.sum() - 1) < 1e-3
    assert abs((pdf * zu**2).sum() / p.mss_upwind - 1) < 1e-2
    assert abs((pdf * zc**2).sum() / p.mss_crosswind - 1) < 1e-2
    skew = (pdf * zu**3).sum() / p.mss_upwind**1.5
    assert abs(skew - p.c03) < 0.03


@pytest.mark.parametrize("u", [2.0, 5.0, 8.0])
def test_cox_munk_fourth_moments_are_the_published_peakedness(u):
    # Cox & Munk (1954), eq 2 and sec. 6: the coefficients of the fourth-order terms are
    # the excess moments of the normalised slopes, E[xi^4] - 3 = c40, E[xi^2 eta^2] - 1 =
    # c22, E[eta^4] - 3 = c04, measured on the clean surface as c40 = 0.40 +- 0.23,
    # c22 = 0.12 +- 0.06, c04 = 0.23 +- 0.41 (independent of the wind speed). The values
    # are written here as published, not read from the code.
    p = cox_munk_parameters(u)
    x = np.linspace(-12, 12, 1201)
    zu, zc = np.meshgrid(x * np.sqrt(p.mss_upwind), x * np.sqrt(p.mss_crosswind), indexing="ij")
    dz = (x[1] - x[0]) ** 2 * np.sqrt(p.mss_upwind * p.mss_crosswind)
    pdf = cox_munk_pdf(zu, zc, p) * dz
    xi, eta = zc / np.sqrt(p.mss_crosswind), -zu / np.sqrt(p.mss_upwind)
    assert (pdf * xi**4).sum() - 3.0 == pytest.approx(0.40, abs=0.02)
    assert (pdf * xi**2 * eta**2).sum() - 1.0 == pytest.approx(0.12, abs=0.02)
    assert (pdf * eta**4).sum() - 3.0 == pytest.approx(0.23, abs=0.02)
    # At nadir backscatter the specular slope is 0, where the series is
    # 1 + c40/8 + c22/4 + c04/8 = 1.10875 times the Gaussian of the same variances:
    # sigma0 = |R(0)|^2 / (2 sigma_u sigma_c) x 1.10875 (Barrick 1968 with eq 2).
    sig = kirchhoff_sigma(0.0, 0.0, 0.0, np.pi, EPS, 0.0, 0.0, cox_munk=p)
    r0 = abs(fresnel_coefficients(1.0, EPS)[0]) ** 2
    ref = r0 / (2 * np.sqrt(p.mss_upwind * p.mss_crosswind)) * (1 + 0.40 / 8 + 0.12 / 4
                                                                 + 0.23 / 8)
    np.testing.assert_allclose(sig[[0, 3]], ref, rtol=1e-12)


def test_cox_munk_clean_surface_mss():
    # Cox & Munk (1954) fit the total clean-surface mss separately:
    # 0.003 + 5.12e-3 U +- 0.004; the sum of their two component fits must agree within that.
    p = cox_munk_parameters(10.0)
    assert abs(p.mss_upwind + p.mss_crosswind - (0.003 + 5.12e-3 * 10.0)) < 0.004
    # Log profile: U12.5 < U19.5 by a few per cent.
    assert 0.95 < u12_5_from_u19_5(10.0) / 10.0 < 0.98


def test_gaussian_density_integrates_to_one():
    x = np.linspace(-1, 1, 801)
    zu, zc = np.meshgrid(x, x, indexing="ij")
    total = gaussian_slope_pdf(zu, zc, 0.02, 0.01).sum() * (x[1] - x[0]) ** 2
    np.testing.assert_allclose(total, 1.0, rtol=1e-9)


@settings(max_examples=100, deadline=None)
@given(angle, azim, angle, azim)
def test_perfect_conductor_matrix_is_the_mirror_law(ti, pi_, ts, ps):
    # Independent of eq K2's rotations: a perfectly conducting facet of normal N reflects
    # a field p into 2 (N . p) N - p (image theory); projected on the global scattered
    # bases this must equal F for eps -> infinity.
    n_i, n_s = frames.directions_from_angles(ti, pi_, ts, ps)
    assume(np.linalg.norm(n_s - n_i) > 1e-3)
    assume(all(t == 0.0 or np.sin(t) > 1e-7 for t in (ti, ts)))
    nsp = (n_s - n_i) / np.linalg.norm(n_s - n_i)
    f = kirchhoff_matrix(n_i, n_s, 1e20 + 0j)
    h_i, v_i = frames.polarisation_basis(n_i)
    h_s, v_s = frames.polarisation_basis(n_s)
    for col, p in enumerate((h_i, v_i)):
        e_r = 2 * np.dot(nsp, p) * nsp - p
        np.testing.assert_allclose(f[:, col], [np.dot(h_s, e_r), np.dot(v_s, e_r)],
                                   atol=1e-6)


def test_cox_munk_most_probable_slope_ascends_downwind():
    # Cox & Munk (1954), abstract: "the most probable slope at high winds is not zero but
    # a few degrees, with the azimuth of ascent pointing downwind". With z_u = dz/du
    # (u downwind) the mode of the density along the wind must be a positive slope of a
    # few degrees (2.3 deg at 14 m/s), and the crosswind section is symmetric.
    p = cox_munk_parameters(14.0)
    z = np.linspace(-0.5, 0.5, 100_001)
    mode = z[np.argmax(cox_munk_pdf(z, 0.0 * z, p))]
    assert 1.0 < np.degrees(np.arctan(mode)) < 5.0
    np.testing.assert_allclose(cox_munk_pdf(0.0 * z, z, p), cox_munk_pdf(0.0 * z, -z, p))
    # A weak wind is nearly Gaussian: mode within 0.3 deg of zero.
    p1 = cox_munk_parameters(1.0)
    mode1 = z[np.argmax(cox_munk_pdf(z, 0.0 * z, p1))]
    assert abs(np.degrees(np.arctan(mode1))) < 0.3
