"""Scattering centres: delay-equivalent positions, coherent cells, refresh schedule."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ship_helpers import K, direction, trace

from seaecho.targets import canonical
from seaecho.targets.centres import (
    CentreAccumulator,
    _pack,
    _unpack,
    coherent_total,
    equivalent_positions,
    refresh_schedule,
)


@given(st.floats(0.0, 30.0), st.floats(-3.0, 3.0), st.floats(0.0, 40.0))
@settings(max_examples=30)
def test_equivalent_position_is_on_the_iso_range_ellipsoid(extra, y, z):
    # |c - T| + |c - R| = L to 1e-9 m for any extra path (multi-bounce, sea legs), and
    # c moves along the bistatic-range gradient only (the nearest such point)
    tx, rx = np.array([-800.0, 50.0, 30.0]), np.array([300.0, -400.0, 15.0])
    p = np.array([[2.0, y, z]])
    length = np.linalg.norm(p - tx) + np.linalg.norm(p - rx) + extra
    c, ok = equivalent_positions(p, [length], tx, rx)
    assert ok[0]
    assert np.linalg.norm(c - tx) + np.linalg.norm(c - rx) == pytest.approx(length, abs=1e-9)
    g = (p - tx) / np.linalg.norm(p - tx) + (p - rx) / np.linalg.norm(p - rx)
    step = (c - p)[0]
    assert np.linalg.norm(np.cross(step, g[0])) <= 1e-3 * max(np.linalg.norm(step), 1e-12) \
        + 1e-9


def test_equivalent_position_refuses_forward_scatter():
    # Receiver opposite the transmitter through the point: the delay does not locate it
    c, ok = equivalent_positions(np.zeros((1, 3)), [2001.0], [-1000.0, 0, 0], [1000.0, 0, 0])
    assert not ok[0]


def test_pack_round_trip():
    rng = np.random.default_rng(0)
    idx = rng.integers(-(2**19) + 1, 2**19 - 1, size=(100, 3))
    path = rng.integers(0, 4, 100)
    p2, i2 = _unpack(_pack(path, idx))
    assert (p2 == path).all() and (i2 == idx).all()
    with pytest.raises(ValueError, match="cell size"):
        _pack(path[:1], np.array([[2**19, 0, 0]]))


def test_cells_are_exact_at_the_trace_geometry():
    # Parity: the centres (eq C2) sum back, by eq C3, to the totals summed ray by ray,
    # at the geometry of the trace (1e-9 relative), whatever the cell size.
    mesh = canonical.dihedral(0.3, 0.4)
    u = direction(38.0, 12.0)
    for cell in (0.01, 0.1, 1.0):
        sig = trace(mesh, u, n=3, cell=cell, prune=0.0)
        c = sig.centres
        s = coherent_total(c.position, c.s, sig.tx, sig.rx, K, sig.reference)
        np.testing.assert_allclose(s, sig.s, rtol=1e-9, atol=1e-12 * np.abs(sig.s).max())
    assert len(c) < 10  # 1 m cells: a handful of centres


def test_pruning_bounds_the_dropped_power():
    mesh = canonical.sphere(0.25, 4)
    sig_all = trace(mesh, direction(50.0), n=3, cell=0.02, prune=0.0)
    sig = trace(mesh, direction(50.0), n=3, cell=0.02, prune=1e-3)
    p_all = np.sum(np.abs(sig_all.centres.s) ** 2)
    p = np.sum(np.abs(sig.centres.s) ** 2)
    assert len(sig.centres) < len(sig_all.centres)
    assert p >= (1 - 1e-3) * p_all


def test_accumulator_rejects_bad_cell():
    with pytest.raises(ValueError, match="cell"):
        CentreAccumulator(1.0, np.zeros(3), np.zeros(3), np.zeros(3), 0.0, 1)


def test_refresh_schedule():
    # A transmitter sweeping 0.13 deg per step: a new trace every 8 steps for a 1 deg
    # step; a fixed geometry: only the first; an interval adds traces; the receiver
    # alone can trigger them.
    n = 100
    t = np.arange(n) * 0.01
    az = np.deg2rad(0.13) * np.arange(n)
    ut = np.stack([np.cos(az), np.sin(az), np.zeros(n)], -1)
    fixed = np.tile([1.0, 0.0, 0.0], (n, 1))
    s = refresh_schedule(ut, fixed, t, np.deg2rad(1.0))
    assert s[0] == 0 and np.all(np.diff(s) == 8)
    assert refresh_schedule(fixed, fixed, t, np.deg2rad(1.0)).tolist() == [0]
    assert refresh_schedule(fixed, ut, t, np.deg2rad(1.0)).tolist() == s.tolist()
    s = refresh_schedule(fixed, fixed, t, np.deg2rad(1.0), interval=0.25)
    assert s.tolist() == [0, 25, 50, 75]
    with pytest.raises(ValueError, match="step"):
        refresh_schedule(fixed, fixed, t, 0.0)
