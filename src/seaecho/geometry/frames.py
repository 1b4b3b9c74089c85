"""Bistatic geometry and polarisation frames (paper section II, Fig. 2).

Each formula is written once, over an array namespace ``xp`` (:mod:`seaecho.backend`):
:func:`reference_tangent`, :func:`fsa_basis` (eqs F1-F2), :func:`local_geometry` and
:func:`bistatic_angles`, :func:`basis_change` (eq F3), :func:`tilt` and
:func:`global_matrix` (eq F4), :func:`cos_beta`. The numpy reference path and the fused
Dr.Jit kernels (scattering, tracing, radar) call these same functions. The numpy API
(:func:`polarisation_basis`, :func:`local_angles`, :func:`tilt_rotation`, ...) takes
vectors on the last axis, shape ``(..., 3)``, broadcasts its inputs and returns plain
numpy arrays. World frame: x east, y north, z up.

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
.. [4] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary, Mat2

#: Below this norm a cross product is treated as zero (the direction is along the normal).
DEGENERATE = 1e-9  # the float64 namespaces' ``degenerate`` (backend._LIMITS)
_DEGENERATE = DEGENERATE  # former name

Z_HAT = np.array([0.0, 0.0, 1.0])
X_HAT = np.array([1.0, 0.0, 0.0])
Y_HAT = np.array([0.0, 1.0, 0.0])


# ------------------------------------------------------------- formulas (any namespace)
def reference_tangent(xp, N: Any) -> Any:
    """Unit reference direction of the plane of unit normal ``N`` (degenerate directions).

    World x projected on the plane, ``x - (x . N) N = (1 - N_x^2, -N_x N_y, -N_x N_z)``,
    normalised; world y projected when ``N`` is within 60 deg of x (the projection of x
    is then shorter than 0.5).
    """
    rx = xp.vec(1.0 - N.x * N.x, -N.x * N.y, -N.x * N.z)
    ry = xp.vec(-N.y * N.x, 1.0 - N.y * N.y, -N.y * N.z)
    return xp.normalize(xp.select(xp.norm(rx) < 0.5, ry, rx))


def tangential_part(xp, n: Any, N: Any) -> tuple[Any, Any]:
    """``t = n - (n . N) N``, or the reference direction where it vanishes; and that mask.

    The tangential part of ``n`` has the length of ``N x n``: one test decides, for the
    bases and for the local azimuths alike, which directions are degenerate.
    """
    t = n - xp.dot(n, N) * N
    degenerate = xp.norm(t) < xp.degenerate
    return xp.select_lazy(degenerate, lambda: reference_tangent(xp, N), t), degenerate


def fsa_basis(xp, n: Any, N: Any) -> tuple[Any, Any]:
    r"""Forward-scattering-alignment basis ``(h, v)`` of direction ``n`` about ``N``.

    .. math::
        \hat h = \frac{\hat N \times \hat n}{|\hat N \times \hat n|}, \qquad
        \hat v = \hat h \times \hat n \qquad \text{(F1, F2)}

    computed as ``h = N x t / |t|`` (``t`` from :func:`tangential_part`, normal to
    ``N``, so that ``|N x n| = |t|``) and, where ``t`` vanishes, the limit from the
    reference azimuth, made exactly normal to ``n`` (a change below 1e-9 there, below
    rounding elsewhere).

    Parameters
    ----------
    xp : array namespace
    n, N : vectors of the namespace
        Unit propagation direction and unit normal of the reference plane [-].

    Returns
    -------
    h, v : vectors [-]

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), Vol. II, sec. 12-2; paper Fig. 2.
    """
    t, _ = tangential_part(xp, n, N)
    h = xp.cross(N, xp.normalize(t))  # eq F1
    # A degenerate n is within 1e-9 of N, not along it: make h exactly normal to n.
    h = h - xp.dot(h, n) * n
    return h, xp.cross(h, n)  # eq F2


def reversed_fsa_basis(xp, basis: tuple[Any, Any], n: Any, N: Any) -> tuple[Any, Any]:
    """:func:`fsa_basis` of ``-n`` about ``N`` from ``basis = fsa_basis(xp, n, N)`` [-].

    The tangential part of ``-n`` is ``-t``, so ``(h, v)`` of ``-n`` is ``(-h, v)``;
    where ``t`` vanishes both take the reference azimuth and it is ``(h, -v)``. Negation
    is exact and round-to-nearest is symmetric, so these are the numbers
    ``fsa_basis(xp, -n, N)`` computes, to the bit, for the price of a test (the
    monostatic receive side, ``n_s = -n_i``).
    """
    _, degenerate = tangential_part(xp, n, N)
    h, v = basis
    return xp.select(degenerate, h, -h), xp.select(degenerate, -v, v)


def reversed_basis_change(xp, a: Mat2, n: Any, N_from: Any, N_to: Any) -> Mat2:
    """:func:`basis_change` between the FSA bases of ``-n`` about ``N_from`` and about
    ``N_to``, from ``a``, the one of ``n`` [-].

    With :func:`reversed_fsa_basis` each basis of ``-n`` is ``(-h, v)`` or ``(h, -v)``:
    the diagonal of ``a`` keeps its sign and the off-diagonal flips, all four negated
    where exactly one of the two bases is degenerate (to the bit: products of negated
    factors round as the products of the factors).
    """
    _, deg_from = tangential_part(xp, n, N_from)
    _, deg_to = tangential_part(xp, n, N_to)
    flip = deg_from ^ deg_to
    return Mat2(xp.select(flip, -a.hh, a.hh), xp.select(flip, a.hv, -a.hv),
                xp.select(flip, a.vh, -a.vh), xp.select(flip, -a.vv, a.vv))


def local_geometry(xp, n_i: Any, n_s: Any, N: Any) -> tuple[Any, Any, Any, Any]:
    r"""Cosines of the local angles and the local azimuth of ``n_s`` about a plane.

    .. math::
        \cos\theta_i = -\hat n_i\cdot\hat N, \quad \cos\theta_s = \hat n_s\cdot\hat N,
        \quad (x_s, y_s) = (\mathbf t_s\cdot\hat e_1,\ \mathbf t_s\cdot(\hat N\times\hat e_1))

    with ``t`` the tangential parts (:func:`tangential_part`) and ``e1 = t_i / |t_i|``
    (the local incidence azimuth is 0): ``phi = atan2(y_s, x_s)``.

    Returns
    -------
    cos_i, cos_s, x_s, y_s
        [-], [-], [-], [-].
    """
    cos_i = -xp.dot(n_i, N)
    cos_s = xp.dot(n_s, N)
    t_i, _ = tangential_part(xp, n_i, N)
    t_s, _ = tangential_part(xp, n_s, N)
    e1 = xp.normalize(t_i)
    return cos_i, cos_s, xp.dot(t_s, e1), xp.dot(t_s, xp.cross(N, e1))


def bistatic_angles(xp, n_i: Any, n_s: Any, N: Any) -> tuple[Any, Any, Any]:
    """``theta_i, theta_s`` [rad] in [0, pi] and ``phi = phi_s - phi_i`` [rad] in (-pi, pi].

    From :func:`local_geometry`; values of ``theta`` above pi/2 mean the transmitter
    (receiver) is behind the plane.

    References
    ----------
    .. [1] Khenchaf and Airiau (2000), sec. 3 (local bistatic angles of a tilted facet).
    """
    cos_i, cos_s, x_s, y_s = local_geometry(xp, n_i, n_s, N)
    return (xp.acos(xp.clip(cos_i, -1.0, 1.0)), xp.acos(xp.clip(cos_s, -1.0, 1.0)),
            xp.atan2(y_s, x_s))


def basis_change(xp, basis_from: tuple[Any, Any], basis_to: tuple[Any, Any]) -> Mat2:
    r"""Rotation between two polarisation bases of one direction (eq F3).

    .. math::
        \mathbf e_{to} = \mathsf A\, \mathbf e_{from}, \qquad
        \mathsf A = \begin{pmatrix} \hat h'\cdot\hat h & \hat h'\cdot\hat v \\
        \hat v'\cdot\hat h & \hat v'\cdot\hat v \end{pmatrix} \qquad \text{(F3)}

    (primes: ``basis_to``), for bases ``(h, v)`` of :func:`fsa_basis`.

    References
    ----------
    .. [1] Valenzuela (1968); Ulaby, Moore and Fung (1982), ch. 12 (two-scale model).
    """
    h0, v0 = basis_from
    h1, v1 = basis_to
    return Mat2(xp.dot(h1, h0), xp.dot(h1, v0), xp.dot(v1, h0), xp.dot(v1, v0))


def tilt(xp, n_i: Any, n_s: Any, N_local: Any, N_global: Any) -> tuple[Mat2, Mat2]:
    """``A_i, A_s``: eq F3 from the global (``N_global``) to the local (``N_local``) bases.

    References
    ----------
    .. [1] Valenzuela (1968); Khenchaf and Airiau (2000), sec. 3.
    """
    a_i = basis_change(xp, fsa_basis(xp, n_i, N_global), fsa_basis(xp, n_i, N_local))
    a_s = basis_change(xp, fsa_basis(xp, n_s, N_global), fsa_basis(xp, n_s, N_local))
    return a_i, a_s


def global_matrix(s_local: Mat2, a_i: Mat2, a_s: Mat2) -> Mat2:
    r"""Eq F4: a matrix of the local bases in the global ones, ``A_s^T S_loc A_i``.

    .. math::
        \mathsf S_{glob} = \mathsf A_s^{T}\, \mathsf S_{loc}\, \mathsf A_i
        \qquad \text{(F4)}
    """
    return a_s.T @ s_local @ a_i


def cos_beta(xp, n_i: Any, n_s: Any, N: Any) -> Any:
    """Cosine of the angle between ``N`` and ``q = k (n_s - n_i)`` (paper eqs 10-11) [-].

    0 (beta = pi/2) where ``n_s = n_i`` (no scattering vector).
    """
    d = n_s - n_i
    qn = xp.norm(d)
    ok = qn > DEGENERATE
    return xp.select(ok, xp.dot(d, N) / xp.select(ok, qn, 1.0), 0.0)


# ---------------------------------------------------------------------- numpy API
def _as_vectors(a: ArrayLike, name: str) -> NDArray:
    a = np.asarray(a, dtype=float)
    if a.shape[-1:] != (3,):
        raise ValueError(f"{name} must have shape (..., 3), got {a.shape}")
    return a


def _vectors(*named: tuple[ArrayLike, str]) -> list:
    io = Boundary(NUMPY)
    return [io.vec3(_as_vectors(a, name)) for a, name in named]


def _np_vec(v: Any) -> NDArray:
    return np.stack(np.broadcast_arrays(v.x, v.y, v.z), axis=-1)


def _np_mat(m: Mat2) -> NDArray:
    e = np.broadcast_arrays(*(np.asarray(c) for c in m.flat()))
    return np.stack(e, axis=-1).reshape(e[0].shape + (2, 2))


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
        is (nearly) along x [-] (:func:`reference_tangent`).
    """
    (nn,) = _vectors((normal, "normal"))
    return _np_vec(reference_tangent(NUMPY, nn))


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
        azimuth is returned (module docstring). Formula: :func:`fsa_basis`.

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), Vol. II, sec. 12-2; paper Fig. 2.
    """
    nv, nn = _vectors((n, "n"), (normal, "normal"))
    h, v = fsa_basis(NUMPY, nv, nn)
    return _np_vec(h), _np_vec(v)


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
    :func:`polarisation_basis`. Formula: :func:`bistatic_angles`.

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
    vi, vs, nn = _vectors((n_i, "n_i"), (n_s, "n_s"), (normal, "normal"))
    out = bistatic_angles(NUMPY, vi, vs, nn)
    return tuple(np.asarray(a) for a in np.broadcast_arrays(*out))


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
    handedness, so ``A`` is a rotation (``A^T = A^-1``, det 1). Formula:
    :func:`basis_change`.

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
    nv, n0, n1 = _vectors((n, "n"), (normal_from, "normal_from"), (normal_to, "normal_to"))
    return _np_mat(basis_change(NUMPY, fsa_basis(NUMPY, nv, n0), fsa_basis(NUMPY, nv, n1)))


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

    the polarisation rotation of two-scale models. Formula: :func:`tilt`.

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
    vi, vs, nl, ng = _vectors((n_i, "n_i"), (n_s, "n_s"), (normal_local, "normal_local"),
                              (normal_global, "normal_global"))
    a_i, a_s = tilt(NUMPY, vi, vs, nl, ng)
    return _np_mat(a_i), _np_mat(a_s)


def _mat(a: ArrayLike) -> Mat2:
    a = np.asarray(a)
    return Mat2(a[..., 0, 0], a[..., 0, 1], a[..., 1, 0], a[..., 1, 1])


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
        Formula: :func:`global_matrix`.
    """
    return _np_mat(global_matrix(_mat(s_local), _mat(a_i), _mat(a_s)))


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
    Kirchhoff approximation holds, and grows away from it. Formula: :func:`cos_beta`.

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
    vi, vs, nn = _vectors((n_i, "n_i"), (n_s, "n_s"), (normal, "normal"))
    return np.arccos(np.clip(cos_beta(NUMPY, vi, vs, nn), -1.0, 1.0))


