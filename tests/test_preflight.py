"""Checks before a run (``seaecho.checks.preflight``): the closest approach over the pulses,
the crest bound, the reactive near field."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.build import _platforms as build_platforms
from seaecho.checks.preflight import (
    Pulses,
    crest_bound,
    exhaustive_min_distance,
    min_distance,
    min_height,
    near_field_distance,
    nominal_segments,
)
from seaecho.config import parse_scene
from seaecho.constants import G
from seaecho.radar.platforms import Platform

ANT = {"pattern": "isotropic", "look_at_m": (0.0, 0.0, 0.0)}
coord = st.floats(-2000.0, 2000.0)
vec = st.tuples(coord, coord, coord)
speed = st.tuples(*[st.floats(-300.0, 300.0)] * 3)


@st.composite
def platform_sections(draw, perturbed=False):
    motion = draw(st.sampled_from(["fixed", "linear", "waypoints"]))
    d: dict = {"motion": motion, "antenna": ANT}
    if motion == "fixed":
        d["position_m"] = draw(vec)
    elif motion == "linear":
        d["position_m"], d["velocity_m_s"] = draw(vec), draw(speed)
    else:
        n = draw(st.integers(2, 5))
        gaps = draw(st.lists(st.floats(0.01, 0.5), min_size=n - 1, max_size=n - 1))
        t0 = draw(st.floats(-0.5, 0.5))
        d["waypoint_times_s"] = tuple(np.concatenate([[t0], t0 + np.cumsum(gaps)]))
        p = [np.array(draw(vec))]
        for gap in gaps:  # segment velocities within the schema's +-1e4 m/s
            p.append(p[-1] + gap * np.array(draw(st.tuples(*[st.floats(-3000, 3000)] * 3))))
        d["waypoint_positions_m"] = tuple(tuple(float(c) for c in x) for x in p)
    if perturbed:
        d["perturbation"] = {"position_sigma_m": draw(st.tuples(*[st.floats(0, 50)] * 3)),
                             "position_tau_s": 0.05, "step_s": 1e-3}
    return d


def _scene(section, n_pulses=200, prf=1000.0, start=0.0):
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 16},
        "radar": {"carrier_frequency_hz": 1e10, "sampling_rate_hz": 1e8, "prf_hz": prf,
                  "n_pulses": n_pulses, "start_time_s": start,
                  "waveform": {"kind": "pulse", "duration_s": 1e-6}},
        "transmitter": section,
    })


def _platform(scene) -> Platform:
    return build_platforms(scene)[0]  # the builder's transmitter, as the run has it


@settings(max_examples=60, deadline=None)
@given(section=platform_sections(), q=vec, w=speed, n=st.integers(1, 400),
       start=st.floats(-0.3, 0.3))
def test_closest_approach_over_pulses_equals_brute_force(section, q, w, n, start):
    """Two evaluations per segment (convexity of the distance on a segment) find the
    minimum over every pulse: parity with the exhaustive search on the same track."""
    scene = _scene(section, n_pulses=n, start=start)
    platform = _platform(scene)
    pulses = Pulses(start, 1000.0, n)
    q, w = np.array([q]), np.array([w])
    d, p = min_distance(scene.transmitter, platform, pulses, q, w)
    d_ref, _ = exhaustive_min_distance(platform, pulses, q[0], w[0])
    assert d[0] == pytest.approx(d_ref, rel=1e-9, abs=1e-6)
    t = pulses.time(p[0])
    assert np.linalg.norm(q[0] + w[0] * t - platform.state(t).position) == pytest.approx(
        d[0], rel=1e-9, abs=1e-6)
    z, _ = min_height(scene.transmitter, pulses)
    z_ref, _ = exhaustive_min_distance(platform, pulses, None, None)
    assert z == pytest.approx(z_ref, rel=1e-9, abs=1e-6)


@settings(max_examples=30, deadline=None)
@given(section=platform_sections(perturbed=True), q=vec, w=speed, n=st.integers(1, 300))
def test_perturbed_track_bound_is_below_the_true_minimum(section, q, w, n):
    """On a Gauss-Markov track, nominal distance minus 8 sigma is a lower bound."""
    scene = _scene(section, n_pulses=n)
    platform = _platform(scene)
    pulses = Pulses(0.0, 1000.0, n)
    d, _ = min_distance(scene.transmitter, platform, pulses, np.array([q]), np.array([w]))
    d_ref, _ = exhaustive_min_distance(platform, pulses, np.array(q), np.array(w))
    assert d[0] <= d_ref + 1e-6


@settings(max_examples=40, deadline=None)
@given(section=platform_sections(), t=st.lists(st.floats(-2.0, 2.0), min_size=1,
                                               max_size=20))
def test_nominal_segments_are_the_platform_track(section, t):
    """Parity: the segments rebuilt from the section give Platform.nominal_state, also
    extrapolated before the first and after the last waypoint."""
    scene = _scene(section)
    platform = _platform(scene)
    segs = nominal_segments(scene.transmitter)
    for ti in [-10.0, *t, 10.0]:
        seg = next(s for s in segs if s.t_a <= ti <= s.t_b)
        np.testing.assert_allclose(seg.c + seg.v * ti, platform.nominal_state(ti).position,
                                   rtol=1e-12, atol=1e-9)


def test_crest_bound_is_twice_the_pierson_moskowitz_significant_height():
    """Pierson & Moskowitz (1964): H_s = 0.21 U19.5^2 / g (Stewart 2008, eq 16.26), so
    the crest bound 2 H_s of a tile that holds the whole spectrum is 0.42 U^2 / g."""
    u = 8.0
    scene = parse_scene({"sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": u,
                                 "size_x_m": 2000.0, "nx": 16384}})
    assert crest_bound(scene) == pytest.approx(2 * 0.21 * u**2 / G, rel=0.01)


def test_reactive_near_field_boundary():
    """Balanis (2016), section 2.2.4: R1 = 0.62 sqrt(D^3 / lambda) for an antenna large
    against lambda; lambda / 2 pi for a small one; never inside the antenna itself."""
    scene = _scene({"position_m": (0, 0, 10), "antenna": {
        "pattern": "rectangular", "width_m": 1.0, "height_m": 0.5, "look_at_m": (0, 0, 0)}})
    assert near_field_distance(scene.transmitter.antenna, 0.03) == pytest.approx(
        0.62 * np.sqrt(1.0 / 0.03))
    iso = _scene({"position_m": (0, 0, 10), "antenna": ANT}).transmitter.antenna
    assert near_field_distance(iso, 300.0) == pytest.approx(300.0 / (2 * np.pi))


def test_antenna_inside_a_scatterer_hull_is_refused_by_check_and_run(tmp_path, capsys):
    # Found by comparing what `run` refuses with what the preflight checks: an antenna
    # inside the sphere the ray tracer launches its rays from (1.05 x the hull's bounding
    # radius, 0.449 m for the 0.5 m trihedral) passed `check`, and `run` stopped with a
    # traceback in the tracer. Both refuse it now, naming the antenna and the object;
    # 0.49 m from the centre, outside the sphere, both accept it
    from pathlib import Path

    from seaecho.cli import main

    root = Path(__file__).resolve().parents[1] / "scenes"
    text = (root / "calibration_trihedral.toml").read_text().replace(
        'file = "meshes/', f'file = "{root}/meshes/').replace(
        "look_at_m = [0.0, 0.0, 2.0]", "look_at_m = [0.0, 0.0, 20.0]")
    scene = tmp_path / "s.toml"
    scene.write_text(text.replace("position_m = [-500.0, 0.0, 300.0]",
                                  "position_m = [0.0, 0.0, 2.0]"))
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "r.nc"), "-q", "--no-figures"] if command == "run" \
            else []
        assert main([command, str(scene), *extra]) == 2
        err = capsys.readouterr().err
        assert "[transmitter].position_m" in err and "'trihedral'" in err, err
        assert "bounding radius 0.449 m" in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
    scene.write_text(text.replace("position_m = [-500.0, 0.0, 300.0]",
                                  "position_m = [0.2, 0.0, 2.3]"))
    assert main(["check", str(scene)]) == 0
