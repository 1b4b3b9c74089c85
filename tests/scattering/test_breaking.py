"""Breaking-zone scattering (Kudryavtsev, Hauser, Caudal & Chapron 2003, "KHCC03").

Closed forms and limiting cases of the published model, and the properties of the
bistatic generalisation (reciprocity, non-polarised backscatter, finiteness).
"""

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.geometry import frames
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.wind import u10_from_u19_5, u19_5_from_u10
from seaecho.scattering.breaking import (
    EPS_WB,
    S_WB2,
    add_breaking,
    breaking_nrcs_monostatic,
    breaking_sigma,
    breaking_statistics,
    facet_breaking,
)
from seaecho.scattering.models import sea_sigma

K_X = 2 * np.pi * 9.3e9 / C0
K_C = 2 * np.pi * 5.3e9 / C0


def _mono(theta, phi=0.0):
    return frames.directions_from_angles(theta, phi, theta, phi + np.pi)


def test_khcc03_eq60_closed_form_and_limits():
    """KHCC03 eq 60: sec^4/s^2 exp(-tan^2/s^2) + eps/s^2 with s^2 = 0.19, eps = 0.005.

    At nadir it is (1 + eps)/s^2 = 5.289 (7.23 dB); at grazing the front term
    eps/s^2 = 0.0263 (-15.80 dB) is left.
    """
    th = np.radians(np.linspace(0.0, 89.9, 400))
    expected = (np.exp(-np.tan(th) ** 2 / S_WB2) / (np.cos(th) ** 4 * S_WB2)
                + EPS_WB / S_WB2)
    np.testing.assert_allclose(breaking_nrcs_monostatic(th), expected, rtol=1e-12)
    assert breaking_nrcs_monostatic(0.0) == pytest.approx(1.005 / 0.19, rel=1e-12)
    assert 10 * np.log10(breaking_nrcs_monostatic(np.pi / 2)) == pytest.approx(-15.798, abs=1e-3)
    # The bistatic form (BR5) without tilt reduces to eq 60 at backscatter, any azimuth.
    for phi in (0.0, 0.7, 2.0):
        n_i, n_s = _mono(th, phi)
        s = breaking_sigma(n_i, n_s)
        np.testing.assert_allclose(s[:, 0], expected, rtol=1e-9)
        np.testing.assert_allclose(s[:, 3], expected, rtol=1e-9)


def test_non_polarised_at_backscatter_and_in_plane():
    """KHCC03: breaking is non-polarised (HH = VV, no cross-pol at backscatter)."""
    rng = np.random.default_rng(3)
    th = rng.uniform(0, 1.5, 200)
    ph = rng.uniform(-np.pi, np.pi, 200)
    n_i, n_s = _mono(th, ph)
    s = breaking_sigma(n_i, n_s, wind_direction=0.3, mean_direction=0.8)
    np.testing.assert_allclose(s[:, 0], s[:, 3], rtol=1e-10)
    assert np.all(s[:, 1:3] < 1e-12 * s[:, :1])
    # Bistatic, in the plane of incidence (forward or backward half-plane).
    ts = rng.uniform(0, 1.5, 200)
    for phs in (0.0, np.pi):
        n_i, n_s = frames.directions_from_angles(th, 0.0, ts, phs)
        s = breaking_sigma(n_i, n_s)
        np.testing.assert_allclose(s[:, 0], s[:, 3], rtol=1e-10)
        assert np.all(s[:, 1:3] < 1e-12 * np.maximum(s[:, :1], 1e-300))


def test_reciprocity_and_power_conservation_bistatic():
    """sigma_mn(i -> s) = sigma_nm(-s -> -i); each column of T carries unit power."""
    rng = np.random.default_rng(7)
    n = 500
    ti, ts = rng.uniform(0, 1.55, n), rng.uniform(0, 1.55, n)
    pi_, ps = rng.uniform(-np.pi, np.pi, n), rng.uniform(-np.pi, np.pi, n)
    n_i, n_s = frames.directions_from_angles(ti, pi_, ts, ps)
    kw = dict(wind_direction=0.9, mean_direction=0.87)
    s = breaking_sigma(n_i, n_s, **kw).reshape(n, 2, 2)
    r = breaking_sigma(-n_s, -n_i, **kw).reshape(n, 2, 2)
    np.testing.assert_allclose(s, np.swapaxes(r, -1, -2), rtol=1e-9, atol=1e-14)
    # Power of each transmitted polarisation equals the scalar sigma_wb.
    np.testing.assert_allclose(s[:, 0, 0] + s[:, 1, 0], s[:, 0, 1] + s[:, 1, 1], rtol=1e-9)