def tile_outline(size_x: float, size_y: float, n_edge: int = 65) -> NDArray[np.float64]:
    """Points on the edges of a sea tile centred on the origin, and its centre [m].

    Parameters
    ----------
    size_x, size_y : float
        Tile size along x (east) and y (north) [m].
    n_edge : int
        Points per edge, corners included.

    Returns
    -------
    ndarray, shape (4 n_edge + 1, 3)
        The four edges (z = 0), then the centre: the points whose ranges bound the receive
        window of a tile seen from any platform.
    """
    s = np.linspace(-0.5, 0.5, n_edge)
    lx, ly = size_x, size_y
    edge = np.concatenate([np.stack([s * lx, np.full_like(s, -0.5 * ly)], -1),
                           np.stack([s * lx, np.full_like(s, 0.5 * ly)], -1),
                           np.stack([np.full_like(s, -0.5 * lx), s * ly], -1),
                           np.stack([np.full_like(s, 0.5 * lx), s * ly], -1),
                           [[0.0, 0.0]]])
    return np.concatenate([edge, np.zeros((edge.shape[0], 1))], axis=1)


__all__ = [
    "DEGENERATE",
    "X_HAT",
    "Y_HAT",
    "Z_HAT",
    "basis_change",
    "basis_rotation",
    "beta_angle",
    "bistatic_angles",
    "tile_outline",
    "cos_beta",
    "directions_from_angles",
    "fsa_basis",
    "global_matrix",
    "local_angles",
    "local_geometry",
    "polarisation_basis",
    "reference_direction",
    "reference_tangent",
    "scattering_vector",
    "tangential_part",
    "tilt",
    "tilt_rotation",
    "to_global",
]
