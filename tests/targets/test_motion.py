"""A hull following the sea under its waterplane (eq S1 of seaecho.targets.motion).

Closed forms: on a plane sea z = z0 + s_x x + s_y y the hull takes that plane exactly
(heave the plane's height at the centre, pitch and roll its slopes along and across the
heading); on a wave much longer than the hull, heave -> the elevation and pitch -> the
slope at the centre (the long-wave limit of the motion transfer functions, Faltinsen
1990, ch. 2); a wave of length L / 2 along the hull averages to no heave.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.targets.motion import hull_rotation, waterplane_motion

X = np.arange(-200.0, 200.0, 0.5)
Y = np.arange(-150.0, 150.0, 0.5)


@pytest.mark.parametrize(("heading", "pitch", "roll"), [
    (0.0, np.arctan(0.02), np.arctan(-0.01)),       # forward +x, port +y
    (np.pi / 2, np.arctan(-0.01), np.arctan(-0.02)),  # forward +y, port -x
])
def test_plane_sea_is_followed_exactly(heading, pitch, roll):
    z = 0.3 + 0.02 * X[None, :] - 0.01 * Y[:, None]
    h, p, r = waterplane_motion(X, Y, z, (10.0, 5.0), heading, 40.0, 8.0)
    assert h == pytest.approx(0.3 + 0.2 - 0.05, abs=1e-12)
    assert p == pytest.approx(pitch, abs=1e-12)
    assert r == pytest.approx(roll, abs=1e-12)


def test_long_wave_limit():
    a, length = 1.0, 20.0
    k = 2 * np.pi / (20 * length)  # a wave 20 hull lengths long, travelling along x
    x0 = 37.0
    z = a * np.cos(k * X)[None, :] + 0 * Y[:, None]
    h, p, _ = waterplane_motion(X, Y, z, (x0, 0.0), 0.0, length, 4.0)
    # averaging over L changes the heave by (k L)^2 / 24 of a (0.4 %): within 1 %
    assert h == pytest.approx(a * np.cos(k * x0), abs=0.01 * a)
    assert p == pytest.approx(np.arctan(-a * k * np.sin(k * x0)), rel=0.01)


def test_short_wave_averages_out():
    length = 40.0
    k = 2 * np.pi / (length / 2)
    z = np.cos(k * X)[None, :] + 0 * Y[:, None]
    h, p, r = waterplane_motion(X, Y, z, (0.0, 0.0), 0.0, length, 8.0)
    assert abs(h) < 0.03 and abs(r) < 1e-9  # 0 but for the grid's discretisation


def test_off_the_tile_no_motion():
    z = np.ones((Y.size, X.size))
    assert waterplane_motion(X, Y, z, (1e4, 0.0), 0.0, 40.0, 8.0) == (0.0, 0.0, 0.0)


def test_hull_rotation_bow_up_and_starboard_down():
    r = hull_rotation(np.pi / 2, 0.1, 0.2)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-15)
    bow = r @ np.array([0.0, 1.0, 0.0])  # heading north: the bow points +y
    assert bow[2] == pytest.approx(np.sin(0.1))
    port = r @ np.array([-1.0, 0.0, 0.0])  # port is west
    assert port[2] == pytest.approx(np.sin(0.2) * np.cos(0.1), rel=1e-12)  # roll, then pitch


def test_hull_centres_ride_the_sea():
    # the hull echo's centres heave, pitch and roll with the held sea (rigidly)
    from types import SimpleNamespace

    from seaecho.targets.motion import hull_rotation as rot
    from seaecho.tracing.hull_echo import Hull, HullEchoes
    from seaecho.tracing.scene import ObjectGeometry

    shape = ObjectGeometry("s", np.zeros((3, 3)), np.array([[0, 1, 2]], dtype=np.uint32),
                           np.array([10.0, 5.0, 0.0]), np.eye(3), np.array([2.0, 0.0, 0.0]))
    hull = Hull("s", [shape], [None], None, False, 1.0, 0.0, np.zeros(1, dtype=np.intp),
                (40.0, 8.0))
    z = 0.3 + 0.02 * X[None, :] - 0.01 * Y[:, None]
    state = SimpleNamespace(x=X, y=Y, elevation=z)
    echoes = HullEchoes([hull], [shape], None, 80.0, 0.0, surface=lambda t: state,
                        disk_cache=SimpleNamespace(enabled=False))
    t = 5.0  # the origin is then at (20, 5, 0)
    pts = np.array([[40.0, 5.0, 3.0], [20.0, 9.0, 0.0]])
    out = echoes.in_waves(0, pts, t)
    heave = 0.3 + 0.02 * 20.0 - 0.01 * 5.0
    r = rot(0.0, np.arctan(0.02), np.arctan(-0.01))
    o = np.array([20.0, 5.0, 0.0])
    np.testing.assert_allclose(out, o + (pts - o) @ r.T + [0.0, 0.0, heave], atol=1e-12)
    assert out[0, 2] > pts[0, 2] + heave - 1e-9  # the bow rises on the up-slope


def _wave_motion_scene(**ship):
    boat = {"name": "b", "length_m": 8.0, "beam_m": 2.5, "draft_m": 0.8, "speed_m_s": 0.0,
            "position_m": (0.0, 0.0), "hull_echo": True, "wave_motion": True,
            "kelvin_wake": False, **ship}
    return {"sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 32},
            "radar": {"carrier_frequency_hz": 1.3e9, "sampling_rate_hz": 50e6,
                      "prf_hz": 100.0, "n_pulses": 2, "channels": ["HH"],
                      "waveform": {"kind": "lfm", "bandwidth_hz": 40e6, "duration_s": 1e-6}},
            "transmitter": {"position_m": (-300, 0, 30),
                            "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}},
            "ships": [boat]}


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore::seaecho.warnings.SeaechoWarning")
def test_a_ship_with_quasi_static_wave_motion_rides_the_held_sea():
    from seaecho.config import parse_scene
    from seaecho.simulation import Simulation

    sim = Simulation(parse_scene(_wave_motion_scene(wave_response="quasi-static")))
    t = float(sim.radar.emission_time(1))
    st = sim.surface_state_at(t)
    att = sim.hulls.attitude(0, t)
    assert att == waterplane_motion(st.x, st.y, st.elevation, (0.0, 0.0), 0.0, 8.0, 2.5)
    assert att[0] != 0.0 and att[1] != 0.0


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SeaechoWarning")
def test_a_ship_with_wave_motion_runs_and_rides_the_sea():
    from seaecho.config import SceneError, parse_scene
    from seaecho.simulation import Simulation

    d = _wave_motion_scene()
    sim = Simulation(parse_scene(d))
    t = float(sim.radar.emission_time(1))
    # the default, dynamic response: eq S3 on the run's own sea (its wave components)
    w = WaveComponents(*sim.sea.surface.components())
    att = sim.hulls.attitude(0, t)
    assert att == BoxHullMotion(8.0, 2.5, 0.8, 0.05 * 2.5).attitude(w, (0.0, 0.0), 0.0,
                                                                      (0.0, 0.0), t)
    assert att[0] != 0.0 and att[2] != 0.0
    raw = sim.pulse(1)
    assert np.isfinite(raw).all() and np.abs(raw).max() > 0
    with pytest.raises(SceneError, match="sea_clutter"):
        parse_scene({**d, "radar": {**d["radar"], "sea_clutter": False}})
    with pytest.raises(SceneError, match="wave_motion"):
        parse_scene(_wave_motion_scene(wave_motion=False, metacentric_height_m=0.3))


# ---------------------------------------------------------------- dynamic response
# Closed forms and an independent method for eqs S2-S5 (seaecho.targets.motion): the
# response of a damped oscillator (|H(0)| = 1, |H(omega_n)| = 1 / (2 zeta), 90 deg behind
# the forcing: e.g. Journee & Massie 2001, ch. 6), checked against a time-domain
# integration of the oscillator driven by the waterplane average of a regular wave met by
# a moving hull (a quadrature over the rectangle, not eq S4's closed form).

from seaecho.constants import G  # noqa: E402
from seaecho.targets.motion import (  # noqa: E402
    BoxHullMotion,
    WaveComponents,
    oscillator_response,
)


def _regular_wave(amplitude, wavelength, direction, phase=0.0, backward=False):
    """One wave z = A cos(K.r - omega t + phase) travelling along ``direction`` [rad], K
    along ``direction``; ``backward``: the same wave as the component b of -K, z =
    Re[b e^{+j omega t} e^{-j K.r}] with b = A e^{-j phase} (the second half of eq 12')."""
    k = 2 * np.pi / wavelength
    omega = np.sqrt(G * k)
    amp = np.array([amplitude * np.exp(1j * phase)])
    kx, ky = np.array([k * np.cos(direction)]), np.array([k * np.sin(direction)])
    if backward:
        return WaveComponents(-kx, -ky, np.array([omega]), np.array([0j]), np.conj(amp),
                              np.array([1.0]))
    return WaveComponents(kx, ky, np.array([omega]), amp, np.array([0j]), np.array([1.0]))


def test_oscillator_limits():
    wn, zeta = 2.0, 0.1
    assert oscillator_response(0.0, wn, zeta) == pytest.approx(1.0)
    h = oscillator_response(np.array([wn, -wn]), wn, zeta)
    np.testing.assert_allclose(np.abs(h), 1 / (2 * zeta), rtol=1e-12)
    # e^{-j nu t} forcing: H = j / (2 zeta) is a quarter period behind
    assert np.angle(h[0]) == pytest.approx(np.pi / 2)
    assert abs(oscillator_response(1e3 * wn, wn, zeta)) < 1e-5


def test_long_slow_wave_heave_rao_is_one():
    # a wave 40 hull lengths long, far below the heave natural frequency: heave = z
    boat = BoxHullMotion(10.0, 3.0, 0.6, 0.15)
    wave = _regular_wave(0.5, 400.0, 0.0)
    period = 2 * np.pi / wave.omega[0]
    ts = np.linspace(0.0, period, 64, endpoint=False)
    att = np.array([boat.attitude(wave, (12.0, -4.0), 0.0, (0.0, 0.0), t) for t in ts])
    z = np.array([wave.elevation(12.0, -4.0, t) for t in ts])
    # the heave RAO |x| / A within 4 % of 1 ((omega / omega_n)^2 = 0.03), its phase lag
    # arctan(2 zeta r / (1 - r^2)) of the oscillator
    rao = np.sum(att[:, 0] * np.exp(1j * wave.omega[0] * ts)) / np.sum(
        z * np.exp(1j * wave.omega[0] * ts))
    assert abs(rao) == pytest.approx(1.0, abs=0.04)
    r = wave.omega[0] / boat.heave_frequency
    assert np.angle(rao) == pytest.approx(np.arctan2(2 * 0.2 * r, 1 - r * r), rel=0.01)
    # pitch: the wave slope's amplitude A k, within 4 % (the same pitch frequency)
    assert np.max(np.abs(np.tan(att[:, 1]))) == pytest.approx(0.5 * wave.kx[0], rel=0.04)


def _time_domain(motion, wave, heading, v, dof, t_end):
    """x(t_end) of eq S2 integrated in time, forced by the waterplane average (dof 0:
    elevation, 1: slope along, 2: slope across) of the wave at the moving centre."""
    from scipy.integrate import solve_ivp

    xg, wg = np.polynomial.legendre.leggauss(10)
    half_l, half_b = 0.5 * motion.length, 0.5 * motion.beam
    c, s = np.cos(heading), np.sin(heading)
    xi, eta = np.meshgrid(xg * half_l, xg * half_b, indexing="ij")
    ww = np.outer(wg, wg) / 4.0
    basis = (np.ones_like(xi), xi / (half_l**2 / 3), eta / (half_b**2 / 3))[dof]

    def forcing(t):
        cx, cy = v[0] * t, v[1] * t
        px, py = cx + xi * c - eta * s, cy + xi * s + eta * c
        e = np.exp(1j * (wave.kx[0] * px + wave.ky[0] * py))
        ph = np.exp(-1j * wave.omega[0] * t)
        z = np.real((wave.a[0] * ph + wave.b[0] * np.conj(ph)) * e)
        return float(np.sum(ww * basis * z))

    wn = (motion.heave_frequency, motion.pitch_frequency, motion.roll_frequency)[dof]
    zeta = motion.damping[dof]
    sol = solve_ivp(lambda t, y: [y[1], wn**2 * (forcing(t) - y[0]) - 2 * zeta * wn * y[1]],
                    (0.0, t_end), [0.0, 0.0], rtol=1e-8, atol=1e-11)
    return sol.y[0, -1]


@pytest.mark.parametrize(("dof", "wavelength", "direction", "speed", "backward"), [
    # heave, head-on wave near the natural frequency
    pytest.param(0, 25.0, 0.0, 0.0, False, marks=pytest.mark.slow),
    (0, 60.0, np.pi, 4.0, False),  # heave, following wave met at 4 m/s (encounter)
    # the same wave as a component b of -K: its encounter frequency -omega - K.V (eq S3)
    (0, 60.0, np.pi, 4.0, True),
    pytest.param(2, 60.0, np.pi / 2, 0.0, False, marks=pytest.mark.slow),  # roll, beam sea
])
def test_dynamic_response_matches_time_integration(dof, wavelength, direction, speed,
                                                   backward):
    boat = BoxHullMotion(10.0, 3.0, 0.6, 0.15)
    wave = _regular_wave(0.3, wavelength, direction, phase=0.4, backward=backward)
    v = (speed, 0.0)
    # transients decay as exp(-zeta omega_n t): below 1e-7 in heave at 40 s, 2e-4 in roll
    # at 150 s
    t_end = 40.0 if dof == 0 else 150.0
    x_td = _time_domain(boat, wave, 0.0, v, dof, t_end)
    att = boat.attitude(wave, (v[0] * t_end, 0.0), 0.0, v, t_end)
    x = att[0] if dof == 0 else np.tan(att[dof])
    scale = 0.3 if dof == 0 else 0.3 * 2 * np.pi / wavelength
    assert x == pytest.approx(x_td, abs=2e-3 * scale)


def test_roll_resonance_in_a_beam_sea():
    # a long beam wave at the natural roll frequency: roll = slope / (2 zeta), 90 deg late
    boat = BoxHullMotion(80.0, 12.0, 4.0, 0.6)
    wn = boat.roll_frequency
    assert 2 * np.pi / wn == pytest.approx(2 * np.pi * 0.35 * 12.0 / np.sqrt(G * 0.6))
    k = wn**2 / G
    wave = _regular_wave(0.5, 2 * np.pi / k, np.pi / 2)
    rolls = [boat.attitude(wave, (0.0, 0.0), 0.0, (0.0, 0.0), t)[2]
             for t in np.linspace(0, 2 * np.pi / wn, 64, endpoint=False)]
    static = 0.5 * k * np.sinc(k * 6.0 / np.pi)  # not quite the slope: B averaging small
    assert np.max(np.tan(rolls)) == pytest.approx(static / (2 * 0.05), rel=0.02)


def test_heave_natural_period_of_the_box():
    # eq S5 from its parts: restoring rho g L B over mass rho L B T plus added mass
    # rho pi B^2 L / 8
    L, B, T = 80.0, 12.0, 4.0
    box = BoxHullMotion(L, B, T, 1.0)
    assert box.heave_frequency**2 == pytest.approx(G * L * B / (L * B * T + np.pi * B**2 * L / 8))
    assert box.pitch_frequency == box.heave_frequency


def test_static_limit_is_the_waterplane_fit(monkeypatch):
    # H -> 1 (omega_n -> infinity): eq S3 becomes eq S1 on the continuous waterplane
    import seaecho.targets.motion as motion

    monkeypatch.setattr(motion, "oscillator_response", lambda nu, wn, z: np.ones_like(nu))
    stiff = BoxHullMotion(40.0, 8.0, 1.0, 1.0)
    wave = _regular_wave(0.4, 90.0, 0.6, phase=1.0)
    x, y = np.arange(-100.0, 100.0, 0.25), np.arange(-80.0, 80.0, 0.25)
    k, om = wave.kx[0], wave.ky[0]
    z = np.real(wave.a[0] * np.exp(1j * (k * x[None, :] + om * y[:, None])))
    fit = waterplane_motion(x, y, z, (3.0, -2.0), 0.3, 40.0, 8.0)
    att = stiff.attitude(wave, (3.0, -2.0), 0.3, (0.0, 0.0), 0.0)
    np.testing.assert_allclose(att, fit, atol=2e-3 * 0.4)


def test_wave_components_are_the_surface():
    # SeaSurface.components: the same z(x, y, t) as the surface's inverse FFT at its
    # nodes (all components kept; pruned: within the 1e-4 of the height variance left)
    from seaecho.ocean.spectra import DirectionalSpectrum
    from seaecho.ocean.surface import SeaSurface

    sp = DirectionalSpectrum(spectrum="elfouhaily", spreading="elfouhaily", u19_5=8.0,
                             wind_direction=0.3, fetch=None)
    surf = SeaSurface(sp, (256.0, 192.0), (48, 64), np.random.default_rng(1),
                      precision="double")
    z = surf.elevation(3.0)
    full = WaveComponents(*surf.components(0.0, 0.0, 10**9))
    pruned = WaveComponents(*surf.components())
    assert pruned.kx.size < full.kx.size
    for i, j in [(10, 20), (24, 32), (47, 3)]:
        assert full.elevation(surf.x[j], surf.y[i], 3.0) == pytest.approx(z[i, j], abs=1e-12)
        assert pruned.elevation(surf.x[j], surf.y[i], 3.0) == pytest.approx(
            z[i, j], abs=0.05 * z.std())


def test_slope_weight_is_a_spherical_bessel_function():
    # eq S4's m(k, a) = 3 j k (sin ka - ka cos ka) / (ka)^3 = 3 j k j_1(ka) / (ka), with
    # j_1(z) = sin z / z^2 - cos z / z the spherical Bessel function (Abramowitz & Stegun
    # 1964, 10.1.11), evaluated by scipy independently of the module's series near 0
    from scipy.special import spherical_jn

    from seaecho.targets.motion import _slope_weight

    a = 5.0
    ka = np.concatenate([np.geomspace(1e-6, 20.0, 200), [9.99e-4, 1.001e-3]])
    k = np.concatenate([ka, -ka]) / a
    want = 3j * k * spherical_jn(1, np.abs(k) * a) / (np.abs(k) * a)
    np.testing.assert_allclose(_slope_weight(k, a), want, rtol=1e-9, atol=0)
    assert _slope_weight(np.array([0.0]), a)[0] == 0.0


def test_a_ships_metacentric_height_sets_its_roll_period():
    # [[ships]] metacentric_height_m reaches the hull: T_4 = 2 pi k_xx / sqrt(g GM),
    # k_xx = 0.35 B (Journee & Massie 2001, ch. 6); default GM = 0.05 B (a modelling choice)
    from seaecho.build import _box_motion
    from seaecho.config import parse_scene

    for extra, gm in [({"metacentric_height_m": 0.3}, 0.3), ({}, 0.05 * 2.5)]:
        cfg = parse_scene(_wave_motion_scene(**extra)).all_ships[0]
        box = _box_motion(cfg)
        assert (box.length, box.beam, box.draft) == (8.0, 2.5, 0.8)
        assert 2 * np.pi / box.roll_frequency == pytest.approx(
            2 * np.pi * 0.35 * 2.5 / np.sqrt(G * gm), rel=1e-12)
