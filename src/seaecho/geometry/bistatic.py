r"""Bistatic geometry of facets: ranges and directions (float64), angles and bases.

Conventions (docs/conventions.md): ``n_i`` points from the transmitter towards the facet,
``n_s`` from the facet towards the receiver. The local angles and the polarisation-basis
rotations come from :mod:`seaecho.scattering.frames` (eqs F1-F4 there): this module only
adds the ranges and directions, and the global angles (about +z)::

    r_tx = |c - p_tx|,  n_i = (c - p_tx) / r_tx;  r_rx = |p_rx - c|,  n_s = (p_rx - c) / r_rx  (G1)

Ranges are float64: at 10 GHz a float32 range over kilometres is off by degrees of phase.
"""

from __future__ import annotations

import numpy as np

__all__ = ["global_angles", "ranges_directions"]

_EZ = np.array([0.0, 0.0, 1.0])


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("...i,...i->...", a, b)


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
        Unit vectors transmitter -> facet and facet -> receiver [-].
    """
    points = np.asarray(points, dtype=np.float64)
    tx = np.asarray(tx, dtype=np.float64).reshape(3)
    rx = np.asarray(rx, dtype=np.float64).reshape(3)
    d = points - tx
    r_tx = np.sqrt(_dot(d, d))
    if np.any(r_tx == 0.0):
        raise ValueError("the transmitter lies on a facet centroid (zero range)")
    n_i = d / r_tx[:, None]  # (G1)
    if np.array_equal(tx, rx):
        return r_tx, r_tx.copy(), n_i, -n_i
    d = rx - points
    r_rx = np.sqrt(_dot(d, d))
    if np.any(r_rx == 0.0):
        raise ValueError("the receiver lies on a facet centroid (zero range)")
    return r_tx, r_rx, n_i, d / r_rx[:, None]  # (G1)


def global_angles(n_i: np.ndarray, n_s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bistatic angles about the mean-plane normal +z.

    Same definitions as :func:`seaecho.scattering.frames.local_angles` with N = z, computed
    directly from the azimuths (cheaper): ``theta_i = arccos(-n_i,z)``,
    ``theta_s = arccos(n_s,z)``, ``phi = azimuth(n_s) - azimuth(n_i)`` wrapped to (-pi, pi].

    Parameters
    ----------
    n_i, n_s : (N, 3) arrays
        Unit incident and scattered directions [-].

    Returns
    -------
    theta_i, theta_s, phi : (N,) arrays
        [rad]. At a vertical direction (no azimuth) phi is measured from +x, as in
        :func:`seaecho.scattering.frames.reference_direction`.
    """
    theta_i = np.arccos(np.clip(-n_i[:, 2], -1.0, 1.0))
    theta_s = np.arccos(np.clip(n_s[:, 2], -1.0, 1.0))
    az_s = np.where(np.hypot(n_s[:, 0], n_s[:, 1]) < 1e-9, 0.0,
                    np.arctan2(n_s[:, 1], n_s[:, 0]))
    az_i = np.where(np.hypot(n_i[:, 0], n_i[:, 1]) < 1e-9, 0.0,
                    np.arctan2(n_i[:, 1], n_i[:, 0]))
    phi = az_s - az_i
    phi = np.where(phi > np.pi, phi - 2 * np.pi, np.where(phi <= -np.pi, phi + 2 * np.pi, phi))
    return theta_i, theta_s, phi
