"""Narrow-V wake: arm half-angle, decay along the arms, limits (eqs N1-N7).

Published observations the tests compare with:

* Half-angles of narrow-V wakes in SEASAT L-band images are of 1-4 deg (Reed & Milgram
  2002, Annu. Rev. Fluid Mech. 34, 469-502; Munk, Scully-Power & Zachariasen 1987), "a
  bright V with a narrow half angle of 2-3 deg" (Zilman & Miloh, Proc. 21st Symp. Naval
  Hydrodynamics, NAP 1997, p. 235, after Milgram 1988); Shemdin (1990, J. Geophys. Res.
  95(C9)): "the half angles ... are consistent with first-order Bragg surface wave
  theory" and "the decay rate along the bright arms ... is consistent with the combined
  viscous and radiation decay of short surface waves with first-order Bragg wavelengths".
* Kelvin's half-angle asin(1/3) = 19.47 deg (Lamb 1932, art. 256) as the gravity limit of
  the ray law (Lighthill 1978, section 3.10).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest

from seaecho.constants import C0, NU_SEA_WATER, SURFACE_TENSION_OVER_DENSITY, G
from seaecho.ocean.dispersion import group_to_phase_ratio, phase_speed, wavenumber_of_phase_speed
from seaecho.wake import KELVIN_HALF_ANGLE, Ship, narrow_v_amplitude, narrow_v_bragg_gain
from seaecho.wake.empirical import BREAKING_SLOPE
from seaecho.wake.narrow_v import (
    narrow_v_half_angle,
    plane_wave_periodogram,
    ray_angle,
    steady_wave_angle,
)


def _bragg(frequency_hz: float, incidence_deg: float) -> float:
    """Monostatic Bragg wavenumber 2 k sin(incidence) [rad/m]."""
    return 2.0 * (2.0 * np.pi * frequency_hz / C0) * np.sin(np.deg2rad(incidence_deg))


SEASAT_KB = _bragg(1.275e9, 23.0)  # SEASAT L band, 23 deg: k_B = 20.9 rad/m
X45_KB = _bragg(10.0e9, 45.0)  # the paper's Simulation 2: 296 rad/m


def test_gravity_limit_is_kelvins_wedge():
    """n = 1/2 (gravity waves): eq N2 is Kelvin's ray, whose largest angle is
    asin(1/3) = 19.47 deg at tan theta = 1/sqrt 2 (Lamb 1932, art. 256)."""
    theta = np.linspace(0.0, 1.55, 200001)
    alpha = ray_angle(theta, 0.5)
    t = np.tan(theta)
    np.testing.assert_allclose(alpha, np.arctan(t / (1.0 + 2.0 * t * t)), atol=1e-14)
    assert alpha.max() == pytest.approx(KELVIN_HALF_ANGLE, abs=1e-9)
    assert theta[np.argmax(alpha)] == pytest.approx(np.arctan(1.0 / np.sqrt(2.0)), abs=1e-4)


def test_group_to_phase_ratio_limits():
    """c_g / c: 1/2 for gravity waves, 1 at the phase-speed minimum k_m, 3/2 for capillary
    waves (Lamb 1932, art. 267)."""
    k_m = np.sqrt(G / SURFACE_TENSION_OVER_DENSITY)
    assert group_to_phase_ratio(1e-3) == pytest.approx(0.5, abs=1e-9)
    assert group_to_phase_ratio(k_m) == pytest.approx(1.0, abs=1e-12)
    assert group_to_phase_ratio(1e6) == pytest.approx(1.5, abs=1e-6)


def test_wavenumber_of_phase_speed_inverts_the_dispersion_relation():
    """Both roots of tau k^2 - c^2 k + g = 0 have phase speed c (eq 15')."""
    for k in (5.0, 100.0, 296.0, 1000.0):
        c = float(phase_speed(k))
        kk = wavenumber_of_phase_speed(c, capillary=k > np.sqrt(G / SURFACE_TENSION_OVER_DENSITY))
        assert kk == pytest.approx(k, rel=1e-9)


@pytest.mark.parametrize("speed", [5.0, 6.0, 8.0, 10.0, 13.0])
def test_seasat_half_angles_in_the_published_range(speed):
    """SEASAT L band (k_B = 20.9 rad/m): ships of 10-25 kn give half-angles inside the
    1-4 deg of the SEASAT narrow-V wakes (Reed & Milgram 2002)."""
    alpha_deg = np.rad2deg(narrow_v_half_angle(speed, SEASAT_KB))
    assert 1.0 <= alpha_deg <= 4.0


def test_typical_ship_gives_two_to_three_degrees():
    """A 13-18 kn ship at L band: 2-3 deg (Zilman & Miloh 1997, after Milgram 1988)."""
    for speed in (6.9, 9.2):  # 13.4 and 17.9 kn
        assert 2.0 <= np.rad2deg(narrow_v_half_angle(speed, SEASAT_KB)) <= 3.0


@pytest.mark.parametrize("k_b", [SEASAT_KB, 100.0, X45_KB, 600.0])
def test_small_angle_limit_is_group_speed_over_ship_speed(k_b):
    """Eq N3: alpha -> c_g(k_B) / V when the ship is much faster than the Bragg waves;
    the relative error of eq N3 is of order (c / V)^2."""
    c = float(phase_speed(k_b))
    c_g = float(group_to_phase_ratio(k_b)) * c
    for speed in (30.0 * c, 100.0 * c):
        alpha = float(narrow_v_half_angle(speed, k_b))
        assert alpha == pytest.approx(c_g / speed, rel=2.0 * (c / speed) ** 2)


def test_no_narrow_v_without_speed():
    """A ship at rest, or slower than the Bragg waves' phase speed, makes no steady wave
    of the Bragg wavenumber: no half-angle, no gain."""
    assert np.isnan(narrow_v_half_angle(0.0, X45_KB))
    c_b = float(phase_speed(X45_KB))
    assert np.isnan(narrow_v_half_angle(0.99 * c_b, X45_KB))
    assert np.isfinite(narrow_v_half_angle(1.01 * c_b, X45_KB))
    x = np.arange(128) * 0.25 - 16.0
    for speed in (0.0, 0.99 * c_b):
        ship = Ship(10.0, 4.0, 1.5, speed, heading=np.pi / 2, position0=(0.0, 10.0))
        gain = narrow_v_bragg_gain(ship, x, x, 0.0, (X45_KB, 0.0), 1e-13)
        assert gain.shape == (128, 128) and not np.any(gain)


def test_decay_along_the_arm_is_radiation_and_viscous():
    """Eq N5: the energy along an arm falls as R^-1 (geometric spreading of the
    stationary-phase wave) times exp(-4 nu k^2 t), t = R / |u_e| its age (Lamb 1932,
    art. 348): Shemdin's (1990) "combined viscous and radiation decay"."""
    ship = Ship(10.0, 4.0, 1.5, 5.144)
    for k in (SEASAT_KB, X45_KB):
        r1, r2 = 40.0, 160.0
        a1, a2 = narrow_v_amplitude(ship, k, [r1, r2])
        theta = float(steady_wave_angle(ship.speed, k))
        n = float(group_to_phase_ratio(k))
        u_e = ship.speed * np.hypot(1.0 - n * np.cos(theta) ** 2,
                                    n * np.cos(theta) * np.sin(theta))
        expected = (r1 / r2) * np.exp(-4.0 * NU_SEA_WATER * k * k * (r2 - r1) / u_e)
        assert (a2 / a1) ** 2 == pytest.approx(expected, rel=1e-9)
    # X band decays within tens of metres, L band over kilometres
    e_fold_x = ship.speed / (4.0 * NU_SEA_WATER * X45_KB**2)
    assert 10.0 < e_fold_x < 20.0


def test_arms_not_steeper_than_breaking():
    """Eq N4's cap: where a wave leaves the near field its slope a k is at most the
    limiting steepness pi 0.1412 (Williams 1981)."""
    ship = Ship(10.0, 4.0, 1.5, 5.144)
    lam0 = 2.0 * np.pi * ship.speed**2 / G
    for k in (SEASAT_KB, 100.0, X45_KB):
        r0 = 0.5 * ship.length + 0.5 * lam0  # cos(alpha) ~ 1 within 1e-3
        assert k * narrow_v_amplitude(ship, k, r0) <= BREAKING_SLOPE * 1.001


def _arm_profile(heading: float, bragg_vector):
    """Gain across the track 40 m behind midship (ship at the origin at t = 0)."""
    ship = Ship(10.0, 4.0, 1.5, 5.144, heading=heading)
    x = np.arange(-24.0, 24.0, 0.25)
    y = np.arange(-64.0, 8.0, 0.25)
    gain = narrow_v_bragg_gain(ship, x, y, 0.0, bragg_vector, 1e-13)
    return ship, x, y, gain


def test_arms_lie_at_the_half_angle_when_the_radar_looks_across_the_track():
    """Ship sailing north (+y), radar's Bragg vector east: two arms at y' tan(alpha_B)
    either side of the track, within one cell; the arms are where the gain is (the sea
    between and outside them is left alone)."""
    ship, x, y, gain = _arm_profile(np.pi / 2, (X45_KB, 0.0))
    alpha_b = float(narrow_v_half_angle(ship.speed, X45_KB))
    row = gain[np.argmin(np.abs(y + 40.0))]
    for side in (x < 0, x > 0):
        peak = x[side][np.argmax(row[side])]
        assert abs(abs(peak) - 40.0 * np.tan(alpha_b)) <= 0.25
    assert row.max() > 1.0
    assert row[np.abs(x) > 4.0].max() < 1e-3 * row.max()


def test_no_arms_when_the_radar_looks_along_the_track():
    """The arms' waves run across the track: a radar whose Bragg vector lies along the
    track does not see them (narrow-V wakes are seen when ships sail near the SAR's
    azimuth direction: Tunaley; Shemdin 1990 imaged azimuthally travelling ships)."""
    _, _, _, across = _arm_profile(np.pi / 2, (X45_KB, 0.0))
    _, _, _, along = _arm_profile(np.pi / 2, (0.0, X45_KB))
    assert along.max() < 1e-3 * across.max()


def _sim2_scene(**ship):
    import tomllib

    from seaecho.config import parse_scene

    with open("scenes/paper_sim2_sar_128m_wind55.toml", "rb") as f:
        data = tomllib.load(f)
    data["ship"].update(ship)
    data["sea"].update({"size_x_m": 64.0, "nx": 256})
    return parse_scene(data)


def test_scene_key_reaches_the_scattering_model():
    """[ship] narrow_v = true, the paper's boat sailing north under the Simulation 2 SAR
    (flying north, looking east: the Bragg vector lies across the track): the sea's wake
    mask goes negative in the arms, and the facet model's sigma0 there rises by
    10 log10(1 + g) in HH and in VV (Bragg scattering at 45 deg; eq N7), the sea
    elsewhere unchanged. Off (the default), the mask is the turbulent wake's alone."""
    from seaecho.build import build_sea, build_sea_model
    from seaecho.geometry import frames
    from seaecho.scattering.facet import facet_sigma

    scene = _sim2_scene(narrow_v=True, heading_deg=90.0, position_m=[0.0, 30.0])
    on = build_sea(scene).state(0.0).wake_mask
    off = build_sea(_sim2_scene(heading_deg=90.0, position_m=[0.0, 30.0])).state(0.0).wake_mask
    assert off.min() >= 0.0
    assert on.min() < -1.0  # the Bragg spectrum more than doubled in the arms
    np.testing.assert_array_equal(on[on >= 0.0] == 0.0, off[on >= 0.0] == 0.0)
    d = np.array([on.min(), 0.0])
    sea = build_sea_model(scene)
    ti = np.full(2, np.radians(45.0))
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ti, np.pi)
    args = (n_i, n_s, np.broadcast_to(frames.Z_HAT, n_i.shape), sea.facet_model)
    sig = facet_sigma(*args, backend="numpy", wake_damping=d)
    rise_db = 10.0 * np.log10(sig[0, [0, 3]] / sig[1, [0, 3]])
    np.testing.assert_allclose(rise_db, 10.0 * np.log10(1.0 - d[0]), atol=0.3)


