"""Kirchhoff approximation, geometric-optics (stationary phase) limit: paper eq 7.

Only the surface points whose normal is the bisector of ``-n_i`` and ``n_s`` (the
specular points) contribute. Written in Barrick's form,

.. math::
    \\sigma_{mn} = \\pi \\frac{|\\mathbf q|^4}{q_N^4}\\, |F_{mn}|^2\\, P(Z_u, Z_c),
    \\qquad \\mathbf q = k(\\hat n_s - \\hat n_i),\\quad q_N = \\mathbf q\\cdot\\hat N
    \\qquad \\text{(K1)}

which is the paper's eq 7 with ``U_mn = F_mn |q| / k``. ``N`` is the mean-plane normal
(+z) or a facet normal, and ``P`` the density of the slopes (relative to that plane) of
the specular normal ``N_sp = q / |q|``:
``Z_u = -(N_sp . e_u) / (N_sp . N)``, ``Z_c = -(N_sp . e_c) / (N_sp . N)`` with ``e_u``
the downwind direction in the plane and ``e_c = N x e_u`` (:mod:`.slopes`).

``F`` is the 2x2 reflection matrix of the specular facet, in the global (+z) FSA bases:

.. math::
    \\mathsf F = \\mathsf A_s^T\\, \\mathrm{diag}(R_h(\\iota), R_v(\\iota))\\,
    \\mathsf A_i, \\qquad \\cos\\iota = -\\hat n_i\\cdot\\hat N_{sp} = |\\mathbf q|/(2k)
    \\qquad \\text{(K2)}

with the Fresnel coefficients at the local incidence angle ``iota`` and ``A_i``, ``A_s``
the rotations (eq F3) from the global bases to the bases of ``N_sp``. At nadir
backscatter ``F = diag(R_h, R_v)(0)``, ``|q|/q_N = 1`` and for Gaussian slopes
``sigma = pi P(0, 0) |R(0)|^2 = |R(0)|^2 / (2 sigma_u sigma_c)``, which is the classic
``|R(0)|^2 / mss`` for isotropic slopes of total mean square slope
``mss = sigma_u^2 + sigma_c^2``.

References
----------
.. [1] Barrick, D. E. (1968). Rough surface scattering based on the specular point
   theory. *IEEE Trans. Antennas Propag.* AP-16(4), 449-454.
.. [2] Ulaby, F. T., Moore, R. K. and Fung, A. K. (1982). *Microwave Remote Sensing*,
   Vol. II, sec. 12-4 (bistatic U_pq of the geometric-optics limit).
.. [3] Khenchaf, A. (2001). Bistatic scattering and depolarization by randomly rough
   surfaces: application to the natural rough surfaces in X-band. *Waves Random Media*
   11(2), 61-89.
.. [4] Cox, C. and Munk, W. (1954). *J. Opt. Soc. Am.* 44(11), 838-850.
.. [5] Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
   polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
   doi:10.1109/RADAR.2006.1631862 ("the paper").
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY, Boundary, Mat2
from ..geometry import frames
from .fresnel import reflection
from .slopes import CoxMunkParameters, cox_munk_factor, gaussian_log_pdf
from .validity import KirchhoffValidityWarning

#: Half-width of the Kirchhoff domain around specular [deg] (paper sec. III-B).
KIRCHHOFF_DOMAIN_DEG = 20.0

#: Normalised slopes beyond which the Gram-Charlier factor is evaluated at this value: the
#: Gaussian there is exp(-800) (0 in float64), and the factor's fourth powers stay finite
#: in float32.
_GC_SLOPE_CAP = 40.0
#: Below this cosine between the specular normal and the plane's normal: no specular point.
_GRAZING = 1e-12


# ------------------------------------------------------------- formulas (any namespace)
def specular_direction(xp, n_i: Any, n_s: Any, fallback: Any) -> Any:
    """Unit normal ``q / |q|`` of the facet that reflects ``n_i`` into ``n_s`` [-].

    ``fallback`` where ``n_s = n_i`` (no reflection possible).
    """
    d = n_s - n_i
    qn = xp.norm(d)
    ok = qn > frames.DEGENERATE
    return xp.select(ok, d * (1.0 / xp.select(ok, qn, 1.0)), fallback)


def specular_matrix(xp, n_i: Any, n_s: Any, n_sp: Any, eps_r: Any,
                    basis_i: tuple[Any, Any], basis_s: tuple[Any, Any]) -> Mat2:
    r"""Polarimetric reflection matrix ``F`` of the specular facet (eq K2).

    .. math::
        \mathsf F = \mathsf A_s^T\, \mathrm{diag}(R_h(\iota), R_v(\iota))\,
        \mathsf A_i, \qquad \cos\iota = -\hat n_i\cdot\hat N_{sp}

    with the Fresnel coefficients (eqs R1-R2) and ``A_i``, ``A_s`` the rotations (eq F3)
    from the given global bases of ``n_i``, ``n_s`` to the bases of ``N_sp``. These
    share ``h' = N_sp x n_i / |N_sp x n_i| = N_sp x n_s / |N_sp x n_s|`` (``N_sp`` is
    along ``n_s - n_i``), so ``v'_s = h' x n_s``.

    Parameters
    ----------
    xp : array namespace (:mod:`seaecho.backend`)
    n_i, n_s, n_sp : vectors
        Unit incident, scattered and specular-normal directions [-].
    eps_r : complex
        Relative permittivity [-].
    basis_i, basis_s : (h, v)
        Global FSA bases (eqs F1-F2) of ``n_i`` and ``n_s``.

    Returns
    -------
    Mat2 of complex [-]

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), sec. 12-4; Khenchaf (2001), sec. 3.
    """
    r_h, r_v = reflection(xp, -xp.dot(n_i, n_sp), eps_r)
    h, v_i = frames.fsa_basis(xp, n_i, n_sp)
    a_i = frames.basis_change(xp, basis_i, (h, v_i))
    a_s = frames.basis_change(xp, basis_s, (h, xp.cross(h, n_s)))
    return frames.global_matrix(Mat2.diag(r_h, r_v), a_i, a_s)  # eq K2


def wind_axes(xp, N: Any, cos_wind: Any, sin_wind: Any) -> tuple[Any, Any]:
    """Downwind ``e_u`` (the wind direction projected on the plane) and ``e_c = N x e_u``."""
    u = xp.vec(cos_wind, sin_wind, 0.0)
    e_u = xp.normalize(u - xp.dot(u, N) * N)
    return e_u, xp.cross(N, e_u)


def specular_weight(xp, n_sp: Any, N: Any, e_u: Any, e_c: Any, mss_upwind: Any,
                    mss_crosswind: Any, cox_munk: CoxMunkParameters | None) -> tuple[Any, Any]:
    r"""``log(pi |q|^4 / q_N^4 P(Z))`` of eq K1, and the Gram-Charlier factor ``gc``.

    .. math::
        \sigma_{mn} = \pi \frac{|\mathbf q|^4}{q_N^4}\, |F_{mn}|^2\, P(Z_u, Z_c)
        \qquad \text{(K1)}

    with ``|q| / q_N = 1 / (N_sp . N)`` and the slopes of the specular normal in the
    plane's wind frame ``Z_u = -(N_sp . e_u) / (N_sp . N)``,
    ``Z_c = -(N_sp . e_c) / (N_sp . N)``; ``P`` is the Gaussian of eq K3 (slope
    variances ``mss_upwind``, ``mss_crosswind``), or with ``cox_munk`` the Gaussian of
    its own variances times ``gc`` (eq K4). ``log_w`` is capped at the namespace's
    ``exp_cap`` (700 in float64; ``q_N -> 0``);
    ``gc = 0`` where the specular normal points into the plane (``q_N <= 0``).

    Returns
    -------
    log_w, gc : real arrays [-]

    References
    ----------
    .. [1] Barrick (1968); Cox and Munk (1954).
    """
    cos_n = xp.dot(n_sp, N)
    valid = cos_n > _GRAZING
    cn = xp.select(valid, cos_n, _GRAZING)
    inv = 1.0 / cn
    z_u = -xp.dot(n_sp, e_u) * inv
    z_c = -xp.dot(n_sp, e_c) * inv
    if cox_munk is None:
        log_p = gaussian_log_pdf(z_u, z_c, mss_upwind, mss_crosswind, xp=xp)
        gc = xp.select(valid, 1.0, 0.0)
    else:
        log_p = gaussian_log_pdf(z_u, z_c, cox_munk.mss_upwind, cox_munk.mss_crosswind, xp=xp)
        cap_u = _GC_SLOPE_CAP * math.sqrt(cox_munk.mss_upwind)
        cap_c = _GC_SLOPE_CAP * math.sqrt(cox_munk.mss_crosswind)
        gc = xp.select(valid, cox_munk_factor(xp.clip(z_u, -cap_u, cap_u),
                                              xp.clip(z_c, -cap_c, cap_c), cox_munk, xp=xp),
                       0.0)
    # Eq K1: pi (|q| / q_N)^4 P, with |q| / q_N = 1 / cos_n.
    log_w = xp.minimum(math.log(math.pi) - 4.0 * xp.log(cn) + log_p,
                       xp.exp_cap)
    return log_w, gc


# ---------------------------------------------------------------------- numpy API
def specular_normal(n_i: ArrayLike, n_s: ArrayLike) -> NDArray:
    """Unit normal ``q / |q|`` of the facet that reflects ``n_i`` into ``n_s`` [-].

    Where ``n_s = n_i`` (no reflection possible) +z is returned.
    """
    io = Boundary(NUMPY)
    return frames._np_vec(specular_direction(NUMPY, io.vec3(n_i), io.vec3(n_s),
                                             io.vec3(frames.Z_HAT)))


def kirchhoff_matrix(n_i: ArrayLike, n_s: ArrayLike, eps_r: ArrayLike) -> NDArray:
    """Polarimetric reflection matrix ``F`` of the specular facet (eq K2).

    Parameters
    ----------
    n_i, n_s : array_like, shape (..., 3)
        Unit incident and scattered directions [-].
    eps_r : array_like of complex
        Relative permittivity ``eps' - j eps''`` [-].

    Returns
    -------
    ndarray of complex, shape (..., 2, 2)
        ``F`` in the global FSA bases, (h, v) order; ``|F_mn| <= 1``. Formula:
        :func:`specular_matrix`.

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), sec. 12-4; Khenchaf (2001), sec. 3.
    """
    io = Boundary(NUMPY)
    vi, vs, z = io.vec3(n_i), io.vec3(n_s), io.vec3(frames.Z_HAT)
    n_sp = specular_direction(NUMPY, vi, vs, z)
    f = specular_matrix(NUMPY, vi, vs, n_sp, np.asarray(eps_r, dtype=complex),
                        frames.fsa_basis(NUMPY, vi, z), frames.fsa_basis(NUMPY, vs, z))
    return frames._np_mat(f)


def kirchhoff_log_weight(
    n_i: ArrayLike,
    n_s: ArrayLike,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    wind_direction: ArrayLike = 0.0,
    normal: ArrayLike = frames.Z_HAT,
    cox_munk: CoxMunkParameters | None = None,
) -> tuple[NDArray, NDArray]:
    """Log of the scalar factor ``pi |q|^4 / q_N^4 P(Z)`` of eq K1, and the GC factor.

    Returns ``(log_w, gc)`` with ``sigma_mn = exp(log_w) gc |F_mn|^2``; ``log_w`` is
    ``-inf``-free (q_N clipped to 1e-12 |q|) and ``gc`` is 1 for Gaussian slopes or the
    Cox-Munk Gram-Charlier factor (eq K4). Geometries whose specular normal points into
    the plane (``q_N <= 0``) get ``gc = 0``. Formula: :func:`specular_weight`.
    """
    io = Boundary(NUMPY)
    vi, vs, nn = io.vec3(n_i), io.vec3(n_s), io.vec3(normal)
    n_sp = specular_direction(NUMPY, vi, vs, io.vec3(frames.Z_HAT))
    w = np.asarray(wind_direction, dtype=float)
    e_u, e_c = wind_axes(NUMPY, nn, np.cos(w), np.sin(w))
    log_w, gc = specular_weight(NUMPY, n_sp, nn, e_u, e_c,
                                np.asarray(mss_upwind, dtype=float),
                                np.asarray(mss_crosswind, dtype=float), cox_munk)
    log_w, gc = np.broadcast_arrays(log_w, gc)
    return np.array(log_w), np.array(gc)


def kirchhoff_sigma(
    theta_i: ArrayLike,
    phi_i: ArrayLike,
    theta_s: ArrayLike,
    phi_s: ArrayLike,
    eps_r: ArrayLike,
    mss_upwind: ArrayLike,
    mss_crosswind: ArrayLike,
    wind_direction: ArrayLike = 0.0,
    cox_munk: CoxMunkParameters | None = None,
    warn: bool = True,
) -> NDArray:
    """Mean-plane bistatic geometric-optics scattering coefficients (paper eq 7; K1-K2).

    Parameters
    ----------
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad] (:func:`frames.directions_from_angles`).
    eps_r : array_like of complex
        Sea-water permittivity [-].
    mss_upwind, mss_crosswind : array_like
        Slope variances [-] (ignored when ``cox_munk`` is given).
    wind_direction : array_like
        Direction the wind blows towards, CCW from +x [rad].
    cox_munk : CoxMunkParameters, optional
        Use the Cox-Munk Gram-Charlier density instead of the Gaussian.
    warn : bool
        Emit :class:`KirchhoffValidityWarning` for geometries more than 20 deg from
        specular (beta > 20 deg).

    Returns
    -------
    ndarray, shape (..., 4)
        ``sigma_mn`` [m^2/m^2], HH, HV, VH, VV.

    References
    ----------
    .. [1] Paper eq 7; Barrick (1968); Ulaby, Moore and Fung (1982), sec. 12-4.
    """
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    if warn:
        beta = np.degrees(frames.beta_angle(n_i, n_s))
        if np.any(beta > KIRCHHOFF_DOMAIN_DEG):
            warnings.warn(
                f"Kirchhoff/GO used up to {np.max(beta):.1f} deg from specular (valid within "
                f"about {KIRCHHOFF_DOMAIN_DEG:g} deg): the diffuse part is missing",
                KirchhoffValidityWarning, stacklevel=2)
    f = kirchhoff_matrix(n_i, n_s, eps_r)
    log_w, gc = kirchhoff_log_weight(n_i, n_s, mss_upwind, mss_crosswind, wind_direction,
                                     cox_munk=cox_munk)
    s = (f.real**2 + f.imag**2) * (np.exp(log_w) * gc)[..., None, None]
    return s.reshape(s.shape[:-2] + (4,))


__all__ = ["KIRCHHOFF_DOMAIN_DEG", "kirchhoff_log_weight", "kirchhoff_matrix",
           "kirchhoff_sigma", "specular_direction", "specular_matrix", "specular_normal",
           "specular_weight", "wind_axes"]
