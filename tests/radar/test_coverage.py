"""The sea skipped where a scanning beam does not reach the tile (seaecho.radar.coverage,
``[radar] sea_gain_floor_db``, docs/scanning.md).

A small scanning radar: a 0.5 m aperture (3.2 deg beam, Balanis 2016 eq 12-38's
0.886 lambda / a) 2 km south of a 32 m tile, one revolution per second at 100 Hz
(3.6 deg per pulse), so that the beam passes over the tile in the first pulses and
looks away from it for the rest. The bound of eq C1/C2 is checked against the antenna's
own pattern (eq A1) at every vertex of the surface, and the skipped echo against it.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from seaecho.config import parse_scene
from seaecho.radar.antennas import Antenna, line_pattern
from seaecho.radar.coverage import one_way_bound, tile_box, width_envelope
from seaecho.simulation import Simulation


def _scene(floor, motion="held", n_pulses=24, **radar):
    r = {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6, "prf_hz": 100.0,
         "n_pulses": n_pulses, "sea_update_pulses": n_pulses, "transmit_power_w": 25e3,
         "channels": ["HH", "VV"], "thermal_noise": True, "transmit_phase": "random",
         "sea_gain_floor_db": floor, "window_start_m": 1950.0, "window_end_m": 2850.0,
         "waveform": {"kind": "pulse", "duration_s": 1e-7}}
    r.update(radar)
    return parse_scene({
        "sea": {"wind_speed_m_s": 8.0, "size_x_m": 32.0, "nx": 16},
        "scattering": {"sea_motion": motion}, "run": {"seed": 5}, "radar": r,
        "transmitter": {"position_m": (0.0, -2000.0, 30.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "rectangular", "width_m": 0.5, "height_m": 0.1,
            "illumination": "uniform", "depression_deg": 0.9,
            "scan": {"mode": "rotating", "rate_rpm": 60.0, "start_deg": 7.0}}},
        "targets": [{"position_m": (0.0, 800.0, 5.0), "rcs_m2": 10.0}]})


def _sim(*a, **k) -> Simulation:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SPM's validity at X band
        return Simulation(_scene(*a, **k))


def _relative_two_way_gain(sim, pulse, points):
    """(G_t / G_t,peak)(G_r / G_r,peak) of eq A1 at world ``points`` (monostatic)."""
    geo = sim.radar.geometry(pulse)
    ant = sim.radar.tx_antenna
    d = points - geo.tx.position
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    g = ant.gain_local(d @ geo.tx_axes) / ant.peak_gain
    return g * g


def test_width_envelope_bounds_the_pattern_and_decreases():
    """E_w(t) >= |F_w(s)| for every s >= t (the envelope's definition, eq C1), on a grid
    10x finer than its table and off its nodes; 1 at the peak; non-increasing."""
    ant = Antenna("rectangular", 0.0319, 2.0, 0.12, illumination="taylor",
                  taylor_sidelobe_db=30.0, taylor_nbar=4)
    s = np.linspace(0.0, ant.width / ant.wavelength, 200_001)
    f = np.abs(line_pattern(s, "taylor", 30.0, 4))
    tail_max = np.maximum.accumulate(f[::-1])[::-1]
    env = width_envelope(ant, s)
    assert np.all(env >= tail_max)
    assert env[0] == pytest.approx(1.0)
    assert np.all(np.diff(env) <= 0.0)
    # Far out (t = 5) the envelope is the pattern's sidelobe level, not a loose bound
    assert env[s >= 5.0][0] == pytest.approx(tail_max[s >= 5.0][0], rel=2e-3)


def test_bound_holds_at_every_surface_point_and_is_tight_in_the_beam():
    """At every pulse of a revolution the two-way gain of eq A1 at every vertex of the sea
    surface stays below two_way_bound (eq C2); with the beam on the tile the bound is 1."""
    sim = _sim(-60.0, n_pulses=100)
    st = sim.surface_state(0)
    xx, yy = np.meshgrid(st.x, st.y)
    pts = np.stack([xx, yy, st.elevation], -1).reshape(-1, 3)
    bounds = np.array([sim.sea_gain_bound(p) for p in range(100)])
    for p in range(100):
        g = _relative_two_way_gain(sim, p, pts)
        assert g.max() <= bounds[p], p
    assert bounds[2] == 1.0  # boresight at 7.0 - 2 x 3.6 = -0.2 deg: on the tile
    assert (bounds < 1e-6).sum() >= 75  # most of the revolution skips the sea
    # Behind the antenna the obliquity factor bounds it (pulse 50: looking south)
    assert bounds[50] < 1e-10


def test_bound_of_a_tile_beside_the_beam_matches_the_corner_direction():
    """A box wholly on one side of the beam's plane: the bound is the envelope at the
    corner of smallest |u| (eq C1), here a corner computed by hand."""
    ant = Antenna("rectangular", 0.03, 1.0, 0.1)
    axes = np.eye(3)  # boresight +x, width +y, height +z
    corners = tile_box(np.array([990.0, 1010.0]), np.array([50.0, 70.0]), 0.0)
    d = np.array([1010.0, 50.0, 0.0])
    u = d[1] / np.linalg.norm(d)  # the smallest |u|: nearest to the beam, farthest out
    want = float(width_envelope(ant, ant.width * u / ant.wavelength)) ** 2
    assert one_way_bound(ant, axes, np.zeros(3), corners) == pytest.approx(want, rel=1e-12)
    assert one_way_bound(Antenna("isotropic", 0.03), axes, np.zeros(3), corners) == 1.0


@pytest.mark.parametrize("motion", ["held", "evolving"])
def test_off_and_lowest_floor_give_the_same_bytes(motion):
    """'off' and a floor of -300 dB (no pulse's bound is that low) give the same pulses
    as each other, bit for bit."""
    off, low = _sim("off", motion, n_pulses=8), _sim(-300.0, motion, n_pulses=8)
    assert not any(low.sea_skipped(p) for p in range(8))
    for p in range(8):
        assert off.pulse(p).tobytes() == low.pulse(p).tobytes()


@pytest.mark.parametrize("motion", ["held", "evolving"])
def test_pulses_in_the_beam_are_unchanged_and_skipped_ones_keep_targets(motion):
    """With the floor, the pulses that compute the sea are byte-identical to the run
    without skipping; the skipped ones equal the targets and noise alone (the sea turned
    off), so targets are still computed at every pulse."""
    n = 12
    kw = {"sea_update_pulses": 4} if motion == "evolving" else {}
    on, off = _sim(-40.0, motion, n_pulses=n, **kw), _sim("off", motion, n_pulses=n, **kw)
    no_sea = _sim(-40.0, motion, n_pulses=n, sea_clutter=False, **kw)
    skipped = [on.sea_skipped(p) for p in range(n)]
    assert any(skipped) and not all(skipped)
    for p in range(n):
        raw = on.pulse(p)
        if skipped[p]:
            assert raw.tobytes() == no_sea.pulse(p).tobytes()
            assert raw.tobytes() != off.pulse(p).tobytes()
        else:
            assert raw.tobytes() == off.pulse(p).tobytes()


def test_skipped_sea_echo_is_below_the_stated_bound():
    """The sea echo of a skipped pulse, computed anyway, against the pulse with the beam
    on the tile (held sea, one block, fixed radar: only the antenna gain changes from
    pulse to pulse). P(p) / P(p0) = sum g(p) K / sum g(p0) K <= bound(p) / min g(p0),
    min g(p0) the least two-way gain of eq A1 over the surface at p0."""
    sim = _sim(-60.0, n_pulses=100)

    def power(p):
        a = sim.sea_echo(p).echo.amplitudes
        return float(sum(np.sum(np.abs(np.asarray(c)) ** 2) for c in a))

    st = sim.surface_state(0)
    xx, yy = np.meshgrid(st.x, st.y)
    pts = np.stack([xx, yy, st.elevation], -1).reshape(-1, 3)
    p0 = 2
    g_min = _relative_two_way_gain(sim, p0, pts).min()
    assert g_min > 0.3  # the tile lies inside the beam
    p_peak = power(p0)
    floor = 1e-6
    checked = 0
    skipped = [p for p in range(0, 100, 5) if sim.sea_skipped(p)]
    assert len(skipped) >= 12
    for p in skipped:
        ratio = power(p) / p_peak
        assert ratio <= sim.sea_gain_bound(p) / g_min <= floor / g_min
        checked += ratio > 0.0
    assert checked  # not vacuous: the sea still echoes a little there


@pytest.mark.parametrize("motion", ["held", "evolving"])
def test_skip_is_independent_of_the_order_of_pulses(motion):
    """The skip decision and the pulses are pure functions of (scene, pulse): computed
    in reverse and in a shuffled order, they give the serial bytes."""
    n = 12
    kw = {"sea_update_pulses": 4} if motion == "evolving" else {}
    serial = _sim(-40.0, motion, n_pulses=n, **kw)
    ref = {p: (serial.sea_skipped(p), serial.pulse(p).tobytes()) for p in range(n)}
    for order in (range(n - 1, -1, -1), np.random.default_rng(1).permutation(n)):
        other = _sim(-40.0, motion, n_pulses=n, **kw)
        assert any(ref[p][0] for p in range(n)) and not all(ref[p][0] for p in range(n))
        for p in order:
            p = int(p)
            assert (other.sea_skipped(p), other.pulse(p).tobytes()) == ref[p]


def test_antenna_inside_the_box_is_never_skipped():
    """A radar over the tile (inside its box): directions to the box cover the sphere,
    the bound is 1 whatever the pointing."""
    ant = Antenna("rectangular", 0.03, 2.0, 0.1)
    box = tile_box(np.array([-100.0, 100.0]), np.array([-100.0, 100.0]), 30.0)
    rot = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    for axes in (np.eye(3), rot):
        assert one_way_bound(ant, axes, np.array([10.0, -20.0, 15.0]), box) == 1.0
