r"""Bistatic geometry of facets: ranges and directions (float64), angles and bases.

Conventions (docs/conventions.md): ``n_i`` points from the transmitter towards the facet,
``n_s`` from the facet towards the receiver. The local angles and the polarisation-basis
rotations come from :mod:`seaecho.geometry.frames` (eqs F1-F4 there): this module only
adds the ranges and directions, and the global angles (about +z)::

    r_tx = |c - p_tx|,  n_i = (c - p_tx) / r_tx;  r_rx = |p_rx - c|,  n_s = (p_rx - c) / r_rx  (G1)

Ranges are float64: at 10 GHz a float32 range over kilometres is off by degrees of phase.
Each formula is written once over an array namespace (:func:`ranges`, :func:`azimuths`;
:mod:`seaecho.backend`): the numpy functions below and the Dr.Jit frames kernel of the
tracing stage call them.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..backend import NUMPY, Boundary

__all__ = ["azimuths", "bistatic_angle", "global_angles", "ranges", "ranges_directions"]

#: Below this horizontal length a direction is vertical (no azimuth).
_VERTICAL = 1e-9


# ------------------------------------------------------------- formulas (any namespace)
def ranges(xp, points: Any, p_tx: Any, p_rx: Any, monostatic: bool
           ) -> tuple[Any, Any, Any, Any]:
    """Eq G1: ranges [m] and unit directions [-] between points and Tx / Rx positions.

    ``monostatic`` (Tx = Rx, a Python bool) reuses the transmit leg: ``r_rx = r_tx``,
    ``n_s = -n_i``.
    """
    d = points - p_tx
    r_tx = xp.norm(d)
    n_i = d * (1.0 / r_tx)  # (G1)
    if monostatic:
        return r_tx, r_tx, n_i, -n_i
    d = p_rx - points
    r_rx = xp.norm(d)
    return r_tx, r_rx, n_i, d * (1.0 / r_rx)  # (G1)


def azimuths(xp, n_i: Any, n_s: Any) -> tuple[Any, Any, Any]:
    """Bistatic angles about +z: ``theta_i, theta_s`` [rad] and ``phi`` in (-pi, pi] [rad].

    ``theta_i = arccos(-n_i,z)``, ``theta_s = arccos(n_s,z)``,
    ``phi = azimuth(n_s) - azimuth(n_i)`` wrapped to (-pi, pi]; a vertical direction has
    azimuth 0 (measured from +x, as :func:`seaecho.geometry.frames.reference_tangent`).
    """
    theta_i = xp.acos(xp.clip(-n_i.z, -1.0, 1.0))
    theta_s = xp.acos(xp.clip(n_s.z, -1.0, 1.0))

    def azimuth(n):
        vertical = xp.sqrt(n.x * n.x + n.y * n.y) < _VERTICAL
        return xp.select(vertical, 0.0, xp.atan2(n.y, n.x))

    phi = azimuth(n_s) - azimuth(n_i)
    phi = xp.select(phi > math.pi, phi - 2.0 * math.pi,
                    xp.select(phi <= -math.pi, phi + 2.0 * math.pi, phi))
    return theta_i, theta_s, phi


# ---------------------------------------------------------------------- numpy API
def ranges_directions(points: np.ndarray, tx: np.ndarray, rx: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Ranges and unit directions between facets and the transmitter / receiver (eq G1).

    Parameters
    ----------
    points : (N, 3) array
        Facet centroids [m].
    tx, rx : (3,) arrays
        Transmitter and receiver phase centres [m] (equal for monostatic).

    Returns
    -------
    r_tx, r_rx : (N,) float64 arrays
        Ranges transmitter -> facet and facet -> receiver [m].
    n_i, n_s : (N, 3) float64 arrays
        Unit vectors transmitter -> facet and facet -> receiver [-]. Formula:
        :func:`ranges`.
    """
    tx = np.asarray(tx, dtype=np.float64).reshape(3)
    rx = np.asarray(rx, dtype=np.float64).reshape(3)
    io = Boundary(NUMPY)
    with np.errstate(divide="ignore", invalid="ignore"):
        r_tx, r_rx, n_i, n_s = io.numpy(*ranges(NUMPY, io.vec3(points), NUMPY.vconst(tx),
                                                NUMPY.vconst(rx), bool(np.array_equal(tx, rx))))
    if np.any(r_tx == 0.0):
        raise ValueError("the transmitter lies on a facet centroid (zero range)")
    if np.any(r_rx == 0.0):
        raise ValueError("the receiver lies on a facet centroid (zero range)")
    return r_tx, r_rx, n_i, n_s


def global_angles(n_i: np.ndarray, n_s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bistatic angles about the mean-plane normal +z.

    Same definitions as :func:`seaecho.geometry.frames.local_angles` with N = z, computed
    directly from the azimuths (cheaper): ``theta_i = arccos(-n_i,z)``,
    ``theta_s = arccos(n_s,z)``, ``phi = azimuth(n_s) - azimuth(n_i)`` wrapped to (-pi, pi].
    Formula: :func:`azimuths`.

    Parameters
    ----------
    n_i, n_s : (N, 3) arrays
        Unit incident and scattered directions [-].

    Returns
    -------
    theta_i, theta_s, phi : (N,) arrays
        [rad]. At a vertical direction (no azimuth) phi is measured from +x, as in
        :func:`seaecho.geometry.frames.reference_direction`.
    """
    io = Boundary(NUMPY)
    return tuple(io.numpy(*azimuths(NUMPY, io.vec3(n_i), io.vec3(n_s))))


def bistatic_angle(tx: NDArray[np.float64], rx: NDArray[np.float64],
                   point: NDArray[np.float64]) -> NDArray[np.float64]:
    """Bistatic angle beta [rad] at ``point``: the angle between the directions from the
    point to the transmitter and to the receiver (Willis, *Bistatic Radar*, 2nd ed., 2005,
    section 3.1, Fig. 3.1), 0 for a monostatic radar.

    Parameters
    ----------
    tx, rx : (..., 3) arrays
        Transmitter and receiver positions [m].
    point : (3,) array
        The point [m].
    """
    a = np.asarray(tx, dtype=np.float64) - point
    b = np.asarray(rx, dtype=np.float64) - point
    cross = np.linalg.norm(np.cross(a, b), axis=-1)
    return np.arctan2(cross, np.sum(a * b, axis=-1))
