"""The hull echo of a ship on waypoints: the hull follows the route and turns with it.

Closed forms: on a turn of rate omega at speed V the midship point runs on a circle of
radius R = V / omega about the turn's centre, the heading is h0 + omega t, and a point
fixed on the hull at r from midship moves at V (cos h, sin h) + omega z x r (rigid-body
kinematics); the echo's delay is the two-way range of the hull there and its Doppler
f_D = -2 u . v / lambda (Willis 2005, eq 3.23; u the line of sight, v the velocity).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seaecho.config import parse_scene
from seaecho.constants import C0, KNOT
from seaecho.processing.range_compression import range_compress
from seaecho.simulation import Simulation
from seaecho.tracing.hull_echo import Hull
from seaecho.tracing.scene import ObjectGeometry, rotation_matrix
from seaecho.wake.ship import Route, Ship

SCENES = Path(__file__).resolve().parents[2] / "scenes"

V = 10.0 * KNOT
OMEGA = np.deg2rad(3.0)  # rate of turn [rad/s]
R = V / OMEGA
# a 90 deg turn to port from east to north that starts at t = 0 (the first leg is the
# corner's tangent distance R tan 45 deg = R), then a leg north
START = np.array([5.0 - R, 3.0])
WAYPOINTS = (tuple(START), (5.0, 3.0), (5.0, 3.0 + 3 * R))


def _on_turn(t):
    """Midship (2,) [m] and heading [rad] on the turn at time t [s] (closed form)."""
    h = OMEGA * t
    centre = START + R * np.array([0.0, 1.0])
    return centre + R * np.array([np.sin(h), -np.cos(h)]), h


def _hull():
    ship = Ship(length=10.0, beam=4.0, draft=1.5, speed=V, route=Route(WAYPOINTS, R))
    shape = ObjectGeometry("b", np.array([[5.0, 0.0, 2.0], [-5.0, 1.0, 0.0], [0, -1, 1]]),
                           np.array([[0, 1, 2]], dtype=np.uint32),
                           np.array([*START, 0.0]), rotation_matrix(0.0, 0.0, 0.0),
                           np.array([V, 0.0, 0.0]))
    return Hull("b", [shape], [None], None, False, 1.0, 0.0, np.zeros(1, dtype=np.intp),
                track=ship)


@pytest.mark.parametrize("t", [0.1, 7.0, 20.0])
def test_points_on_the_hull_turn_with_the_route(t):
    hull = _hull()
    p_mid, h = _on_turn(t)
    np.testing.assert_allclose(hull.origin(t)[:2], p_mid, atol=1e-9)
    assert float(hull.heading(t)) == pytest.approx(h, abs=1e-12)
    assert float(hull.turn_rate(t)) == pytest.approx(OMEGA, rel=1e-12)
    # the bow (5 m ahead, 2 m up at time 0) is 5 m ahead along the heading at t
    bow0 = np.array([[START[0] + 5.0, START[1], 2.0]])
    q, v = hull.carry(bow0, 0.0, t)
    fwd = np.array([np.cos(h), np.sin(h)])
    np.testing.assert_allclose(q[0], [*(p_mid + 5.0 * fwd), 2.0], atol=1e-9)
    # rigid body: V along the heading plus omega z x r (the bow swings to port)
    np.testing.assert_allclose(v[0], [*(V * fwd + OMEGA * 5.0 * np.array([-fwd[1], fwd[0]])),
                                      0.0], atol=1e-12)
    # the velocity is the derivative of the carried position
    dt = 1e-4
    fd = (hull.carry(bow0, 0.0, t + dt)[0] - hull.carry(bow0, 0.0, t - dt)[0]) / (2 * dt)
    np.testing.assert_allclose(v, fd, atol=1e-6)
    # the mesh turns as a whole: its vertices keep their distances to midship
    m0, m1 = hull.mesh(0.0).vertices, hull.mesh(t).vertices
    np.testing.assert_allclose(np.linalg.norm(m1 - hull.origin(t), axis=1),
                               np.linalg.norm(m0 - hull.origin(0.0), axis=1), atol=1e-9)


def test_on_a_leg_the_hull_moves_straight():
    hull = _hull()
    t = (0.5 * np.pi * R + R) / V  # one radius along the northbound leg
    np.testing.assert_allclose(hull.origin(t)[:2], [5.0, 3.0 + 2 * R], atol=1e-9)
    assert float(hull.heading(t)) == pytest.approx(np.pi / 2, abs=1e-12)
    assert float(hull.turn_rate(t)) == 0.0
    np.testing.assert_allclose(hull.velocity_at(t), [0.0, V, 0.0], atol=1e-12)


def _turning_scene(start_time_s, n_pulses=16):
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "ships": [{"name": "turner", "length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5,
                   "speed_kn": 10.0, "waypoints_m": [list(p) for p in WAYPOINTS],
                   "turn_rate_deg_s": 3.0, "hull_echo": True, "kelvin_wake": False}],
        "radar": {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 200e6,
                  "prf_hz": 2000.0, "n_pulses": n_pulses, "sea_clutter": False,
                  "transmit_power_w": 100.0, "thermal_noise": False,
                  "window_start_m": 200.0, "window_end_m": 420.0,
                  "start_time_s": start_time_s,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 150e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": (-300.0, 0.0, 40.0),
                        "antenna": {"pattern": "isotropic", "look_at_m": (0.0, 3.0, 1.0)}},
    })


@pytest.mark.slow
@pytest.mark.parametrize("t0", [0.0, 15.0])  # the turn's start (heading 0) and 45 deg
def test_turning_boat_echo_delay_and_doppler(t0):
    # A boat turning at 3 deg/s seen by a fixed monostatic radar: the compressed echo
    # peaks within the range extent of the hull where the closed-form turn puts it, and
    # the phase of the peak advances by 2 pi f_D / PRF per pulse, f_D = -2 u . v / lambda
    # with v = V (cos h, sin h), h = omega t (within 5 %: the hull spans ~2 deg)
    sim = Simulation(_turning_scene(t0), base_dir=SCENES)
    radar = sim.radar
    pulses = np.stack([sim.pulse(p) for p in range(radar.n_pulses)])
    y = range_compress(pulses[:, 0], radar.waveform.samples)
    power = np.mean(np.abs(y) ** 2, axis=0)
    i = int(np.argmax(power))
    rng = 0.5 * C0 * radar.window.fast_time[i]
    tx = radar.tx.state(t0).position
    hull = sim.hulls.hulls[0]
    p_mid, h = _on_turn(t0 + 7.5 / radar.prf)
    np.testing.assert_allclose(hull.origin(t0)[:2], _on_turn(t0)[0], atol=1e-9)
    r_hull = np.linalg.norm(hull.mesh(t0).vertices - tx, axis=1)
    assert r_hull.min() - 1.0 <= rng <= r_hull.max() + 1.0
    assert power[i] > 1e3 * np.median(power)
    u = np.array([*p_mid, 0.0]) - tx
    u /= np.linalg.norm(u)
    f_d = -2.0 * (u[:2] @ (V * np.array([np.cos(h), np.sin(h)]))) / radar.wavelength
    step = np.angle(np.sum(y[1:, i] * np.conj(y[:-1, i])))
    assert step * radar.prf / (2 * np.pi) == pytest.approx(f_d, rel=0.05)


@pytest.mark.slow
def test_check_refuses_a_route_through_the_antenna(tmp_path, capsys):
    # the hull's launch sphere must not hold the antenna at a pulse where the run traces
    # it: a route that sails the hull onto the radar is refused by check (and run)
    from seaecho.cli import main
    from seaecho.config.loading import scene_to_toml_dict
    from seaecho.config.toml_writer import dumps

    data = scene_to_toml_dict(_turning_scene(0.0, n_pulses=2))
    data["ships"][0]["waypoints_m"] = [[-300.0, 0.0], [-280.0, 0.0]]
    data["ships"][0].pop("turn_rate_deg_s")
    data["transmitter"]["position_m"] = [-300.0, 0.0, 3.0]
    path = tmp_path / "s.toml"
    path.write_text(dumps(data))
    assert main(["check", str(path)]) == 2
    assert "[[ships]] 'turner' (hull_echo)" in capsys.readouterr().err
