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
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import frames
from .fresnel import fresnel_coefficients
from .slopes import CoxMunkParameters, cox_munk_factor, gaussian_log_pdf
from .validity import KirchhoffValidityWarning

#: Half-width of the Kirchhoff domain around specular [deg] (paper sec. III-B).
KIRCHHOFF_DOMAIN_DEG = 20.0

#: exp() argument cap: keeps sigma finite where |q|/q_N explodes (q_N -> 0).
_LOG_CAP = 700.0


def specular_normal(n_i: ArrayLike, n_s: ArrayLike) -> NDArray:
    """Unit normal ``q / |q|`` of the facet that reflects ``n_i`` into ``n_s`` [-].

    Where ``n_s = n_i`` (no reflection possible) +z is returned.
    """
    d = np.asarray(n_s, dtype=float) - np.asarray(n_i, dtype=float)
    norm = np.linalg.norm(d, axis=-1, keepdims=True)
    return np.where(norm > 1e-12, d / np.maximum(norm, 1e-300), frames.Z_HAT)


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
        ``F`` in the global FSA bases, (h, v) order; ``|F_mn| <= 1``.

    References
    ----------
    .. [1] Ulaby, Moore and Fung (1982), sec. 12-4; Khenchaf (2001), sec. 3.
    """
    n_i = np.asarray(n_i, dtype=float)
    n_s = np.asarray(n_s, dtype=float)
    n_sp = specular_normal(n_i, n_s)
    cos_iota = np.clip(-np.einsum("...i,...i->...", n_i, n_sp), 0.0, 1.0)
    r_h, r_v = fresnel_coefficients(cos_iota, eps_r)
    a_i, a_s = frames.tilt_rotation(n_i, n_s, n_sp)
    # Eq K2: F = A_s^T diag(R_h, R_v) A_i, written out for the diagonal middle matrix.
    r = np.stack([r_h, r_v], axis=-1)  # (..., 2)
    return np.einsum("...ji,...j,...jl->...il", a_s, r, a_i)


def _wind_axes(normal: NDArray, wind_direction: ArrayLike) -> tuple[NDArray, NDArray]:
    w = np.asarray(wind_direction, dtype=float)
    u = np.stack([np.cos(w), np.sin(w), np.zeros_like(w)], axis=-1)
    e_u = u - np.einsum("...i,...i->...", u, normal)[..., None] * normal
    e_u = e_u / np.linalg.norm(e_u, axis=-1, keepdims=True)
    return e_u, np.cross(normal, e_u)


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
    the plane (``q_N <= 0``) get ``gc = 0``.
    """
    n_i = np.asarray(n_i, dtype=float)
    n_s = np.asarray(n_s, dtype=float)
    shape = np.broadcast_shapes(n_i.shape, n_s.shape, np.shape(normal))
    nn = np.broadcast_to(np.asarray(normal, dtype=float), shape)
    n_sp = specular_normal(n_i, n_s)
    cos_n = np.einsum("...i,...i->...", n_sp, nn)
    valid = cos_n > 1e-12
    cn = np.where(valid, cos_n, 1e-12)
    e_u, e_c = _wind_axes(nn, wind_direction)
    # Slopes of the specular normal in the plane's wind frame.
    z_u = -np.einsum("...i,...i->...", n_sp, e_u) / cn
    z_c = -np.einsum("...i,...i->...", n_sp, e_c) / cn
    if cox_munk is None:
        log_p = gaussian_log_pdf(z_u, z_c, mss_upwind, mss_crosswind)
        gc = np.ones_like(log_p)
    else:
        log_p = gaussian_log_pdf(z_u, z_c, cox_munk.mss_upwind, cox_munk.mss_crosswind)
        gc = cox_munk_factor(z_u, z_c, cox_munk)
    # Eq K1: pi (|q| / q_N)^4 P, with |q| / q_N = 1 / cos_n.
    log_w = np.minimum(np.log(np.pi) - 4.0 * np.log(cn) + log_p, _LOG_CAP)
    return log_w, np.where(valid, gc, 0.0)


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
           "kirchhoff_sigma", "specular_normal"]
