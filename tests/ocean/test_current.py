"""A uniform surface current in the sea's motion (eq C1 of seaecho.ocean.dispersion).

Closed forms: a wave of vector K on a depth-uniform current U turns at omega_0(K) + K.U
(Phillips 1977, The Dynamics of the Upper Ocean, section 3.6; Kirby & Chen 1989, the
uniform-current limit), so that the sea on a current is the still-water sea advected by U,
z_U(r, t) = z_0(r - U t, t), and the Eulerian vertical rate at a fixed point is
w - U . grad z. The echo's Doppler centroid moves by q . U / (2 pi), i.e. 2 U . r_hat /
lambda in monostatic (r_hat the unit vector towards the radar; docs/conventions.md:
exp(+j omega t), a scatterer approaching gives a positive Doppler).
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from seaecho.ocean.dispersion import angular_frequency, doppler_shifted_frequency
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.rng import generator


def _surface(current, precision="double"):
    spec = DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=8.0, wind_direction=0.3)
    return SeaSurface(spec, size=(64.0, 48.0), shape=(32, 48), rng=generator(5, "surface"),
                      precision=precision, current=current)


def test_each_wave_turns_at_omega0_plus_k_dot_u():
    u = (0.4, -0.25)
    s = _surface(u)
    t = 1.7
    plus, minus = s._travelling_at(t)
    kx, ky = np.broadcast_arrays(s._kx, s._ky)
    w0 = angular_frequency(np.hypot(kx, ky))
    i = np.unravel_index(np.argmax(np.abs(s._a)), s._a.shape)
    # wave along +K: omega_0 + K.U; wave along -K: omega_0 - K.U (eq C1)
    assert plus[i] / s._a[i] == pytest.approx(
        np.exp(-1j * (w0[i] + kx[i] * u[0] + ky[i] * u[1]) * t), abs=1e-12)
    j = np.unravel_index(np.argmax(np.abs(s._b)), s._b.shape)
    assert minus[j] / s._b[j] == pytest.approx(
        np.exp(1j * (w0[j] - kx[j] * u[0] - ky[j] * u[1]) * t), abs=1e-12)
    assert doppler_shifted_frequency(2.0, 3.0, -1.0, (0.5, 0.25)) == pytest.approx(3.25)


def test_sea_on_a_current_is_the_still_sea_advected():
    # U t = (3 dx, -2 dy): z_U(r, t) = z_0(r - U t, t) is a roll of the grid, exactly
    s0 = _surface((0.0, 0.0))
    t = 2.5
    u = (3 * s0.dx / t, -2 * s0.dy / t)
    su = _surface(u)
    z0, zu = s0.elevation(t), su.elevation(t)
    assert np.abs(zu - np.roll(z0, (-2, 3), axis=(0, 1))).max() < 1e-12 * np.abs(z0).max()
    assert np.abs(zu - z0).max() > 0.1 * np.abs(z0).max()  # and it did move
    # still water: the bytes of a surface made without a current
    ref = SeaSurface(DirectionalSpectrum("elfouhaily", "elfouhaily", u19_5=8.0, wind_direction=0.3),
                     size=(64.0, 48.0), shape=(32, 48), rng=generator(5, "surface"),
                     precision="double")
    assert np.array_equal(ref.fields(t).velocity, s0.fields(t).velocity)


def test_velocity_is_the_rate_at_the_fixed_node():
    # the Eulerian rates (w - U.grad z, dD/dt - U.grad D) against centred differences
    from seaecho.sea import surface_kinematics

    s = _surface((0.6, 0.35))
    t, dt = 1.3, 1e-4
    f = s.fields(t)
    dz = (s.elevation(t + dt) - s.elevation(t - dt)) / (2 * dt)
    dd = (surface_kinematics(s, t + dt, False).displacement
          - surface_kinematics(s, t - dt, False).displacement) / (2 * dt)
    scale = np.abs(dz).max()
    assert np.abs(f.velocity[..., 2] - dz).max() < 1e-5 * scale
    assert np.abs(f.velocity[..., :2] - dd).max() < 1e-5 * np.abs(dd).max()
    # without the advection terms the vertical rate would be off by U.grad z
    adv = 0.6 * f.slope_x + 0.35 * f.slope_y
    assert np.abs(adv).max() > 0.05 * scale


@pytest.mark.slow
@pytest.mark.parametrize("mode", ["analytic", "raytraced"])
def test_doppler_centroid_moves_by_two_u_dot_r_over_lambda(mode):
    """Evolving sea, X band, 45 deg incidence, radar east of the tile: a current of
    0.5 m/s towards the radar (+x) moves the HH and VV centroids by 2 U sin(45 deg) /
    lambda = +23.6 Hz (measured: 0.9996 and 0.9941 of it on this 16 m, 8 x 8 tile, 32
    pulses; 1.046 on a 16 x 16 grid, 48 pulses; raytraced, the fused kernel's evolving
    path: 1.013 and 0.990); tolerance 10 % (one short record: the advected resolved waves
    change the facets' own Doppler by a fraction of the orbital spread). About 3.5 s
    each: slow."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples"))
    from sea_doppler import scene

    from seaecho.constants import C0
    from seaecho.processing.doppler import (
        clutter_cells,
        doppler_moments,
        doppler_spectrum,
        range_doppler,
    )
    from seaecho.simulation import Simulation

    cen = []
    for u in (0.0, 0.5):
        sc = scene(8.0, 0.0, 45.0, "blend", size=16.0, n=8, n_pulses=32, update=4)
        sc = sc.model_copy(update={
            "sea": sc.sea.model_copy(update={"current_m_s": (u, 0.0)}),
            "tracing": sc.tracing.model_copy(update={"mode": mode})})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = Simulation(sc)
            assert (sim._resident is not None) == (mode == "raytraced")
            rc = np.array([sim.compress(sim.pulse(p)) for p in range(sim.radar.n_pulses)])
        f, psd = range_doppler(rc, sim.radar.prf)
        c, _ = doppler_moments(f, doppler_spectrum(f, psd, clutter_cells(psd, 20.0)))
        cen.append(c)
    expected = 2 * 0.5 * np.sin(np.radians(45.0)) / (C0 / 10e9)
    np.testing.assert_allclose(cen[1] - cen[0], expected, rtol=0.1)


