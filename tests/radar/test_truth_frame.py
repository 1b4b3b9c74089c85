"""The frame of the ground truth on a spherical Earth, and why an object is hidden.

``truth_position`` is written in the scene's coordinates (on a spherical Earth:
Earth-following, x and y along the surface from the origin, z above the sphere: the
coordinates ``[[targets]]`` are given in, docs/scanning.md), ``truth_position_cartesian``
in the simulation's Cartesian frame tangent to the sphere at the origin (eq E4 of
seaecho.geometry.earth), where the platforms' tracks are; the truth's range is that of
the echo. References: Skolnik, *Introduction to Radar Systems*, 3rd ed. (2001), chapter
8 (the 4/3 Earth and its horizon, eq E2 of seaecho.geometry.earth).
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.config import parse_scene
from seaecho.geometry.earth import SphericalEarth, effective_radius, horizon_range
from seaecho.radar.truth import HIDDEN_REASONS
from seaecho.simulation import Simulation

R43 = effective_radius(4.0 / 3.0)


def _scene(targets, earth="spherical"):
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6,
                  "prf_hz": 1000.0, "n_pulses": 3, "sea_clutter": False,
                  "transmit_power_w": 25e3, "channels": ["HH"], "thermal_noise": False,
                  "waveform": {"kind": "pulse", "duration_s": 5e-8}},
        "transmitter": {"position_m": (0.0, -2000.0, 25.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "propagation": {"earth": earth}, "targets": targets})


def test_truth_position_is_in_the_scene_frame_and_its_range_is_the_echos():
    d_h = float(horizon_range(25.0, 10.0, R43))
    targets = [{"name": "boat", "position_m": (3000.0, 12000.0, 10.0),
                "velocity_m_s": (5.0, -2.0, 0.0), "rcs_m2": 10.0},
               {"name": "beyond", "position_m": (0.0, 1.01 * d_h - 2000.0, 10.0),
                "rcs_m2": 10.0}]
    sim = Simulation(_scene(targets))
    ds = sim.static_dataset()
    t = sim.radar.emission_time(np.arange(3))
    scene_xyz = np.array([3000.0, 12000.0, 10.0]) + t[:, None] * [5.0, -2.0, 0.0]
    earth = SphericalEarth(R43)
    pos = ds["truth_position"].values[:, 0]
    cart = ds["truth_position_cartesian"].values[:, 0]
    assert pos == pytest.approx(scene_xyz, abs=1e-9)  # the scene's coordinates
    assert cart == pytest.approx(earth.position(scene_xyz), abs=1e-6)  # eq E4
    assert cart[0, 2] < 10.0 - 12000.0**2 / (2 * R43) + 1.0  # dropped ~8.5 m
    assert "along the surface" in ds["truth_position"].attrs["frame"]
    # the truth's range is the echo's (monostatic: r_t), not the flat one of pos
    for p in range(3):
        echo = sim.radar.target_echo(sim.radar.geometry(p))
        assert echo.r_t.size == 1  # "beyond" is past the horizon
        # (the echo's r_t includes the target's motion during the flight, 5 m/s x 48 us)
        assert ds["truth_range"].values[p, 0] == pytest.approx(echo.r_t[0], abs=3e-4)
        assert ds["truth_range"].values[p, 0] == pytest.approx(
            np.linalg.norm(cart[p] - sim.radar.tx.state(t[p]).position), rel=1e-14)
        flat = np.linalg.norm(pos[p] - sim.radar.tx.state(t[p]).position)
        assert abs(flat - echo.r_t[0]) > 1e-3  # a flat-frame range would be off
    reason = ds["truth_hidden_reason"].values
    assert reason[:, 1].tolist() == [HIDDEN_REASONS.index("below_horizon")] * 3
    assert reason[:, 0].tolist() == [0, 0, 0]
    assert ds["truth_visible"].values.tolist() == [[1, 0]] * 3


def test_flat_earth_truth_frames_coincide():
    sim = Simulation(_scene([{"position_m": (100.0, 200.0, 3.0), "rcs_m2": 1.0}], "flat"))
    ds = sim.static_dataset()
    assert np.array_equal(ds["truth_position"].values,
                          ds["truth_position_cartesian"].values)