def test_finite_over_sweeps_and_singular_geometries():
    """No NaN/inf from grazing to nadir, forward specular, Tx = Rx, facing away."""
    th = np.radians(np.linspace(0.0, 90.0, 181))
    for phs in (0.0, np.pi, np.pi / 2):
        n_i, n_s = frames.directions_from_angles(th, 0.0, th, phs)
        assert np.all(np.isfinite(breaking_sigma(n_i, n_s, mean_direction=0.9)))
    n_i = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 0.0, 1.0]])
    s = breaking_sigma(n_i, n_i)
    assert np.all(np.isfinite(s)) and np.all(s >= 0.0)
    # transmitter below the plane: no return
    assert np.all(breaking_sigma(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0])) == 0.0)


def test_tilt_is_khcc03_first_order_modulation():
    """BR5's mean tilt reproduces KHCC03's sigma_0wb (1 + M_wb theta_wb A_wb cos phi) to
    first order, M_wb = d ln sigma_0wb / d theta; upwind looks are brighter."""
    th = np.radians(np.array([25.0, 35.0, 45.0, 55.0]))
    tilt = 1e-3
    d = 1e-6
    log_s = np.log(breaking_nrcs_monostatic(th + d)) - np.log(breaking_nrcs_monostatic(th - d))
    m_wb = log_s / (2 * d)
    # radar looking upwind: look azimuth opposite to the wind direction (wind towards +x)
    n_i, n_s = _mono(th, np.pi)
    s_up = breaking_sigma(n_i, n_s, wind_direction=0.0, mean_direction=1.0, theta_wb=tilt)[:, 0]
    s0 = breaking_nrcs_monostatic(th)
    np.testing.assert_allclose(s_up / s0 - 1.0, -m_wb * tilt, rtol=2e-2)
    n_i, n_s = _mono(th, 0.0)
    s_down = breaking_sigma(n_i, n_s, wind_direction=0.0, mean_direction=0.87)[:, 0]
    n_i, n_s = _mono(th, np.pi)
    s_upw = breaking_sigma(n_i, n_s, wind_direction=0.0, mean_direction=0.87)[:, 0]
    assert np.all(s_upw > s_down)


def test_breaking_fraction_grows_with_wind_and_radar_wavenumber():
    """KHCC03 sec. 5: q grows with wind speed, and with k_r through k_wb = 0.1 k_r."""
    q_x = [breaking_statistics(u, K_X).q for u in (3, 5, 7, 10, 15, 20)]
    q_c = [breaking_statistics(u, K_C).q for u in (3, 5, 7, 10, 15, 20)]
    assert np.all(np.diff(q_x) > 0) and np.all(np.diff(q_c) > 0)
    assert np.all(np.array(q_x) > np.array(q_c))
    # k_wb saturates at 2 pi / 0.3 m: Ku and Ka band see the same breakers.
    assert breaking_statistics(10.0, 2 * np.pi * 14e9 / C0).q == pytest.approx(
        breaking_statistics(10.0, 2 * np.pi * 35e9 / C0).q, rel=1e-12)
    # breakers travel with the wind, at the phase speed of waves longer than 0.3 m
    st = breaking_statistics(10.0, K_X)
    assert 0.6 < st.mean_direction < 1.0
    assert st.mean_phase_speed > np.sqrt(9.80665 / st.k_wb)


def test_breakers_drift_at_their_mean_velocity_not_their_mean_speed():
    """Hansen et al. (2012) eq 19 (after K05): the breaking zones move at the
    Lambda-weighted mean of c(k) cos(phi), the mean velocity of the fronts along the wind,
    below the mean speed by the spread of the breaking directions. Checked against an
    independent quadrature of eq BR3 (midpoint rule in ln k and phi)."""
    from seaecho.ocean.dispersion import phase_speed
    from seaecho.scattering.breaking import breaking_front_density

    for u10 in (4.7, 7.6, 11.3):
        st = breaking_statistics(u10, K_X)
        edges = np.linspace(np.log(1e-3), np.log(st.k_wb), 2001)
        k = np.exp(0.5 * (edges[1:] + edges[:-1]))
        dk = np.diff(np.exp(edges))
        phi = np.linspace(-np.pi, np.pi, 361)[:-1] + np.pi / 360
        lam = breaking_front_density(k[:, None], phi[None, :], u10) * dk[:, None]
        v = float((lam * phase_speed(k)[:, None] * np.cos(phi)[None, :]).sum() / lam.sum())
        assert st.mean_velocity == pytest.approx(v, rel=5e-3)
        # the fronts spread about the wind: 0.87 of the mean speed at X band
        assert 0.8 < st.mean_velocity / st.mean_phase_speed < 0.92
    # at 10 GHz, U10 = 7.6 m/s: 0.97 m/s (the mean speed, 1.11 m/s, is not the velocity)
    st = breaking_statistics(7.6, 2 * np.pi * 10e9 / C0)
    assert (st.mean_velocity, st.mean_phase_speed) == pytest.approx((0.967, 1.111), abs=0.005)


