"""A hull riding the waves: heave, pitch and roll from the sea under its waterplane.

The quasi-static, wave-following estimate: the hull takes the plane that fits the sea
surface over its waterplane (the rectangle L x B around its centre, along its heading)
in the least-squares sense,

.. math::

    z(\\xi, \\eta) \\approx \\zeta_0 + a\\,\\xi + b\\,\\eta, \\qquad
    \\text{heave} = \\zeta_0,\\quad \\text{pitch} = \\arctan a,\\quad
    \\text{roll} = \\arctan b                                                 (S1)

with xi forward and eta to port (pitch positive bow up, roll positive starboard side
down, as the platforms' attitudes, docs/conventions.md). On a symmetric waterplane the
fit is the waterplane average of the elevation (heave) and its first moments (pitch,
roll). This is the long-wave limit of a ship's motion response: for waves much longer
than the hull the heave and pitch transfer functions tend to 1 and to the wave slope
(Faltinsen 1990, ch. 2; Lewis 1989, PNA vol. III, ch. 8), and the
averaging over the waterplane attenuates waves comparable to the hull or shorter
(a wave of wavelength L / n along the hull averages to zero heave). Neglected: the
dynamics (added mass, damping, the resonances of heave, pitch and roll: a ship rolls
most near its natural roll period, which this estimate does not know), the surge, sway
and yaw responses and the hull's own wave making.

References
----------
.. [1] O. M. Faltinsen, *Sea Loads on Ships and Offshore Structures*, Cambridge
   University Press (1990), ch. 2 (linear wave-induced motions; the long-wave limit).
.. [2] E. V. Lewis (ed.), *Principles of Naval Architecture*, 2nd rev., vol. III,
   SNAME (1989), ch. 8 (motions in waves).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray


def waterplane_motion(x: NDArray, y: NDArray, elevation: NDArray, centre, heading: float,
                      length: float, beam: float) -> tuple[float, float, float]:
    """Heave [m], pitch [rad] and roll [rad] of a hull following the sea (eq S1).

    Parameters
    ----------
    x : (nx,) array
        Grid x [m].
    y : (ny,) array
        Grid y [m].
    elevation : (ny, nx) array
        Sea surface elevation [m].
    centre : (2,) array_like
        The waterplane's centre (x, y) [m].
    heading : float
        The hull's heading, counter-clockwise from +x [rad].
    length, beam : float
        The waterplane's length and beam [m].

    Returns
    -------
    heave, pitch, roll : float
        0 where fewer than three grid nodes fall in the waterplane (a hull smaller than
        the grid spacing, or off the tile: no surface to follow).
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    c, s = np.cos(heading), np.sin(heading)
    cx, cy = float(centre[0]), float(centre[1])
    half = 0.5 * np.hypot(length, beam)
    # the grid nodes of the waterplane's bounding box, then the rectangle itself
    ix = np.flatnonzero(np.abs(x - cx) <= half)
    iy = np.flatnonzero(np.abs(y - cy) <= half)
    if ix.size == 0 or iy.size == 0:
        return 0.0, 0.0, 0.0
    dx = x[ix][None, :] - cx
    dy = y[iy][:, None] - cy
    xi = dx * c + dy * s
    eta = -dx * s + dy * c
    inside = (np.abs(xi) <= 0.5 * length) & (np.abs(eta) <= 0.5 * beam)
    if np.count_nonzero(inside) < 3:
        return 0.0, 0.0, 0.0
    z = np.asarray(elevation)[np.ix_(iy, ix)][inside]
    a = np.stack([np.ones_like(z), xi[inside], eta[inside]], axis=-1)
    # eq S1: the least-squares plane
    coef, *_ = np.linalg.lstsq(a, z, rcond=None)
    if not np.all(np.isfinite(coef)):
        return 0.0, 0.0, 0.0
    return float(coef[0]), float(np.arctan(coef[1])), float(np.arctan(coef[2]))


def hull_rotation(heading: float, pitch: float, roll: float) -> NDArray[np.float64]:
    """The world rotation (3, 3) that pitches and rolls a hull about its own axes:
    Rz(h) Ry(-pitch) Rx(roll) Rz(-h) (pitch bow up, roll starboard down; the platforms'
    convention, docs/conventions.md)."""
    ch, sh = np.cos(heading), np.sin(heading)
    cp, sp = np.cos(-pitch), np.sin(-pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    rz = np.array([[ch, -sh, 0.0], [sh, ch, 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return rz @ ry @ rx @ rz.T


__all__ = ["hull_rotation", "waterplane_motion"]
