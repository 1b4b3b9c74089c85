"""The radar on a spherical Earth: targets past the horizon are not seen, the platform
is mapped onto the sphere, and the flat Earth is today's path, byte for byte.

References: the horizon (eq E2) and the grazing angle (eq E1, the law of cosines) of
seaecho.geometry.earth on the 4/3 Earth (Skolnik, *Introduction to Radar Systems*, 3rd
ed. 2001, chapter 8; Federal Standard 1037C, "radio horizon range").
"""

from __future__ import annotations

import numpy as np
import pytest

import seaecho
from seaecho.build import build_radar
from seaecho.checks.preflight import check_run
from seaecho.config import SceneError, parse_scene
from seaecho.geometry.earth import effective_radius, grazing_angle, horizon_range
from seaecho.radar.system import RadarSystem

R43 = effective_radius(4.0 / 3.0)


def _scene(targets, earth="spherical", sea_clutter=False, tx=(0.0, 0.0, 25.0)):
    return {
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 2, "sea_clutter": sea_clutter,
                  "transmit_power_w": 25e3, "channels": ["HH"],
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": tx, "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "propagation": {"earth": earth},
        "targets": targets}


@pytest.mark.parametrize("h_target", [0.0, 10.0])
def test_target_just_inside_and_beyond_the_horizon(h_target):
    d_h = float(horizon_range(25.0, h_target, R43))  # 20.6 km (+13.0 km)
    inside = {"name": "in", "position_m": (0.0, 0.995 * d_h, h_target), "rcs_m2": 1.0}
    beyond = {"name": "out", "position_m": (0.0, 1.005 * d_h, h_target), "rcs_m2": 1.0}
    radar = RadarSystem(build_radar(parse_scene(_scene([inside, beyond]))),
                        backend="numpy")
    echo = radar.target_echo(radar.geometry(0))
    assert echo.tau.size == 1  # only the target inside the horizon echoes
    assert echo.r_t[0] == pytest.approx(0.995 * d_h, rel=1e-3)
    alone = RadarSystem(build_radar(parse_scene(_scene([beyond]))), backend="numpy")
    assert alone.target_echo(alone.geometry(0)) is None
    flat = RadarSystem(build_radar(parse_scene(_scene([inside, beyond], earth="flat"))),
                       backend="numpy")
    assert flat.target_echo(flat.geometry(0)).tau.size == 2  # a flat Earth hides nothing


def test_radar_on_the_sphere_sees_the_origin_at_eq_e1_grazing():
    # the radar 8 km east, 30 m up: its line of sight to the origin's sea surface meets
    # it at the grazing angle of eq E1
    radar = RadarSystem(build_radar(parse_scene(_scene(
        [{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 1.0}], tx=(8000.0, 0.0, 30.0)))),
        backend="numpy")
    p = radar.tx.state(0.0).position
    r = float(np.linalg.norm(p))
    assert np.arcsin(p[2] / r) == pytest.approx(grazing_angle(30.0, r, R43), rel=1e-9)
    assert p[2] == pytest.approx(30.0 - 8000.0**2 / (2 * R43), abs=1e-3)  # eq E3 drop


def test_flat_earth_and_fixed_antenna_are_todays_path():
    """The keys' defaults (earth 'flat', scan 'fixed', transmit_phase 'coherent',
    multipath 'none') leave the radar model as before them and the run's samples the
    same bytes (the run of
    scenes/paper_sim1 with 3 pulses had the same sha256 as before these keys existed:
    docs/scanning.md)."""
    base = _scene([{"position_m": (500.0, 300.0, 5.0), "rcs_m2": 3.0}], earth="flat")
    base.pop("propagation")
    explicit = _scene([{"position_m": (500.0, 300.0, 5.0), "rcs_m2": 3.0}], earth="flat")
    explicit["transmitter"]["antenna"]["scan"] = {"mode": "fixed"}
    explicit["radar"]["transmit_phase"] = "coherent"
    explicit["propagation"]["multipath"] = "none"
    m = build_radar(parse_scene(base))
    assert m.earth is None and m.scan_period is None and m.transmit_phase == "coherent"
    a = seaecho.simulate(parse_scene(base), progress=False)
    b = seaecho.simulate(parse_scene(explicit), progress=False)
    assert a["raw"].values.tobytes() == b["raw"].values.tobytes()
    assert "sweep" not in a


def test_sea_tile_beyond_the_horizon_is_refused():
    far = _scene([], sea_clutter=True, tx=(0.0, -25000.0, 25.0))  # horizon 20.6 km
    with pytest.raises(SceneError, match=r"\[transmitter\].position_m.*radar horizon"):
        check_run(parse_scene(far), "far.toml")
    near = _scene([], sea_clutter=True, tx=(0.0, -3000.0, 25.0))
    check_run(parse_scene(near), "near.toml")