def test_breaking_share_grows_with_wind_and_towards_grazing_hh():
    """KHCC03 (and Mouche et al. 2006): the non-polarised share of the NRCS grows with
    wind speed and incidence angle, and is larger in HH than in VV."""
    inc = np.radians(np.array([30.0, 45.0, 60.0, 75.0, 85.0]))
    shares = []
    for u10 in (5.0, 10.0, 15.0):
        spec = DirectionalSpectrum(u19_5=float(u19_5_from_u10(u10)))
        reg = sea_sigma("two-scale", inc, np.pi, inc, 0.0, 9.3e9, spec, 55 - 37j)
        tot = sea_sigma("two-scale+breaking", inc, np.pi, inc, 0.0, 9.3e9, spec, 55 - 37j)
        share = (tot - (1.0 - breaking_statistics(u10, K_X).q) * reg) / tot
        shares.append(share)
        assert np.all(np.diff(share[2:, 0]) > 0)  # HH share grows towards grazing
        assert share[-1, 0] > 0.5  # and dominates HH at 5 deg grazing
        assert np.all(share[:, 0] > share[:, 3])  # HH more than VV
    shares = np.array(shares)
    assert np.all(np.diff(shares[:, :, 0], axis=0) > 0)  # grows with wind


def test_sea_sigma_breaking_is_eq1_combination():
    """Parity: the ``+breaking`` models are (1 - q) sigma_regular + q sigma_wb (BR1)."""
    spec = DirectionalSpectrum(u19_5=8.0, wind_direction=0.4)
    th = np.radians([20.0, 50.0, 80.0])
    reg = sea_sigma("blend", th, 0.0, th, np.pi, 10e9, spec, 55 - 37j)
    tot = sea_sigma("blend+breaking", th, 0.0, th, np.pi, 10e9, spec, 55 - 37j)
    st = breaking_statistics(float(u10_from_u19_5(8.0)), 2 * np.pi * 10e9 / C0)
    n_i, n_s = _mono(th, 0.0)
    wb = breaking_sigma(n_i, n_s, wind_direction=0.4, mean_direction=st.mean_direction)
    np.testing.assert_allclose(tot, add_breaking(reg, wb, st.q), rtol=1e-12)


def test_facet_interface_flat_and_rotated():
    """A +z facet gives the mean-plane value; rotating geometry, normal and wind about z
    together leaves sigma unchanged; q outside [0, 1] is refused."""
    rng = np.random.default_rng(11)
    n = 64
    th, ts = rng.uniform(0.1, 1.4, n), rng.uniform(0.1, 1.4, n)
    n_i, n_s = frames.directions_from_angles(th, 0.3, ts, rng.uniform(0, 2 * np.pi, n))
    normal = np.tile([0.0, 0.0, 1.0], (n, 1))
    fb = facet_breaking(n_i, n_s, normal, 0.02, 0.5, 0.8)
    np.testing.assert_allclose(fb.sigma(), 0.02 * breaking_sigma(n_i, n_s, frames.Z_HAT, 0.5, 0.8),
                               rtol=1e-12)
    tilt = np.array([0.2, -0.1, 1.0]) / np.linalg.norm([0.2, -0.1, 1.0])
    a = 1.1
    rot = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1.0]])
    s1 = facet_breaking(n_i, n_s, np.tile(tilt, (n, 1)), 0.03, 0.5, 0.8).sigma()
    s2 = facet_breaking(n_i @ rot.T, n_s @ rot.T, np.tile(rot @ tilt, (n, 1)), 0.03,
                        0.5 + a, 0.8).sigma()
    # co- and cross-pol powers are invariant (the global bases rotate with the scene)
    np.testing.assert_allclose(s1, s2, rtol=1e-8, atol=1e-14)
    with pytest.raises(ValueError, match="q"):
        facet_breaking(n_i, n_s, normal, 1.5, 0.0, 0.8)