def _scene(**sea):
    from seaecho.config import parse_scene

    return parse_scene({"sea": {"spectrum": "elfouhaily", "wind_speed_m_s": 8.0,
                                "size_x_m": 16.0, "nx": 8, **sea}})


def test_wind_drift_wu_and_the_scene_keys():
    # Wu (1975): surface drift 0.53 u*; u* of Wu's (1982) drag law, C_D = (0.8 + 0.065
    # U10) 1e-3: at U10 = 10 m/s, u* = 0.3808 m/s and the drift 0.2018 m/s (2.0 % of U10)
    from seaecho.build import sea_current
    from seaecho.ocean.wind import u10_from_u19_5, wind_drift_wu

    ux, uy = wind_drift_wu(10.0, np.pi / 2)
    assert (ux, uy) == pytest.approx((0.0, 0.53 * 10.0 * np.sqrt(1.45e-3)), abs=1e-12)
    assert uy == pytest.approx(0.2018, abs=1e-4)
    assert sea_current(_scene()) == (0.0, 0.0)
    sc = _scene(current_m_s=[0.1, -0.2], wind_drift="wu", wind_direction_deg=30.0)
    dx, dy = wind_drift_wu(float(u10_from_u19_5(8.0)), np.radians(30.0))
    assert sea_current(sc) == pytest.approx((0.1 + dx, -0.2 + dy), abs=1e-12)
    with pytest.raises(ValueError, match=r"current_m_s\[0\] = 6 m/s"):
        _scene(current_m_s=[6.0, 0.0])
    with pytest.raises(ValueError, match="coverage = 'radar': not implemented yet"):
        _scene(current_m_s=[0.1, 0.0], coverage="radar")


