"""Ranges/directions (float64) and global angles vs geometry.frames."""

import numpy as np
import pytest

from seaecho.geometry.bistatic import global_angles, ranges_directions
from seaecho.geometry.frames import local_angles


def test_global_angles_equal_frames_local_angles_about_z():
    rng = np.random.default_rng(0)
    c = rng.uniform(-50, 50, (400, 3))
    c[:3] = (0.0, 0.0, 0.0)  # nadir below the transmitter: degenerate azimuth
    tx, rx = np.array([0.0, 0.0, 300.0]), np.array([80.0, -20.0, 60.0])
    for r in (tx, rx):
        _, _, n_i, n_s = ranges_directions(c, tx, r)
        got = global_angles(n_i, n_s)
        ref = local_angles(n_i, n_s, np.array([0.0, 0.0, 1.0]))
        np.testing.assert_allclose(got[0], ref[0], atol=1e-12)
        np.testing.assert_allclose(got[1], ref[1], atol=1e-12)
        np.testing.assert_allclose(np.angle(np.exp(1j * (got[2] - ref[2]))), 0, atol=1e-12)


def test_ranges_are_float64_exact_at_long_range():
    """A 1 mm displacement at 30 km is kept (float32 would lose it: ulp(3e4) = 2 mm)."""
    tx = np.array([30_000.0, 0.0, 3_000.0])
    c = np.array([[0.0, 0.0, 0.0], [0.001, 0.0, 0.0]])
    r_tx, r_rx, n_i, n_s = ranges_directions(c, tx, tx)
    assert r_tx.dtype == np.float64
    assert r_tx[0] - r_tx[1] == pytest.approx(0.001 * 30_000 / np.hypot(30_000, 3_000), rel=1e-6)
    np.testing.assert_array_equal(n_s, -n_i)
    with pytest.raises(ValueError, match="zero range"):
        ranges_directions(np.array([tx]), tx, tx)
