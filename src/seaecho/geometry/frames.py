"""Bistatic geometry and polarisation frames (paper section II, Fig. 2).

Every function takes vectors on the last axis, shape ``(..., 3)``, broadcasts its inputs
and returns plain numpy arrays. World frame: x east, y north, z up.

Symbols (paper Fig. 2 -> code):

============================  ===============================================
``n_i``                       unit propagation direction of the incident wave
                              (from the transmitter towards the surface)
``n_s``                       unit propagation direction of the scattered wave
                              (from the surface towards the receiver)
``N`` (``normal``)            unit normal of the reference plane: +z for the
                              mean sea plane, the facet normal for local frames
``h = N x n / |N x n|``       horizontal polarisation unit vector  (eq F1)
``v = h x n``                 vertical polarisation unit vector    (eq F2)
``theta_i, theta_s``          angles of ``-n_i`` and ``n_s`` from ``N``
``phi = phi_s - phi_i``       azimuth of ``n_s`` from that of ``n_i`` about ``N``
``q = k (n_s - n_i)``         scattering (Bragg / specular) vector
============================  ===============================================

2x2 polarimetric matrices are stored in **(h, v) order**, ``M[..., m, n]`` with ``m`` the
received (scattered) and ``n`` the transmitted (incident) polarisation, so that
``M.reshape(..., 4)`` lists the channels HH, HV, VH, VV (the project's channel order).

Degenerate directions. When ``n`` is parallel to ``N`` (nadir incidence, zenith
scattering), ``N x n`` vanishes. The basis is then the limit taken as ``n`` approaches
``N`` from the azimuth of the *reference direction* (the world x axis projected on the
reference plane, or y if x is normal to it), so ``h = N x r / |N x r|``. The local
azimuth :func:`local_angles` uses the same reference, so the bistatic formulas, which
depend on ``phi_s - phi_i``, stay consistent with the bases at these points.

References
----------
.. [1] Ulaby, F. T., Moore, R. K. and Fung, A. K. (1982). *Microwave Remote Sensing*,
   Vol. II, ch. 12 (forward scattering alignment, local frames of two-scale models).
.. [2] Valenzuela, G. R. (1968). Scattering of electromagnetic waves from a tilted
   slightly rough surface. *Radio Science* 3(11), 1057-1066 (tilt rotation of the
   polarisation bases).
.. [3] Khenchaf, A. and Airiau, O. (2000). Bistatic radar moving returns from sea
   surface. *IEICE Trans. Electron.* E83-C(12), 1827-1835 (bistatic two-scale with
   local frames).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: Below this norm a cross product is treated as zero (the direction is along the normal).
_DEGENERATE = 1e-9

Z_HAT = np.array([0.0, 0.0, 1.0])
X_HAT = np.array([1.0, 0.0, 0.0])
Y_HAT = np.array([0.0, 1.0, 0.0])


def _dot(a: NDArray, b: NDArray) -> NDArray:
    """Dot product over the last axis."""
    return np.einsum("...i,...i->...", a, b)


def _normalise(a: NDArray) -> NDArray:
    return a / np.linalg.norm(a, axis=-1, keepdims=True)


def _as_vectors(a: ArrayLike, name: str) -> NDArray:
    a = np.asarray(a, dtype=float)
    if a.shape[-1:] != (3,):
        raise ValueError(f"{name} must have shape (..., 3), got {a.shape}")
    return a


def reference_direction(normal: ArrayLike) -> NDArray:
    """Unit tangent of the reference plane used at degenerate directions.

    Parameters
    ----------
    normal : array_like, shape (..., 3)
        Unit normal ``N`` of the reference plane [-].

    Returns
    -------
    ndarray, shape (..., 3)
        World x projected on the plane and normalised, or world y projected when ``N``
        is (nearly) along x [-].
    """
    n = _as_vectors(normal, "normal")
    # Project x on the plane; fall back on y when x is (nearly) along the normal.
    rx = X_HAT - _dot(n, X_HAT)[..., None] * n
    ry = Y_HAT - _dot(n, Y_HAT)[..., None] * n
    bad = np.linalg.norm(rx, axis=-1) < 0.5
    r = np.where(bad[..., None], ry, rx)
    return _normalise(r)


def polarisation_basis(
    n: ArrayLike, normal: ArrayLike = Z_HAT
) -> tuple[NDArray, NDArray]:
    """Horizontal and vertical polarisation unit vectors (forward scattering alignment).

    .. math::
        \\hat h = \\frac{\\hat N \\times \\hat n}{|\\hat N \\times \\hat n|}, \\qquad
        \\hat v = \\hat h \\times \\hat n \\qquad \\text{(F1, F2)}

    Parameters
    ----------
    n : array_like, shape (..., 3)
        Unit propagation direction (``n_i`` or ``n_s``) [-].
    normal : array_like, shape (..., 3), optional
        Unit normal of the reference plane [-]; +z (mean sea plane, the paper's Fig. 2)
        by default, a facet normal for local bases.

    Returns
    -------
    h, v : ndarray, shape (..., 3)
        Orthonormal, both perpendicular to ``n``; ``(h, v, n)`` satisfies
        ``h x v = -n``. At ``n`` parallel to ``normal`` the limit from the reference
        azimuth is returned (module docstring).

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), Vol. II, sec. 12-2; paper Fig. 2.
    """
    n = _as_vectors(n, "n")
    nn = _as_vectors(normal, "normal")
    n, nn = np.broadcast_arrays(n, nn)
    # Eq F1: h along N x n = N x t (t the tangential part of n), with the
    # reference-azimuth limit where t vanishes; the same test as local_angles, so the
    # bases and the local azimuths always agree on which directions are degenerate.
    t = n - _dot(n, nn)[..., None] * nn
    degenerate = np.linalg.norm(t, axis=-1, keepdims=True) < _DEGENERATE
    if np.any(degenerate):
        t = np.where(degenerate, reference_direction(nn), t)
    c = np.cross(nn, t)
    if np.any(degenerate):
        # Near-degenerate n is only within 1e-9 of N: make h exactly normal to n.
        c = c - _dot(c, n)[..., None] * n
    h = c / np.linalg.norm(c, axis=-1, keepdims=True)
    # Eq F2: v completes the right-handed triad.
    v = np.cross(h, n)
    return h, v


def directions_from_angles(
    theta_i: ArrayLike, phi_i: ArrayLike, theta_s: ArrayLike, phi_s: ArrayLike
) -> tuple[NDArray, NDArray]:
    """Incident and scattered unit directions from the mean-plane angles (paper Fig. 2).

    .. math::
        \\hat n_i = (\\sin\\theta_i\\cos\\phi_i, \\sin\\theta_i\\sin\\phi_i, -\\cos\\theta_i),
        \\quad
        \\hat n_s = (\\sin\\theta_s\\cos\\phi_s, \\sin\\theta_s\\sin\\phi_s, \\cos\\theta_s)

    so that ``phi_s = phi_i`` with ``theta_s = theta_i`` is the forward specular direction
    and ``phi_s = phi_i + pi`` with ``theta_s = theta_i`` is backscatter (monostatic), as in
    the paper's eq 9.

    Parameters
    ----------
    theta_i, theta_s : array_like
        Incidence and scattering angles from +z [rad], in [0, pi/2].
    phi_i, phi_s : array_like
        Azimuths of the horizontal propagation directions, counter-clockwise from +x
        [rad].

    Returns
    -------
    n_i, n_s : ndarray, shape (..., 3)
    """
    ti, pi_, ts, ps = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in
                                            (theta_i, phi_i, theta_s, phi_s)))
    n_i = np.stack([np.sin(ti) * np.cos(pi_), np.sin(ti) * np.sin(pi_), -np.cos(ti)], -1)
    n_s = np.stack([np.sin(ts) * np.cos(ps), np.sin(ts) * np.sin(ps), np.cos(ts)], -1)
    return n_i, n_s


def local_angles(
    n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike = Z_HAT
) -> tuple[NDArray, NDArray, NDArray]:
    """Bistatic angles of a geometry relative to a (local) reference plane.

    .. math::
        \\cos\\theta_i = -\\hat n_i\\cdot\\hat N, \\quad
        \\cos\\theta_s = \\hat n_s\\cdot\\hat N, \\quad
        \\phi = \\operatorname{atan2}(\\mathbf t_s\\cdot(\\hat N\\times\\hat e_1),\\,
        \\mathbf t_s\\cdot\\hat e_1)

    with ``t = n - (n . N) N`` the tangential parts and ``e1 = t_i / |t_i|`` (the local
    incidence azimuth is 0). Where a tangential part vanishes the reference direction
    (:func:`reference_direction`) replaces it, consistently with
    :func:`polarisation_basis`.

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    normal : array_like, shape (..., 3), optional
        Unit normal of the reference plane [-] (+z by default).

    Returns
    -------
    theta_i, theta_s : ndarray
        Local incidence and scattering angles [rad], in [0, pi]; values above pi/2 mean
        the transmitter (receiver) is behind the plane.
    phi : ndarray
        ``phi_s - phi_i`` in the local frame [rad], in (-pi, pi].

    References
    ----------
    .. [1] Khenchaf and Airiau (2000), sec. 3 (local bistatic angles of a tilted facet).
    """
    n_i = _as_vectors(n_i, "n_i")
    n_s = _as_vectors(n_s, "n_s")
    nn = _as_vectors(normal, "normal")
    n_i, n_s, nn = np.broadcast_arrays(n_i, n_s, nn)
    ci = -_dot(n_i, nn)
    cs = _dot(n_s, nn)
    theta_i = np.arccos(np.clip(ci, -1.0, 1.0))
    theta_s = np.arccos(np.clip(cs, -1.0, 1.0))
    t_i = n_i + ci[..., None] * nn
    t_s = n_s - cs[..., None] * nn
    ref = None
    ni_norm = np.linalg.norm(t_i, axis=-1, keepdims=True)
    ns_norm = np.linalg.norm(t_s, axis=-1, keepdims=True)
    if np.any(ni_norm < _DEGENERATE) or np.any(ns_norm < _DEGENERATE):
        ref = reference_direction(nn)
        t_i = np.where(ni_norm < _DEGENERATE, ref, t_i)
        t_s = np.where(ns_norm < _DEGENERATE, ref, t_s)
    e1 = _normalise(t_i)
    e2 = np.cross(nn, e1)
    phi = np.arctan2(_dot(t_s, e2), _dot(t_s, e1))
    return theta_i, theta_s, phi


def basis_rotation(
    n: ArrayLike, normal_from: ArrayLike, normal_to: ArrayLike
) -> NDArray:
    """2x2 matrix that carries field components between two polarisation bases of ``n``.

    For a transverse field ``E`` of direction ``n`` with components ``e_from`` in the
    basis ``(h, v)`` built on ``normal_from`` and ``e_to`` in the basis built on
    ``normal_to``,

    .. math::
        \\mathbf e_{to} = \\mathsf A\\, \\mathbf e_{from}, \\qquad
        \\mathsf A = \\begin{pmatrix} \\hat h'\\cdot\\hat h & \\hat h'\\cdot\\hat v \\\\
        \\hat v'\\cdot\\hat h & \\hat v'\\cdot\\hat v \\end{pmatrix} \\qquad \\text{(F3)}

    (primes: ``normal_to``). Both bases span the plane normal to ``n`` with the same
    handedness, so ``A`` is a rotation (``A^T = A^-1``, det 1).

    Parameters
    ----------
    n : array_like, shape (..., 3)
        Unit propagation direction [-].
    normal_from, normal_to : array_like, shape (..., 3)
        Unit normals defining the two bases [-].

    Returns
    -------
    ndarray, shape (..., 2, 2)
        ``A`` in (h, v) order.

    References
    ----------
    .. [1] Valenzuela (1968); Ulaby, Moore and Fung (1982), ch. 12 (two-scale model).
    """
    h0, v0 = polarisation_basis(n, normal_from)
    h1, v1 = polarisation_basis(n, normal_to)
    a = np.empty(np.broadcast_shapes(h0.shape, h1.shape)[:-1] + (2, 2))
    # Eq F3: projections of the old basis vectors on the new ones.
    a[..., 0, 0] = _dot(h1, h0)
    a[..., 0, 1] = _dot(h1, v0)
    a[..., 1, 0] = _dot(v1, h0)
    a[..., 1, 1] = _dot(v1, v0)
    return a


def tilt_rotation(
    n_i: ArrayLike, n_s: ArrayLike, normal_local: ArrayLike, normal_global: ArrayLike = Z_HAT
) -> tuple[NDArray, NDArray]:
    """Rotations between global (mean-plane) and local (facet) polarisation bases.

    Returns ``A_i`` (global -> local components of the incident field) and ``A_s``
    (global -> local components of the scattered field). A matrix ``S_loc`` computed
    in the local bases becomes, in the global bases (:func:`to_global`),

    .. math::
        \\mathsf S_{glob} = \\mathsf A_s^{T}\\, \\mathsf S_{loc}\\, \\mathsf A_i
        \\qquad \\text{(F4)}

    the polarisation rotation of two-scale models.

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    normal_local : array_like, shape (..., 3)
        Unit facet normal [-].
    normal_global : array_like, shape (..., 3), optional
        Unit normal of the global bases [-], +z by default.

    Returns
    -------
    a_i, a_s : ndarray, shape (..., 2, 2)

    References
    ----------
    .. [1] Valenzuela (1968); Khenchaf and Airiau (2000), sec. 3.
    """
    a_i = basis_rotation(n_i, normal_global, normal_local)
    a_s = basis_rotation(n_s, normal_global, normal_local)
    return a_i, a_s


def to_global(s_local: ArrayLike, a_i: NDArray, a_s: NDArray) -> NDArray:
    """Apply eq F4: ``S_glob = A_s^T S_loc A_i`` on matrices in (h, v) order.

    Parameters
    ----------
    s_local : array_like, shape (..., 2, 2)
        Scattering matrix (or amplitudes) in the local bases, complex or real.
    a_i, a_s : ndarray, shape (..., 2, 2)
        Rotations from :func:`tilt_rotation`.

    Returns
    -------
    ndarray, shape (..., 2, 2)
    """
    s = np.asarray(s_local)
    return np.einsum("...ji,...jk,...kl->...il", a_s, s, a_i)


def scattering_vector(n_i: ArrayLike, n_s: ArrayLike, k: ArrayLike = 1.0) -> NDArray:
    """Scattering vector ``q = k (n_s - n_i)`` [rad/m] (paper eq 7).

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    k : array_like
        Electromagnetic wavenumber [rad/m].

    Returns
    -------
    ndarray, shape (..., 3)
    """
    n_i = _as_vectors(n_i, "n_i")
    n_s = _as_vectors(n_s, "n_s")
    return np.asarray(k, dtype=float)[..., None] * (n_s - n_i)


def beta_angle(n_i: ArrayLike, n_s: ArrayLike, normal: ArrayLike = Z_HAT) -> NDArray:
    """Angle between a surface normal and ``q = k (n_s - n_i)`` [rad] (paper eqs 10-11).

    It is 0 in the specular direction of the plane of normal ``normal``, where the
    Kirchhoff approximation holds, and grows away from it.

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    normal : array_like, shape (..., 3), optional
        Unit (local) surface normal [-].

    Returns
    -------
    ndarray
        beta [rad] in [0, pi]. Where ``n_s = n_i`` (no scattering vector) it is pi/2.
    """
    n_i = _as_vectors(n_i, "n_i")
    n_s = _as_vectors(n_s, "n_s")
    nn = _as_vectors(normal, "normal")
    d = n_s - n_i
    qn = np.linalg.norm(d, axis=-1)
    cos_b = np.where(qn > _DEGENERATE, _dot(d, nn) / np.maximum(qn, _DEGENERATE), 0.0)
    return np.arccos(np.clip(cos_b, -1.0, 1.0))


__all__ = [
    "X_HAT",
    "Y_HAT",
    "Z_HAT",
    "basis_rotation",
    "beta_angle",
    "directions_from_angles",
    "local_angles",
    "polarisation_basis",
    "reference_direction",
    "scattering_vector",
    "tilt_rotation",
    "to_global",
]
