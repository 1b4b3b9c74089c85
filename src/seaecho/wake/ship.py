"""The ship that makes the wake: hull dimensions and a straight, constant-speed track.

Frames
------
World frame: x east, y north, z up (docs/conventions.md). The ship sails towards the azimuth
``heading`` (counter-clockwise from +x) at speed ``V``; its hull centre (midship) is at

.. math::

    \\mathbf{p}(t) = \\mathbf{p}_0 + V t\\,(\\cos h, \\sin h)                     (W1)

Ship frame (used by the wake theory, :mod:`seaecho.wake.kelvin`): origin at midship,
``x'`` along the track pointing *behind* the ship (downstream in the ship's frame, where
the water streams past at speed V in +x'), ``y'`` completing a right-handed frame with z up:

.. math::

    x' = -(\\mathbf{r} - \\mathbf{p}(t))\\cdot\\hat{\\mathbf{h}}, \\qquad
    y' = -(\\mathbf{r} - \\mathbf{p}(t))\\cdot\\hat{\\mathbf{n}}, \\qquad
    \\hat{\\mathbf{h}} = (\\cos h, \\sin h),\\;
    \\hat{\\mathbf{n}} = (-\\sin h, \\cos h).                                  (W2)

The bow is at x' = -L/2 and the stern at x' = +L/2.

Manoeuvres. A ship may instead follow a :class:`Route`: legs at constant speed between
waypoints, each corner rounded by a circular arc of radius R tangent to both legs (a
turn at the constant rate omega = V / R). The hull centre is then at arclength
s = V t along the route (at the first waypoint at t = 0; straight on along the first leg
before, along the last leg after), with the heading of the route's tangent there.
:meth:`Ship.at` gives the straight-course ship tangent to the route at a time (the
Kelvin wake's quasi-steady frame, docs/wake.md); :meth:`Ship.to_ship_frame` gives, for a
route, the curvilinear coordinates of the track the ship has sailed (x' the arclength
behind midship, y' the signed distance from the track), in which the turbulent wake
follows a curved track.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import G
from .film import DEFAULT_WAKE_FILM_ELASTICITY

#: Default length of the turbulent wake strip, in ship lengths (a modelling choice,
#: docs/wake.md).
DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS = 20.0
#: Kelvin-wake height models: empirical (Kriebel & Seelig 2005) or Michell's theory.
WAKE_AMPLITUDE_MODELS = ("kriebel-seelig", "michell")


def _wrap(a: NDArray | float) -> NDArray[np.float64]:
    """Angle wrapped into (-pi, pi] [rad]."""
    return np.pi - np.mod(np.pi - np.asarray(a, dtype=np.float64), 2.0 * np.pi)


@dataclass(frozen=True)
class Route:
    """Waypoints joined by straight legs and circular turns of one radius.

    Segments of constant curvature kappa (0 on a leg, +-1/R on a turn, + turning
    counter-clockwise): segment i starts at arclength ``s0[i]`` at point ``p0[i]`` with
    heading ``h0[i]``; at local arclength u its point is

    .. math::

        \\mathbf p = \\mathbf p_0 + \\frac{1}{\\kappa}\\big(\\sin(h_0 + \\kappa u) - \\sin h_0,
        \\; \\cos h_0 - \\cos(h_0 + \\kappa u)\\big), \\qquad h = h_0 + \\kappa u     (W18)

    (the limit kappa -> 0 is the straight leg p0 + u (cos h0, sin h0)). A corner of turn
    angle Delta is cut at the tangent distance R tan(|Delta| / 2) before and after the
    waypoint (the fillet of two lines, e.g. Bowditch, *American Practical Navigator*,
    2019, "advance and transfer").

    Parameters
    ----------
    waypoints : (N, 2) array_like
        Points (x, y) [m], N >= 2, consecutive ones distinct.
    turn_radius : float
        R > 0 [m] (only used at corners).
    """

    waypoints: tuple
    turn_radius: float
    s0: NDArray[np.float64] = field(init=False, repr=False, compare=False)
    p0: NDArray[np.float64] = field(init=False, repr=False, compare=False)
    h0: NDArray[np.float64] = field(init=False, repr=False, compare=False)
    kappa: NDArray[np.float64] = field(init=False, repr=False, compare=False)
    seg_length: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        w = np.asarray(self.waypoints, dtype=np.float64)
        if w.ndim != 2 or w.shape[1] != 2 or w.shape[0] < 2 or not np.all(np.isfinite(w)):
            raise ValueError("waypoints: need at least two finite (x, y) points [m]")
        r = float(self.turn_radius)
        if not (np.isfinite(r) and r > 0.0):
            raise ValueError(f"turn_radius = {self.turn_radius!r} m: must be > 0")
        d = np.diff(w, axis=0)
        legs = np.hypot(d[:, 0], d[:, 1])
        if np.any(legs == 0.0):
            i = int(np.flatnonzero(legs == 0.0)[0])
            raise ValueError(f"waypoints {i} and {i + 1} coincide: a leg needs a length")
        a = np.arctan2(d[:, 1], d[:, 0])
        turn = _wrap(np.diff(a))  # turn angle at each inner waypoint [rad]
        cut = np.concatenate([[0.0], r * np.tan(0.5 * np.abs(turn)), [0.0]])
        if np.any(np.abs(turn) > np.pi - 1e-9):
            i = int(np.flatnonzero(np.abs(turn) > np.pi - 1e-9)[0]) + 1
            raise ValueError(f"waypoint {i}: the route turns back on itself (180 deg); a "
                             "U-turn needs an intermediate waypoint")
        over = cut[:-1] + cut[1:] > legs * (1.0 + 1e-12)
        if np.any(over):
            i = int(np.flatnonzero(over)[0])
            raise ValueError(
                f"leg {i} (waypoints {i} to {i + 1}) is {legs[i]:.4g} m long but its turns "
                f"at radius {r:.4g} m need {cut[i] + cut[i + 1]:.4g} m: a smaller radius "
                "(a faster turn rate) or waypoints further apart")
        s0, p0, h0, kappa, length = [], [], [], [], []
        s = 0.0
        for i in range(len(legs)):
            u = d[i] / legs[i]
            start = w[i] + cut[i] * u
            n = legs[i] - cut[i] - cut[i + 1]
            s0.append(s), p0.append(start), h0.append(a[i]), kappa.append(0.0)
            length.append(n)
            s += n
            if i + 1 < len(legs):
                s0.append(s), p0.append(w[i + 1] - cut[i + 1] * u), h0.append(a[i])
                kappa.append(np.sign(turn[i]) / r)
                length.append(r * abs(turn[i]))
                s += r * abs(turn[i])
        for name, v in (("s0", s0), ("p0", p0), ("h0", h0), ("kappa", kappa),
                        ("seg_length", length)):
            object.__setattr__(self, name, np.asarray(v, dtype=np.float64))
        object.__setattr__(self, "waypoints", tuple(map(tuple, w.tolist())))

    @property
    def length(self) -> float:
        """Arclength from the first to the last waypoint [m]."""
        return float(self.s0[-1] + self.seg_length[-1])

    def _segment(self, s: NDArray) -> NDArray[np.intp]:
        """Segment index of arclengths s (the first leg before 0, the last after the end)."""
        i = np.searchsorted(self.s0, s, side="right") - 1
        return np.clip(i, 0, self.s0.size - 1)

    def point(self, s: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Position (..., 2) [m] and heading (...) [rad] at arclength(s) s [m] (eq W18)."""
        s = np.asarray(s, dtype=np.float64)
        i = self._segment(s)
        u = s - self.s0[i]
        return self._at(i, u)

    def _at(self, i, u):
        h0, k, p0 = self.h0[i], self.kappa[i], self.p0[i]
        h = h0 + k * u
        straight = k == 0.0
        ks = np.where(straight, 1.0, k)
        # eq W18 (the straight limit where kappa = 0)
        dx = np.where(straight, u * np.cos(h0), (np.sin(h) - np.sin(h0)) / ks)
        dy = np.where(straight, u * np.sin(h0), (np.cos(h0) - np.cos(h)) / ks)
        return p0 + np.stack([dx, dy], axis=-1), h

    def nearest(self, x: NDArray, y: NDArray, s_lo: float, s_hi: float
                ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Arclength of the nearest route point within [s_lo, s_hi] [m] and the signed
        distance to it, positive to the left of the route [m], of points (x, y)."""
        best_d = np.full(np.broadcast(x, y).shape, np.inf)
        best_s = np.zeros_like(best_d)
        best_l = np.zeros_like(best_d)
        n = self.s0.size
        for i in range(n):  # a handful of segments, each vectorised over the points
            a = self.s0[i] if i > 0 else -np.inf
            b = self.s0[i] + self.seg_length[i] if i < n - 1 else np.inf
            lo, hi = max(a, s_lo), min(b, s_hi)
            if lo > hi:
                continue
            ulo, uhi = lo - self.s0[i], hi - self.s0[i]
            h0, k, p0 = self.h0[i], self.kappa[i], self.p0[i]
            rx, ry = x - p0[0], y - p0[1]
            if k == 0.0:
                u = np.clip(rx * np.cos(h0) + ry * np.sin(h0), ulo, uhi)
            else:
                # centre of the turn, and the angle swept from the start to the point
                cx, cy = -np.sin(h0) / k, np.cos(h0) / k
                phi0 = np.arctan2(-cy, -cx)
                phi = np.arctan2(ry - cy, rx - cx)
                sweep = np.mod(np.sign(k) * (phi - phi0) + np.pi / 2, 2 * np.pi) - np.pi / 2
                u = np.clip(sweep / abs(k), ulo, uhi)
            p, h = self._at(np.full(u.shape, i), u)
            ex, ey = x - p[..., 0], y - p[..., 1]
            dist = np.hypot(ex, ey)
            better = dist < best_d
            best_d = np.where(better, dist, best_d)
            best_s = np.where(better, self.s0[i] + u, best_s)
            best_l = np.where(better, -np.sin(h) * ex + np.cos(h) * ey, best_l)
        return best_s, best_l


@dataclass(frozen=True)
class Ship:
    """A ship sailing in a straight line at constant speed (eq W1).

    Parameters
    ----------
    length : float
        Waterline length L [m], > 0.
    beam : float
        Beam B [m], 0 < B < L.
    draft : float
        Draft T [m], > 0.
    speed : float
        Speed through the water V [m/s], >= 0.
    heading : float
        Course the ship sails towards, counter-clockwise from +x (east) [rad].
    position0 : tuple of float
        (x, y) of the hull centre (midship) at t = 0 [m].
    turbulent_wake_length : float or None
        Length of the turbulent (damped) wake strip behind the stern [m]; None for the
        default of 20 ship lengths.
    wake_amplitude : {"kriebel-seelig", "michell"}
        Heights of the Kelvin wake (:class:`seaecho.wake.KelvinWake`).
    wake_breaking_limit : bool
        Cap the Kelvin wake's waves at the breaking steepness.
    turbulent_wake_film_contrast_db : float or None
        Persistent Bragg contrast of the wake's surfactant film C_f [dB] (<= 0; eq W15),
        overriding the Marangoni model; None (default) takes C_f from the film's
        elasticity at ``bragg_wavenumber`` (eqs W16, W17).
    turbulent_wake_film_elasticity : float
        Dilational modulus of the wake's surfactant film E [N/m] (>= 0; eq W16).
    bragg_wavenumber : float or None
        The radar's Bragg wavenumber k_B at the scene [rad/m] (>= 0), at which the film's
        contrast is evaluated (eq W17); set by :mod:`seaecho.build` from the scene's
        carrier and geometry. None (no radar): without an override, the wake's damping
        is the turbulent part alone.
    route : Route or None
        Sail along this route at ``speed`` instead of the straight course (``heading``
        and ``position0`` are then the route's at t = 0).
    name : str
        A label.
    """

    length: float
    beam: float
    draft: float
    speed: float
    heading: float = 0.0
    position0: tuple[float, float] = (0.0, 0.0)
    turbulent_wake_length: float | None = None
    wake_amplitude: str = "kriebel-seelig"
    wake_breaking_limit: bool = True
    turbulent_wake_film_contrast_db: float | None = None
    turbulent_wake_film_elasticity: float = DEFAULT_WAKE_FILM_ELASTICITY
    bragg_wavenumber: float | None = None
    route: Route | None = None
    name: str = ""
    _p0: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for name in ("length", "beam", "draft"):
            value = getattr(self, name)
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"Ship.{name} = {value!r} m: must be a finite number > 0")
        if self.beam >= self.length:
            raise ValueError(
                f"Ship.beam = {self.beam!r} m must be smaller than Ship.length = {self.length!r} m"
            )
        if not np.isfinite(self.speed) or self.speed < 0.0:
            raise ValueError(f"Ship.speed = {self.speed!r} m/s: must be a finite number >= 0")
        if not np.isfinite(self.heading):
            raise ValueError(f"Ship.heading = {self.heading!r} rad: must be finite")
        p0 = np.asarray(self.position0, dtype=np.float64)
        if p0.shape != (2,) or not np.all(np.isfinite(p0)):
            raise ValueError(f"Ship.position0 = {self.position0!r}: must be two finite numbers [m]")
        if self.turbulent_wake_length is not None and not (
            np.isfinite(self.turbulent_wake_length) and self.turbulent_wake_length >= 0.0
        ):
            raise ValueError(
                f"Ship.turbulent_wake_length = {self.turbulent_wake_length!r} m: must be >= 0"
            )
        if self.wake_amplitude not in WAKE_AMPLITUDE_MODELS:
            raise ValueError(f"Ship.wake_amplitude = {self.wake_amplitude!r}: choose from "
                             f"{WAKE_AMPLITUDE_MODELS}")
        c_f = self.turbulent_wake_film_contrast_db
        if c_f is not None and not (np.isfinite(c_f) and c_f <= 0.0):
            raise ValueError(f"Ship.turbulent_wake_film_contrast_db = {c_f!r} dB: must be "
                             "<= 0 (or None for the Marangoni film model)")
        e = self.turbulent_wake_film_elasticity
        if not (np.isfinite(e) and e >= 0.0):
            raise ValueError(f"Ship.turbulent_wake_film_elasticity = {e!r} N/m: must be a "
                             "finite number >= 0")
        k_b = self.bragg_wavenumber
        if k_b is not None and not (np.isfinite(k_b) and k_b >= 0.0):
            raise ValueError(f"Ship.bragg_wavenumber = {k_b!r} rad/m: must be >= 0 (or None)")
        if self.route is not None:
            p, h = self.route.point(0.0)
            p0 = np.asarray(p, dtype=np.float64)
            object.__setattr__(self, "heading", float(h))
        object.__setattr__(self, "position0", (float(p0[0]), float(p0[1])))
        object.__setattr__(self, "_p0", p0)

    @property
    def direction(self) -> NDArray[np.float64]:
        """Unit vector of the heading, h_hat = (cos h, sin h) [-], shape (2,)."""
        return np.array([np.cos(self.heading), np.sin(self.heading)])

    @property
    def velocity(self) -> NDArray[np.float64]:
        """Velocity over ground V h_hat [m/s], shape (2,) (eq W1)."""
        return self.speed * self.direction

    def position(self, t: ArrayLike) -> NDArray[np.float64]:
        """Hull centre at time(s) ``t`` [s] [m], shape t.shape + (2,): p0 + V t h_hat
        (eq W1), or on the route at arclength V t (eq W18)."""
        t = np.asarray(t, dtype=np.float64)
        if self.route is not None:
            return self.route.point(self.speed * t)[0]
        return self._p0 + self.velocity * t[..., None]

    def heading_at(self, t: ArrayLike) -> NDArray[np.float64]:
        """Course at time(s) ``t`` [s], counter-clockwise from +x [rad]."""
        t = np.asarray(t, dtype=np.float64)
        if self.route is not None:
            return _wrap(self.route.point(self.speed * t)[1])
        return np.full(t.shape, float(_wrap(self.heading)))

    def turn_rate_at(self, t: ArrayLike) -> NDArray[np.float64]:
        """Rate of turn dh/dt at time(s) ``t`` [s] [rad/s]: V kappa on a route's turn
        (+ counter-clockwise, eq W18), 0 on a leg and on a straight course."""
        t = np.asarray(t, dtype=np.float64)
        if self.route is None:
            return np.zeros(t.shape)
        s = self.speed * t
        return self.speed * self.route.kappa[self.route._segment(s)]

    def velocity_at(self, t: ArrayLike) -> NDArray[np.float64]:
        """Velocity over ground at time(s) ``t`` [m/s], shape t.shape + (2,)."""
        h = self.heading_at(t)
        return self.speed * np.stack([np.cos(h), np.sin(h)], axis=-1)

    def at(self, t: float) -> Ship:
        """The straight-course ship tangent to this one's track at time ``t`` [s]: the
        same position, heading and speed at ``t`` (itself without a route)."""
        if self.route is None:
            return self
        p, h = self.position(t), float(self.heading_at(t))
        v = self.speed * np.array([np.cos(h), np.sin(h)])
        p0 = p - v * float(t)
        return dataclasses.replace(self, route=None, heading=h,
                                   position0=(float(p0[0]), float(p0[1])))

    @property
    def froude_number(self) -> float:
        """Length Froude number Fn = V / sqrt(g L) [-]."""
        return self.speed / np.sqrt(G * self.length)

    @property
    def wake_length(self) -> float:
        """Length of the turbulent wake strip behind the stern [m] (default 20 L)."""
        if self.turbulent_wake_length is None:
            return DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS * self.length
        return self.turbulent_wake_length

    def to_ship_frame(
        self, x: ArrayLike, y: ArrayLike, t: float
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """World coordinates -> ship-frame coordinates (x', y') (eq W2).

        Parameters
        ----------
        x, y : array_like
            World coordinates [m], broadcast together.
        t : float
            Time [s].

        Returns
        -------
        xs, ys : ndarray
            Distance behind midship along the track, and the transverse coordinate [m].
            On a route: the arclength behind midship of the nearest point of the track
            sailed (from 10^6 ship lengths behind to the bow) and the signed distance to
            it, y' positive to the right of the track as in eq W2.
        """
        if self.route is not None:
            x, y = np.broadcast_arrays(np.asarray(x, dtype=np.float64),
                                       np.asarray(y, dtype=np.float64))
            s_ship = self.speed * float(t)
            lo = s_ship - 1.0e6 * self.length
            s, left = self.route.nearest(x, y, lo, s_ship + 0.5 * self.length)
            return s_ship - s, -left
        p = self.position(t)
        dx = np.asarray(x, dtype=np.float64) - p[0]
        dy = np.asarray(y, dtype=np.float64) - p[1]
        c, s = np.cos(self.heading), np.sin(self.heading)
        xs = -(dx * c + dy * s)
        ys = -(-dx * s + dy * c)
        return xs, ys


__all__ = ["DEFAULT_TURBULENT_WAKE_SHIP_LENGTHS", "WAKE_AMPLITUDE_MODELS", "Route", "Ship"]
