"""Ships on waypoints (eq W18) and the wakes of several ships.

Kinematics of a turn at constant rate: radius R = V / omega (uniform circular motion;
e.g. Bowditch, *The American Practical Navigator*, 2019, ch. "advance and transfer");
corner cut at the tangent distance R tan(|Delta| / 2) of the fillet of two lines. The
wakes of several ships superpose: linear waves add (Lamb 1932, art. 227), so the sea with
ships minus the same sea without ships is the sum of the ships' own wakes, non-zero
astern of each ship and zero far from all.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.rng import generator
from seaecho.sea import Sea
from seaecho.wake import Ship
from seaecho.wake.ship import Route

V = 5.0


def _l_route(r=100.0):
    return Route(((0.0, 0.0), (1000.0, 0.0), (1000.0, 1000.0)), r)


def test_legs_and_speed_put_the_ship_where_they_say():
    ship = Ship(length=20.0, beam=5.0, draft=1.0, speed=V, route=_l_route())
    # on the first leg: x = V t
    np.testing.assert_allclose(ship.position([0.0, 100.0]), [[0, 0], [500, 0]], atol=1e-9)
    # before t = 0: along the first leg, backwards
    np.testing.assert_allclose(ship.position(-10.0), [-50.0, 0.0], atol=1e-9)
    # the 90 deg corner is cut 100 tan 45 = 100 m before and after the waypoint; the arc
    # is a quarter circle of 50 pi m; then north along x = 1000
    s = 900.0 + 50.0 * np.pi + 300.0
    np.testing.assert_allclose(ship.position(s / V), [1000.0, 400.0], atol=1e-9)
    assert ship.heading_at(s / V) == pytest.approx(np.pi / 2)
    np.testing.assert_allclose(ship.velocity_at(s / V), [0.0, V], atol=1e-12)
    # the route's length: legs minus the cuts plus the arc
    assert ship.route.length == pytest.approx(2000.0 - 200.0 + 50.0 * np.pi)
    # past the last waypoint: straight on north
    t_end = ship.route.length / V
    np.testing.assert_allclose(ship.position(t_end + 2.0), [1000.0, 1000.0 + 2 * V],
                               atol=1e-9)


@pytest.mark.parametrize("rate_deg_s", [1.0, 3.0])
@pytest.mark.parametrize("turn", [+60.0, -120.0])
def test_a_turn_at_a_given_rate_has_radius_v_over_omega(rate_deg_s, turn):
    omega = np.deg2rad(rate_deg_s)
    r = V / omega
    a = np.deg2rad(turn)
    w = ((0.0, 0.0), (2000.0, 0.0), (2000.0 + 2000.0 * np.cos(a), 2000.0 * np.sin(a)))
    ship = Ship(length=20.0, beam=5.0, draft=1.0, speed=V, route=Route(w, r))
    cut = r * np.tan(0.5 * abs(a))
    t0 = (2000.0 - cut) / V
    t = t0 + np.linspace(0.0, abs(a) / omega, 50)  # during the turn
    p = ship.position(t)
    # the centre of the turn: R to the left (turn > 0) or right of the entry point
    c = np.array([2000.0 - cut, np.sign(a) * r])
    np.testing.assert_allclose(np.hypot(*(p - c).T), r, rtol=1e-10)
    # heading changes at omega
    h = np.unwrap(ship.heading_at(t))
    np.testing.assert_allclose(np.diff(h) / np.diff(t), np.sign(a) * omega, rtol=1e-9)
    # and leaves the turn on the second leg's course
    assert ship.heading_at(t[-1] + 1.0) == pytest.approx(a)


def test_route_refuses_turns_that_do_not_fit():
    with pytest.raises(ValueError, match="leg 0"):
        Route(((0, 0), (50, 0), (50, 50)), 100.0)  # a 100 m cut on a 50 m leg
    with pytest.raises(ValueError, match="coincide"):
        Route(((0, 0), (0, 0)), 10.0)


def test_track_coordinates_follow_the_route():
    ship = Ship(length=20.0, beam=5.0, draft=1.0, speed=V, route=_l_route())
    t = 400.0  # s = 2000 m: past the corner, on the north leg at y = 2000 - 900 - 50 pi...
    s_ship = V * t
    # a point on the first leg, 20 m to the left (north) of it, at x = 500
    xs, ys = ship.to_ship_frame(np.array([500.0]), np.array([20.0]), t)
    assert xs[0] == pytest.approx(s_ship - 500.0)
    assert ys[0] == pytest.approx(-20.0)  # y' positive to starboard (eq W2)
    # a straight ship: the route's frame agrees with eq W2 on the current leg
    straight = ship.at(t)
    x, y = np.array([1005.0, 990.0]), np.array([600.0, 500.0])
    np.testing.assert_allclose(ship.to_ship_frame(x, y, t), straight.to_ship_frame(x, y, t),
                               atol=1e-9)


def _sea(ships):
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=6.0)
    surface = SeaSurface(spec, size=(512.0, 512.0), shape=(128, 128),
                         rng=generator(1, "surface"))
    return Sea(surface, ships)


def test_wakes_of_several_ships_superpose():
    a = Ship(length=40.0, beam=8.0, draft=2.0, speed=6.0, heading=0.0,
             position0=(-50.0, 120.0), turbulent_wake_length=150.0)
    b = Ship(length=30.0, beam=6.0, draft=1.5, speed=5.0, heading=np.pi / 2,
             position0=(150.0, -100.0), route=None, turbulent_wake_length=150.0)
    both, none = _sea([a, b]).state(10.0), _sea(None).state(10.0)
    only_a, only_b = _sea([a]).state(10.0), _sea([b]).state(10.0)
    diff = both.elevation - none.elevation
    # the difference is the sum of the two wakes (linear superposition)
    np.testing.assert_allclose(diff, (only_a.elevation - none.elevation)
                               + (only_b.elevation - none.elevation), atol=1e-12)
    x, y = both.x, both.y

    def near(px, py, r):
        return (np.hypot(x[None, :] - px, y[:, None] - py) < r)

    for s in (a, b):
        p, h = s.position(10.0), s.heading
        astern = p - (0.5 * s.length + 40.0) * np.array([np.cos(h), np.sin(h)])
        assert np.abs(diff[near(*astern, 30.0)]).max() > 1e-3  # a wake astern
        assert both.wake_mask[near(*astern, 3.0)].max() > 0.1  # and a turbulent strip
    # ahead of both bows (the near-field window, eq W11, is exactly 0 there): nothing
    ahead = near(200.0, 200.0, 40.0)
    assert np.abs(diff[ahead]).max() == 0.0
    assert both.wake_mask[ahead].max() == 0.0
    # astern but far outside both Kelvin wedges (19.47 deg): below 1e-3 of the wakes'
    # peak (the plane-wave synthesis's leakage, ~1e-6 m, not a wave)
    far = near(-200.0, -200.0, 40.0)
    assert np.abs(diff[far]).max() < 1e-3 * np.abs(diff).max()
    assert both.wake_mask[far].max() == 0.0
    # the masks combine as 1 - (1 - m_a)(1 - m_b)
    np.testing.assert_allclose(both.wake_mask,
                               1 - (1 - only_a.wake_mask) * (1 - only_b.wake_mask),
                               atol=1e-15)
    # two ships in the same place: twice the Kelvin wake, damping 1 - (1 - m)^2
    twin = _sea([a, a]).state(10.0)
    np.testing.assert_allclose(twin.elevation - none.elevation,
                               2 * (only_a.elevation - none.elevation), atol=1e-12)
    assert only_a.wake_mask.max() > 0.5
    np.testing.assert_allclose(twin.wake_mask, 1 - (1 - only_a.wake_mask) ** 2, atol=1e-15)
