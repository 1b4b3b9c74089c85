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


@pytest.mark.filterwarnings("ignore::seaecho.warnings.SeaechoWarning")
def test_a_ship_with_wave_motion_runs_and_rides_the_held_sea():
    from seaecho.config import SceneError, parse_scene
    from seaecho.simulation import Simulation

    boat = {"name": "b", "length_m": 8.0, "beam_m": 2.5, "draft_m": 0.8, "speed_m_s": 0.0,
            "position_m": (0.0, 0.0), "hull_echo": True, "wave_motion": True,
            "kelvin_wake": False}
    d = {"sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 32},
         "radar": {"carrier_frequency_hz": 1.3e9, "sampling_rate_hz": 50e6, "prf_hz": 100.0,
                   "n_pulses": 2, "channels": ["HH"],
                   "waveform": {"kind": "lfm", "bandwidth_hz": 40e6, "duration_s": 1e-6}},
         "transmitter": {"position_m": (-300, 0, 30),
                         "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}},
         "ships": [boat]}
    sim = Simulation(parse_scene(d))
    t = float(sim.radar.emission_time(1))
    st = sim.surface_state_at(t)
    att = sim.hulls.attitude(0, t)
    assert att == waterplane_motion(st.x, st.y, st.elevation, (0.0, 0.0), 0.0, 8.0, 2.5)
    assert att[0] != 0.0 and att[1] != 0.0
    raw = sim.pulse(1)
    assert np.isfinite(raw).all() and np.abs(raw).max() > 0
    with pytest.raises(SceneError, match="sea_clutter"):
        parse_scene({**d, "radar": {**d["radar"], "sea_clutter": False}})
