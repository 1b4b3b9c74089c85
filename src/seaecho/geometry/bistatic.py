r"""Bistatic geometry of facets: ranges, directions, global and local angles, bases.

Conventions (``DESIGN.md``): ``n_i`` points from the transmitter towards the facet,
``n_s`` from the facet towards the receiver; theta_i, theta_s are measured from a normal
(``+z`` for the global angles, the facet normal ``N`` for the local ones); the azimuth
difference ``phi = phi_s - phi_i`` is the angle, about the normal, from the tangential part
of ``n_i`` to that of ``n_s`` (``phi = pi`` in backscatter, ``0`` in the forward/specular
plane), the paper's Fig. 2 with ``phi_i = 0``. Polarisation bases follow the forward
scattering alignment: ``h = z x n / |z x n|``, ``v = h x n`` (global) and the same with
``N`` instead of ``z`` (local).

Equations (``docs/tracing.md``)::

    r_tx = |c - p_tx|,  n_i = (c - p_tx) / r_tx;  r_rx = |p_rx - c|,  n_s = (p_rx - c) / r_rx  (G1)
    cos theta_i = -n_i . N,  cos theta_s = n_s . N                                        (G2)
    phi = atan2(N . (t_i x t_s), t_i . t_s),  t = n - (n . N) N                             (G3)
    T_i = [[v_i'.v_i, v_i'.h_i], [h_i'.v_i, h_i'.h_i]]   global -> local incident basis    (G4)
    T_s = [[v_s.v_s', v_s.h_s'], [h_s.v_s', h_s.h_s']]   local -> global scattered basis   (G5)
    S_global = T_s S_local T_i                                                             (G6)

Ranges are float64: at 10 GHz a float32 range over kilometres is off by degrees of phase.

References
----------
.. [Ulaby] F. T. Ulaby, D. G. Long, "Microwave Radar and Radiometric Remote Sensing",
   Univ. of Michigan Press, 2014, section 5-2 (FSA bases, bistatic angles).
"""

from __future__ import annotations

import numpy as np

__all__ = ["basis_rotation", "fsa_basis", "global_angles", "local_angles", "ranges_directions"]

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


def local_angles(n_i: np.ndarray, n_s: np.ndarray, normal: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bistatic angles of incidence and scattering about a normal (eqs G2-G3).

    Parameters
    ----------
    n_i, n_s : (..., 3) arrays
        Unit incident (transmitter -> facet) and scattered (facet -> receiver) directions.
    normal : (..., 3) or (3,) array
        Unit normal N (the facet normal, or ``(0, 0, 1)`` for global angles).

    Returns
    -------
    theta_i, theta_s : arrays
        Angles of ``-n_i`` and ``n_s`` from N [rad], in [0, pi] (> pi/2: behind the facet).
    phi : array
        Azimuth of ``n_s`` minus azimuth of ``n_i`` about N [rad], in (-pi, pi];
        pi in backscatter, 0 in the specular plane; 0 when a direction is along N.
    """
    ci = -_dot(n_i, normal)
    cs = _dot(n_s, normal)
    theta_i = np.arccos(np.clip(ci, -1.0, 1.0))  # (G2)
    theta_s = np.arccos(np.clip(cs, -1.0, 1.0))
    t_i = n_i + ci[..., None] * normal  # n_i - (n_i . N) N
    t_s = n_s - cs[..., None] * normal
    phi = np.arctan2(_dot(normal, np.cross(t_i, t_s)), _dot(t_i, t_s))  # (G3)
    return theta_i, theta_s, phi


def global_angles(n_i: np.ndarray, n_s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Bistatic angles about the mean-plane normal +z (eqs G2-G3 with N = z)."""
    return local_angles(n_i, n_s, _EZ)


def fsa_basis(n: np.ndarray, normal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Forward-scattering-alignment basis ``h = N x n / |N x n|``, ``v = h x n``.

    Parameters
    ----------
    n : (..., 3) array
        Unit propagation direction.
    normal : (..., 3) or (3,) array
        Unit reference normal (``z`` for the global basis, the facet normal for the local).

    Returns
    -------
    h, v : (..., 3) arrays
        Unit horizontal and vertical polarisation vectors. Where n is along N (normal
        incidence, h undefined), h falls back to the global ``z x n`` direction, then to +y.
    """
    n = np.asarray(n, dtype=np.float64)
    h = np.cross(np.broadcast_to(normal, n.shape), n)
    norm = np.sqrt(_dot(h, h))
    bad = norm < 1e-12
    if np.any(bad):
        hz = np.cross(_EZ, n[bad])
        nz = np.sqrt(_dot(hz, hz))
        vertical = nz < 1e-12
        hz[vertical] = (0.0, 1.0, 0.0)
        nz[vertical] = 1.0
        h[bad] = hz
        norm[bad] = nz
    h /= norm[..., None]
    return h, np.cross(h, n)


def basis_rotation(n_i: np.ndarray, n_s: np.ndarray, normal: np.ndarray
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Matrices that carry a local 2x2 scattering matrix into the global bases (G4-G6).

    With (v, h) ordered as the scattering matrix's rows and columns (E_v first), a
    scattering matrix ``S_local`` computed in the facet's local bases becomes
    ``S_global = T_s @ S_local @ T_i`` in the global bases (eq G6).

    Parameters
    ----------
    n_i, n_s : (N, 3) arrays
        Unit incident and scattered directions [-].
    normal : (N, 3) array
        Unit facet normals [-].

    Returns
    -------
    T_i, T_s : (N, 2, 2) arrays
        Rotation matrices (orthogonal, determinant +1).
    """
    h_i, v_i = fsa_basis(n_i, _EZ)
    h_s, v_s = fsa_basis(n_s, _EZ)
    hl_i, vl_i = fsa_basis(n_i, normal)
    hl_s, vl_s = fsa_basis(n_s, normal)
    t_i = np.empty(n_i.shape[:-1] + (2, 2))
    t_i[..., 0, 0] = _dot(vl_i, v_i)  # (G4)
    t_i[..., 0, 1] = _dot(vl_i, h_i)
    t_i[..., 1, 0] = _dot(hl_i, v_i)
    t_i[..., 1, 1] = _dot(hl_i, h_i)
    t_s = np.empty_like(t_i)
    t_s[..., 0, 0] = _dot(v_s, vl_s)  # (G5)
    t_s[..., 0, 1] = _dot(v_s, hl_s)
    t_s[..., 1, 0] = _dot(h_s, vl_s)
    t_s[..., 1, 1] = _dot(h_s, hl_s)
    return t_i, t_s
