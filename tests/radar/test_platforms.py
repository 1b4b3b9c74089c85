"""Platforms: trajectories, attitude, Gauss-Markov perturbation."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.config.radar import PlatformConfig
from seaecho.radar.platforms import (
    Platform,
    draw_perturbation,
    gauss_markov,
    rotation_matrix,
)

ANT = {"pattern": "isotropic", "look_at_m": (0.0, 0.0, 0.0)}


def _rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def _ry(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def _rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


@settings(max_examples=50, deadline=None)
@given(st.floats(-np.pi, np.pi), st.floats(-1.5, 1.5), st.floats(-np.pi, np.pi))
def test_rotation_is_zyx_composition(yaw, pitch, roll):
    # Eq (P1): R = Rz(yaw) Ry(-pitch) Rx(roll) (Stevens & Lewis 2003, section 1.3)
    expected = _rz(yaw) @ _ry(-pitch) @ _rx(roll)
    r = rotation_matrix(yaw, pitch, roll)
    np.testing.assert_allclose(r, expected, atol=1e-12)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(r) == pytest.approx(1.0)


def test_rotation_sign_conventions():
    # yaw 90 deg: forward points north; pitch up: forward gains +z; roll right-wing-down:
    # the left wing (+y body) goes up (+z)
    assert rotation_matrix(np.pi / 2, 0, 0) @ [1, 0, 0] == pytest.approx([0, 1, 0])
    assert (rotation_matrix(0, 0.1, 0) @ [1, 0, 0])[2] == pytest.approx(np.sin(0.1))
    assert (rotation_matrix(0, 0, 0.1) @ [0, 1, 0])[2] == pytest.approx(np.sin(0.1))


def _platform(**tx):
    """The transmitter platform of a scene whose [transmitter] is ``tx`` (via the builder)."""
    radar = {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 1e8, "prf_hz": 1e3,
             "waveform": {"kind": "lfm", "bandwidth_hz": 5e7, "duration_s": 1e-6}}
    scene = parse_scene({"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
                         "radar": radar, "transmitter": dict(tx, antenna=ANT)})
    return build_radar(scene).tx


def test_linear_platform_state_vectorised():
    p = _platform(motion="linear", position_m=(0, -100, 3000), velocity_m_s=(0, 222, 0))
    t = np.array([[0.0, 1.0], [2.0, -1.0]])
    s = p.state(t)
    assert s.position.shape == (2, 2, 3) and s.rotation.shape == (2, 2, 3, 3)
    np.testing.assert_allclose(s.position[..., 1], -100 + 222 * t)
    np.testing.assert_allclose(s.velocity[..., 1], 222.0)
    # default yaw along the velocity: north
    np.testing.assert_allclose(s.attitude[..., 0], np.pi / 2)


def test_fixed_platform():
    p = _platform(position_m=(0, 0, 256.65))
    s = p.state(np.linspace(0, 10, 5))
    np.testing.assert_allclose(s.position, np.tile([0, 0, 256.65], (5, 1)))
    np.testing.assert_allclose(s.velocity, 0.0)


def test_waypoints_piecewise_linear():
    p = _platform(motion="waypoints", waypoint_times_s=(0, 10, 20),
                  waypoint_positions_m=((0, 0, 100), (100, 0, 100), (100, 50, 100)))
    s = p.state(np.array([5.0, 15.0, 25.0]))
    np.testing.assert_allclose(s.position, [[50, 0, 100], [100, 25, 100], [100, 75, 100]])
    np.testing.assert_allclose(s.velocity, [[10, 0, 0], [0, 5, 0], [0, 5, 0]])


def test_gauss_markov_statistics():
    # Stationary first-order GM: variance sigma^2 and lag-1 correlation phi (Gelb 1974,
    # section 3.8). 200k samples: the standard error of the variance ratio is about
    # sqrt(2 (1 + phi^2) / (1 - phi^2) / n) ~ 0.014 for phi = 0.9, so 5 % is > 3 sigma.
    rng = np.random.default_rng(1)
    phi = 0.9
    x = gauss_markov(200_000, [2.0, 0.5], phi, rng)
    np.testing.assert_allclose(x.var(axis=0), [4.0, 0.25], rtol=0.05)
    r1 = np.mean(x[1:] * x[:-1], axis=0) / x.var(axis=0)
    np.testing.assert_allclose(r1, phi, atol=0.01)


def test_perturbed_track_reproducible_and_nominal_kept():
    t_grid, dpos, datt = draw_perturbation(
        (0, 5), np.random.default_rng(3), step=0.01, position_sigma=(1, 1, 0.5),
        position_tau=2.0, attitude_sigma=np.deg2rad((0.1, 0.1, 0.1)), attitude_tau=1.0)
    assert dpos.shape == datt.shape == (t_grid.size, 3)
    p = Platform(np.array([0.0, 1.0]), np.array([[0, 0, 1000], [100, 0, 1000]]),
                 perturbation=(t_grid, dpos, datt))
    t = t_grid[:400]
    true, nominal = p.state(t), p.nominal_state(t)
    assert np.abs(true.position - nominal.position).max() > 0.01
    np.testing.assert_allclose(nominal.position[:, 0], 100 * t)
    # velocity of the true track = derivative of its (piecewise-linear) position
    tm = 0.5 * (t[1:] + t[:-1])
    fd = (true.position[1:] - true.position[:-1]) / np.diff(t)[:, None]
    np.testing.assert_allclose(p.state(tm).velocity, fd, rtol=1e-6, atol=1e-6)
    # attitude errors reach the rotation matrices
    assert not np.allclose(true.rotation, nominal.rotation)


def _scene(extra):
    base = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
            "radar": {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 1e8, "prf_hz": 1e3,
                      "n_pulses": 10,
                      "waveform": {"kind": "lfm", "bandwidth_hz": 5e7, "duration_s": 1e-6}},
            "transmitter": {"position_m": (0, 0, 100), "antenna": ANT,
                            "perturbation": {"position_sigma_m": (1, 1, 1)}}}
    base.update(extra)
    return parse_scene(base)


def test_scene_platforms_same_seed_same_track_monostatic_shares():
    a = build_radar(_scene({}))
    a_tx, a_rx = a.tx, a.rx
    b_tx = build_radar(_scene({})).tx
    assert a_tx is a_rx and a.monostatic
    t = np.linspace(0, 0.009, 10)
    np.testing.assert_array_equal(a_tx.state(t).position, b_tx.state(t).position)
    c_tx = build_radar(_scene({"run": {"seed": 7}})).tx
    assert not np.array_equal(a_tx.state(t).position, c_tx.state(t).position)


@pytest.mark.parametrize("bad", [
    {"motion": "fixed", "position_m": (0, 0, 1), "velocity_m_s": (1, 0, 0)},
    {"motion": "linear"},
    {"motion": "waypoints", "waypoint_times_s": (0, 0), "waypoint_positions_m": ((0, 0, 0),) * 2},
])
def test_platform_config_rejects(bad):
    with pytest.raises(ValueError):
        PlatformConfig(antenna=ANT, **bad)
