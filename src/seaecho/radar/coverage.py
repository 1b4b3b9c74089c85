"""Does the beam reach the sea tile? A conservative bound of the two-way gain over it.

A scanning antenna (docs/scanning.md) looks away from the sea tile for most of a
revolution. The sea's per-pulse work can then be skipped with a stated truncation: if,
at pulse p, the two-way gain relative to the beam peak is below a floor g_f at *every*
point of the tile, the skipped sea echo power is at most g_f times the power the tile
would return with all of it at the peak of both beams (docs/scanning.md, "Skipping the
sea outside the beam").

The bound. For a rectangular aperture (eq A1 of :mod:`seaecho.radar.antennas`)

    G(d) / G_peak = [(1 + cos theta) / 2]^2 F_w(a u / lambda)^2 sinc^2(b v / lambda)
                  <= [(1 + c) / 2]^2 E_w(a |u| / lambda)^2                          (C1)

with u = d . y_a the direction cosine along the width, E_w(t) = max_{|s| >= t}
|F_w(s)| the width pattern's envelope (the height's sinc is at most 1, and 1 at the
peak) and c >= cos theta = d . x_a: the largest cos theta of the set's corners when they
all lie behind the aperture's plane (cos theta is quasi-convex where negative, by the
argument below), else 1. E_w is non-increasing, so over a set of directions the bound is
E_w(min |u| a / lambda)^2. The directions towards a convex set of points (the tile's
box) from an antenna outside it: u(p) = y_a . (p - o) / |p - o| is the cosine of the
angle to y_a, whose super-level sets {u >= c}, c > 0, are convex cones, so u is
quasi-concave where positive (quasi-convex where negative): min |u| over the box is 0 if
its corners lie on both sides of the plane u = 0 (the beam's plane crosses it), else it
is reached at a corner. The two-way bound is the product of the transmitter's and the
receiver's (eq C2); a pattern other than ``rectangular`` bounds its factor by 1.

E_w is tabulated on |s| in [0, a / lambda] (|u| <= 1) at steps of 1/256 and taken at
the step below t (a maximum over a larger interval), times 1.001: the lobes are at least
one unit of s wide, so sampling misses their peaks by less than (pi / 512)^2 / 2 = 2e-5.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .antennas import Antenna, line_pattern

#: Steps per unit of t = a u / lambda of the envelope table [-].
ENVELOPE_STEPS = 256
#: Relative margin on the tabulated envelope (its sampling error is below 2e-5) [-].
ENVELOPE_MARGIN = 1.001


@lru_cache(maxsize=16)
def _envelope_table(illumination: str, sidelobe_db: float, nbar: int, t_max: float
                    ) -> NDArray[np.float64]:
    """E_w at s_i = i / ENVELOPE_STEPS, i = 0 .. ceil(t_max * steps): max |F_w| over
    [s_i, t_max] (eq C1), with the sampling margin."""
    n = int(np.ceil(t_max * ENVELOPE_STEPS)) + 1
    s = np.arange(n) / ENVELOPE_STEPS
    f = np.abs(np.asarray(line_pattern(s, illumination, sidelobe_db, nbar), dtype=float))
    env = np.maximum.accumulate(f[::-1])[::-1]
    env = np.minimum(env * ENVELOPE_MARGIN, 1.0)
    env.setflags(write=False)
    return env


def width_envelope(antenna: Antenna, t: ArrayLike) -> NDArray[np.float64]:
    """Envelope E_w(|t|) >= max_{|s| >= |t|} |F_w(s)| of a rectangular aperture's width
    pattern at t = a u / lambda (eq C1) [-]; 1 at t = 0.

    Parameters
    ----------
    antenna : Antenna
        A ``rectangular`` antenna.
    t : array_like
        a u / lambda [-].
    """
    if antenna.pattern != "rectangular":
        raise ValueError(f"width_envelope: pattern = {antenna.pattern!r}; only "
                         "'rectangular' has a width pattern")
    t_max = antenna.width / antenna.wavelength
    env = _envelope_table(antenna.illumination, float(antenna.taylor_sidelobe_db),
                          int(antenna.taylor_nbar), float(t_max))
    i = np.floor(np.abs(np.asarray(t, dtype=float)) * ENVELOPE_STEPS).astype(np.int64)
    return env[np.clip(i, 0, env.size - 1)]


def one_way_bound(antenna: Antenna, axes: ArrayLike, origin: ArrayLike,
                  corners: ArrayLike) -> float:
    """Upper bound of G / G_peak over the convex hull of ``corners`` seen from ``origin``
    (eq C1) [-].

    Parameters
    ----------
    antenna : Antenna
    axes : array_like (3, 3)
        Antenna axes in the world, columns (boresight, width, height)
        (:func:`seaecho.radar.antennas.antenna_axes`).
    origin : array_like (3,)
        Antenna phase centre [m].
    corners : array_like (K, 3)
        Corners of a convex set of points [m]. If the set contains ``origin`` (an
        antenna over the tile, inside its box), every plane through ``origin`` has
        corners on both sides and the bound is 1, as it must be.

    Returns
    -------
    float
        In [0, 1]; 1 for a pattern other than ``rectangular``.
    """
    return float(one_way_bounds(antenna, axes, origin, np.asarray(corners)[None])[0])


def one_way_bounds(antenna: Antenna, axes: ArrayLike, origin: ArrayLike,
                   corners: ArrayLike) -> NDArray[np.float64]:
    """:func:`one_way_bound` of several convex sets at once, ``corners`` (S, K, 3) [m]:
    the bound of each, (S,) [-] (eq C1; the tiles of a radar-wide sea)."""
    corners = np.asarray(corners, dtype=float)
    if antenna.pattern != "rectangular":
        return np.ones(corners.shape[0])
    d = corners - np.asarray(origin, dtype=float)
    norm = np.linalg.norm(d, axis=-1)
    u = d @ np.asarray(axes, dtype=float)[:, 1] / norm
    c = (d @ np.asarray(axes, dtype=float)[:, 0] / norm).max(axis=-1)
    # Obliquity (1 + cos theta) / 2: cos theta is quasi-convex where negative, so behind
    # the aperture's plane its maximum over the set is at a corner; else bounded by 1
    ob = np.where(c <= 0.0, 0.5 * (1.0 + c), 1.0)
    crossed = (u.min(axis=-1) <= 0.0) & (u.max(axis=-1) >= 0.0)  # the beam's plane u = 0
    e = width_envelope(antenna, antenna.width * np.abs(u).min(axis=-1) / antenna.wavelength)
    return np.where(crossed, ob * ob, (ob * e) ** 2)


def two_way_bound(radar, pulse: int, corners: ArrayLike) -> float:
    """Upper bound of the two-way gain relative to the beams' peaks,
    (G_t / G_t,peak)(G_r / G_r,peak), over the convex hull of ``corners`` at ``pulse``
    (eq C2: the product of :func:`one_way_bound`) [-].

    A pure function of the radar's model and the pulse index: platforms and pointing at
    the pulse's emission time (:meth:`seaecho.radar.system.RadarSystem.geometry`).

    Parameters
    ----------
    radar : seaecho.radar.system.RadarSystem
    pulse : int
    corners : array_like (K, 3)
        Corners of a convex set of points [m] (the sea tile's box) in the simulation frame.
    """
    return float(two_way_bounds(radar, pulse, np.asarray(corners)[None])[0])


def two_way_bounds(radar, pulse: int, corners: ArrayLike) -> NDArray[np.float64]:
    """:func:`two_way_bound` of several convex sets at once, ``corners`` (S, K, 3) [m]:
    (S,) [-] (eq C2)."""
    geo = radar.geometry(pulse)
    # Eq C2: two-way = transmit x receive
    g = one_way_bounds(radar.tx_antenna, geo.tx_axes, geo.tx.position, corners)
    if not g.any():
        return g
    return g * one_way_bounds(radar.rx_antenna, geo.rx_axes, geo.rx.position, corners)


def tile_box(x: ArrayLike, y: ArrayLike, margin_m: float) -> NDArray[np.float64]:
    """The 8 corners of the box [min x - m, max x + m] x [min y - m, max y + m] x [-m, m]
    around a sea grid of coordinates ``x``, ``y`` [m], ``m = margin_m`` [m]: every facet
    vertex and phase centre of the sea lies inside while its elevations and horizontal
    displacements stay below ``margin_m``. Shape (8, 3) [m]."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    xs = (x.min() - margin_m, x.max() + margin_m)
    ys = (y.min() - margin_m, y.max() + margin_m)
    zs = (-margin_m, margin_m)
    return np.array([[a, b, c] for a in xs for b in ys for c in zs])


__all__ = ["ENVELOPE_MARGIN", "ENVELOPE_STEPS", "one_way_bound", "one_way_bounds",
           "tile_box", "two_way_bound", "two_way_bounds", "width_envelope"]
