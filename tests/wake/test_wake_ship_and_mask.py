"""Ship track (eq W1), ship frame (eq W2) and the turbulent wake mask (eqs W13, W14)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.build import build_sea
from seaecho.config import parse_scene
from seaecho.wake import Ship, turbulent_wake_mask, turbulent_wake_strip, turbulent_wake_width


def test_straight_track_and_velocity():
    ship = Ship(10.0, 4.0, 1.5, 5.0, np.deg2rad(30.0), (1.0, -2.0))
    np.testing.assert_allclose(ship.velocity, 5.0 * np.array([np.sqrt(3) / 2, 0.5]))
    np.testing.assert_allclose(ship.position(0.0), [1.0, -2.0])
    np.testing.assert_allclose(ship.position(4.0), [1.0, -2.0] + 20.0 * ship.direction)


def test_builder_converts_knots_and_degrees():
    # [ship] in knots and degrees -> the wake stage's SI Ship (seaecho.build)
    ship_cfg = {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 10.0,
                "heading_deg": 35.0, "position_m": [3.0, 4.0],
                "turbulent_wake_length_m": 150.0}
    sea = {"wind_speed_m_s": 5.0, "size_x_m": 16.0, "nx": 16}
    ship = build_sea(parse_scene({"sea": sea, "ship": ship_cfg})).ship
    assert ship.speed == pytest.approx(10.0 * 1852.0 / 3600.0)  # 1 kn = 1852 m / h
    assert ship.heading == pytest.approx(np.deg2rad(35.0))
    assert ship.position0 == (3.0, 4.0)
    assert ship.wake_length == 150.0
    del ship_cfg["turbulent_wake_length_m"]
    default = build_sea(parse_scene({"sea": sea, "ship": ship_cfg})).ship
    assert default.wake_length == pytest.approx(200.0)


def test_ship_frame_bow_is_ahead():
    ship = Ship(10.0, 4.0, 1.5, 5.0, np.deg2rad(90.0), (0.0, 0.0))  # sailing north
    xs, ys = ship.to_ship_frame(np.array([0.0, 0.0, 3.0]), np.array([5.0, -7.0, 0.0]), 0.0)
    np.testing.assert_allclose(xs, [-5.0, 7.0, 0.0], atol=1e-12)  # bow at x' = -L/2
    assert abs(ys[2]) == pytest.approx(3.0)


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"length": -1.0}, "length"),
        ({"beam": 12.0}, "beam"),
        ({"speed": -1.0}, "speed"),
        ({"heading": np.nan}, "heading"),
        ({"position0": (0.0, np.inf)}, "position0"),
    ],
)
def test_ship_rejects_bad_input(kwargs, match):
    base = {"length": 10.0, "beam": 4.0, "draft": 1.5, "speed": 5.0}
    with pytest.raises(ValueError, match=match):
        Ship(**{**base, **kwargs})


@pytest.fixture(scope="module")
def mask_case():
    ship = Ship(10.0, 4.0, 1.5, 5.0, np.deg2rad(35.0), (50.0, 40.0))
    x = np.linspace(-200.0, 100.0, 601)
    y = np.linspace(-200.0, 100.0, 601)
    return ship, x, y, turbulent_wake_strip(ship, x, y, 0.0)


def _at(ship, x, y, m, xs, ys):
    """Mask value at ship-frame point (x', y') by nearest grid point."""
    c, s = np.cos(ship.heading), np.sin(ship.heading)
    p = ship.position(0.0)
    wx = p[0] - xs * c + ys * s
    wy = p[1] - xs * s - ys * c
    return m[np.argmin(np.abs(y - wy)), np.argmin(np.abs(x - wx))]


def test_mask_core_ends_and_outside(mask_case):
    ship, x, y, m = mask_case
    assert m.min() >= 0.0 and m.max() <= 1.0
    assert _at(ship, x, y, m, 5.0 + 30.0, 0.0) == pytest.approx(1.0)  # on the track
    assert _at(ship, x, y, m, -20.0, 0.0) == 0.0  # ahead of the ship
    assert _at(ship, x, y, m, 0.0, 0.0) == 0.0  # alongside the hull
    assert _at(ship, x, y, m, 60.0, 20.0) == 0.0  # far to the side


def test_mask_width_grows_as_one_fifth_power():
    """Half-maximum width measured from the mask follows w0 (1 + xi/w0)^(1/5) (eq W13)."""
    ship = Ship(10.0, 4.0, 1.5, 5.0, 0.0, (0.0, 0.0), turbulent_wake_length=5000.0)
    y = np.linspace(-20, 20, 4001)
    widths = []
    xis = np.array([20.0, 200.0, 2000.0])
    for xi in xis:
        x = np.array([-(5.0 + xi)])  # sailing +x: x' = -x
        prof = turbulent_wake_strip(ship, x, y, 0.0)[:, 0]
        widths.append(y[prof >= 0.5].max() - y[prof >= 0.5].min())
    np.testing.assert_allclose(widths, turbulent_wake_width(xis, 4.0), rtol=2e-3)
    ratio = widths[2] / widths[1]
    assert ratio == pytest.approx(((1 + 2000 / 4) / (1 + 200 / 4)) ** 0.2, rel=3e-3)


def test_mask_length_default_and_explicit():
    ship = Ship(10.0, 4.0, 1.5, 5.0, 0.0, (0.0, 0.0))
    x = -np.array([5.0 + 150.0, 5.0 + 199.0, 5.0 + 250.0])
    m = turbulent_wake_strip(ship, x, np.array([0.0]), 0.0)[0]
    assert m[0] == pytest.approx(1.0) and 0.0 < m[1] < 0.1 and m[2] == 0.0
    m2 = turbulent_wake_strip(ship, x, np.array([0.0]), 0.0, length=100.0)[0]
    assert np.all(m2 == 0.0)


def test_mask_moves_with_the_ship(mask_case):
    ship, x, y, m = mask_case
    t = 12.0
    d = ship.velocity * t
    moved = turbulent_wake_strip(ship, x + d[0], y + d[1], t)
    np.testing.assert_allclose(moved, m, atol=1e-12)


@settings(max_examples=30, deadline=None)
@given(
    length=st.floats(5.0, 300.0),
    beam_frac=st.floats(0.05, 0.5),
    heading=st.floats(-np.pi, np.pi),
    t=st.floats(0.0, 100.0),
)
def test_mask_is_a_damping_fraction(length, beam_frac, heading, t):
    ship = Ship(length, beam_frac * length, 0.05 * length, 5.0, heading, (0.0, 0.0))
    x = np.linspace(-3 * length, 3 * length, 41)
    m = turbulent_wake_mask(ship, x, x, t)
    assert m.shape == (41, 41)
    assert np.all((m >= 0.0) & (m < 1.0))
    assert np.all(m <= turbulent_wake_strip(ship, x, x, t))


def test_a_subnormal_wake_length_is_no_strip():
    # Found by the fuzzing suite: a length of 5e-324 m made the fade-out 0.2 L underflow
    # to 0 (a division by zero, NaN where xi = L); such a strip is empty, as L = 0.
    ship = Ship(10.0, 4.0, 1.5, 5.0, np.deg2rad(35.0), (50.0, 40.0))
    x = np.linspace(-200.0, 100.0, 61)
    m = turbulent_wake_strip(ship, x, x, 0.0, length=5e-324)
    assert m.shape == (61, 61) and not m.any()


def test_a_subnormal_fade_out_neither_warns_nor_breaks_the_strip():
    # Found by the fuzzing suite: a strip of 1e-308 m has a subnormal fade-out 0.2 L; the
    # ratio (L - xi) / (0.2 L) overflowed (RuntimeWarning) before the clip of S took it to
    # 0 or 1. The strip is empty behind the stern, as for any strip shorter than a beam.
    ship = Ship(10.0, 4.0, 1.5, 5.0, np.deg2rad(35.0), (50.0, 40.0))
    x = np.linspace(-200.0, 100.0, 61)
    m = turbulent_wake_strip(ship, x, x, 0.0, length=1e-308)
    assert m.shape == (61, 61) and np.all(np.isfinite(m)) and not m.any()