def test_surface_drift_3pct_against_the_published_fractions():
    # AMS Glossary of Meteorology: the surface drift is "2.5%-3.0% of the wind speed",
    # "a rough estimate of wind drift is 3% of the wind speed"; Wu (1975): the total
    # surface drift approaches "about 3.5%" of the wind at very long fetch
    from seaecho.build import sea_current
    from seaecho.ocean.wind import surface_drift_3pct, u10_from_u19_5

    for u10 in (3.0, 7.6, 10.0, 20.0):
        ux, uy = surface_drift_3pct(u10, np.radians(120.0))
        assert np.hypot(ux, uy) / u10 == pytest.approx(0.03, abs=1e-12)
        assert 0.025 <= np.hypot(ux, uy) / u10 <= 0.035
        assert np.degrees(np.arctan2(uy, ux)) == pytest.approx(120.0, abs=1e-9)
    assert surface_drift_3pct(10.0, 0.0) == pytest.approx((0.30, 0.0), abs=1e-12)
    sc = _scene(wind_drift="3pct", wind_direction_deg=-45.0)
    u = 0.03 * float(u10_from_u19_5(8.0))
    assert sea_current(sc) == pytest.approx((u / np.sqrt(2), -u / np.sqrt(2)), abs=1e-12)
    # an explicit law on a radar-coverage sea is refused; "auto" resolves to none there
    with pytest.raises(ValueError, match="wind_drift = '3pct' with coverage = 'radar'"):
        _scene(wind_drift="3pct", coverage="radar")
    assert sea_current(_scene(coverage="radar", size_x_m=64.0, nx=16)) == (0.0, 0.0)


def test_dynamic_hull_on_a_current_is_refused_by_the_scene_as_by_the_run():
    # the hull's dynamic response needs the travelling waves, not built for a sea on a
    # current: the scene refuses it (so `seaecho check` does), naming the fields
    from seaecho.config import SceneError, parse_scene

    boat = {"name": "b", "length_m": 8.0, "beam_m": 2.5, "draft_m": 0.8, "speed_m_s": 0.0,
            "position_m": (0.0, 0.0), "hull_echo": True, "wave_motion": True,
            "kelvin_wake": False}
    scene = {"sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 32,
                     "current_m_s": [0.3, 0.0]},
             "radar": {"carrier_frequency_hz": 1.3e9, "sampling_rate_hz": 50e6,
                       "prf_hz": 100.0, "n_pulses": 2, "channels": ["HH"],
                       "waveform": {"kind": "lfm", "bandwidth_hz": 40e6,
                                    "duration_s": 1e-6}},
             "transmitter": {"position_m": (-300, 0, 30),
                             "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}},
             "ships": [boat]}
    with pytest.raises(SceneError, match=r"wave_response = 'dynamic' on a sea with "
                       r"\[sea\] current_m_s = \[0.3, 0.0\].*not implemented yet"):
        parse_scene(scene)
    quasi = dict(scene, ships=[dict(boat, wave_response="quasi-static")])
    assert parse_scene(quasi).sea.current_m_s == (0.3, 0.0)


def test_auto_drift_is_none_with_a_dynamic_hull_and_on_radar_coverage():
    # "auto" is the 3 % surface drift on an evolving tile, and none where a current
    # cannot be simulated: a hull's dynamic response (refused on a current, above) and
    # coverage = "radar" (no current yet), even where the sea evolves.
    from seaecho.build import sea_current, sea_motion, wind_drift
    from seaecho.config import parse_scene

    boat = {"name": "b", "length_m": 8.0, "beam_m": 2.5, "draft_m": 0.8, "speed_m_s": 0.0,
            "position_m": (0.0, 0.0), "hull_echo": True, "wave_motion": True,
            "kelvin_wake": False}
    scene = {"sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 32},
             "radar": {"carrier_frequency_hz": 1.3e9, "sampling_rate_hz": 50e6,
                       "prf_hz": 100.0, "n_pulses": 8, "sea_update_pulses": 1,
                       "channels": ["HH"],
                       "waveform": {"kind": "lfm", "bandwidth_hz": 40e6,
                                    "duration_s": 1e-6}},
             "transmitter": {"position_m": (-300, 0, 30),
                             "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}},
             "ships": [boat]}
    dynamic = parse_scene(scene)
    assert sea_motion(dynamic) == "evolving" and wind_drift(dynamic) == "none"
    assert sea_current(dynamic) == (0.0, 0.0)
    quasi = parse_scene(dict(scene, ships=[dict(boat, wave_response="quasi-static")]))
    assert wind_drift(quasi) == "3pct" and sea_current(quasi) != (0.0, 0.0)
    radar = parse_scene({**scene, "ships": [], "sea": {**scene["sea"], "coverage": "radar"}})
    assert sea_motion(radar) == "evolving" and wind_drift(radar) == "none"