@pytest.mark.parametrize("kw", [(296.0, 0.0), (290.0, 13.0), (280.0, -20.0), (30.0, 5.0)])
def test_facet_periodogram_against_direct_quadrature(kw):
    """Eq N6 against the facet's Fourier integral by quadrature: |int z e^{-i K_B.r}|^2 /
    (4 pi^2 dx dy) for z = a cos(k_w . r + phase) on a 0.25 m facet (Rice 1951: the
    first-order cross section of a facet is 16 pi k^4 |alpha|^2 times this), averaged
    over the phases 0.3 and 0.3 + pi/2, which cancels the +-k_w cross term that eq N6
    leaves out (2.7 % of the peak at X band for one phase; it averages out over the
    facets' random phases)."""
    a, dx, dy, k_b = 1e-3, 0.25, 0.25, (296.0, 0.0)
    n = 400
    u = (np.arange(n) + 0.5) / n - 0.5
    xx, yy = np.meshgrid(u * dx, u * dy)
    direct = 0.0
    for phase in (0.3, 0.3 + 0.5 * np.pi):
        z = a * np.cos(kw[0] * xx + kw[1] * yy + phase)
        f = np.sum(z * np.exp(-1j * (k_b[0] * xx + k_b[1] * yy))) * (dx / n) * (dy / n)
        direct += 0.5 * abs(f) ** 2 / (4.0 * np.pi**2 * dx * dy)
    model = float(plane_wave_periodogram(a, kw[0], kw[1], k_b, dx, dy))
    peak = float(plane_wave_periodogram(a, k_b[0], k_b[1], k_b, dx, dy))
    assert model == pytest.approx(direct, abs=1e-3 * peak)
