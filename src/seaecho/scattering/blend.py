"""Kirchhoff / small-perturbation blend of the paper (eqs 10-11), after Thorsos & Jackson.

.. math::
    \\sigma_{nn} = (1 - w_1)\\sigma_{nn,SP} + w_1\\sigma_{nn,K}, \\qquad
    \\sigma_{nm} = (1 - w_2)\\sigma_{nm,SP} + w_2\\sigma_{nm,K} \\qquad \\text{(B1, B2)}

.. math::
    \\log_{10} w_1(\\beta) = -\\left(\\frac{\\beta}{6\\pi}\\right)^8, \\qquad
    \\log_{10} w_2(\\beta) = -\\left(\\frac{\\beta}{20\\pi}\\right)^{1.5} \\qquad \\text{(B3, B4)}

``beta`` is the angle between the (local) surface normal and ``q = k (n_s - n_i)``, **in
degrees** (docs/conventions.md): ``w1 = 0.1`` at ``beta = 6 pi = 18.85 deg``, the
paper's "Kirchhoff valid within +-20 deg of specular"; ``w2 = 0.1`` at
``beta = 20 pi = 62.8 deg``. Co-polarised channels (HH, VV) use ``w1``, cross-polarised
(HV, VH) ``w2``.

References
----------
.. [1] Paper eqs 10-11 (section III-C).
.. [2] Thorsos, E. I. and Jackson, D. R. (1989). The validity of the perturbation
   approximation for rough surface scattering using a Gaussian roughness spectrum.
   *J. Acoust. Soc. Am.* 86(1), 261-277.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import frames
from .kirchhoff import kirchhoff_sigma
from .slopes import CoxMunkParameters
from .spm import HeightSpectrum, spm_sigma

#: Channels that are co-polarised, in the order HH, HV, VH, VV.
CO_POLARISED = np.array([True, False, False, True])


def blend_weights(beta_deg: ArrayLike) -> tuple[NDArray, NDArray]:
    """Kirchhoff weights ``w1`` (co-pol) and ``w2`` (cross-pol) of eqs B3-B4 [-].

    Parameters
    ----------
    beta_deg : array_like
        Angle between the surface normal and ``q`` [deg], >= 0.

    Returns
    -------
    w1, w2 : ndarray
        In (0, 1]; 1 at specular.

    References
    ----------
    .. [1] Paper eqs 10-11.
    """
    b = np.abs(np.asarray(beta_deg, dtype=float))
    # Eq B3.
    w1 = 10.0 ** (-((b / (6.0 * np.pi)) ** 8))
    # Eq B4.
    w2 = 10.0 ** (-((b / (20.0 * np.pi)) ** 1.5))
    return w1, w2


def channel_weights(beta_deg: ArrayLike) -> NDArray:
    """Kirchhoff weight per channel, shape (..., 4), HH, HV, VH, VV (eqs B1-B4)."""
    w1, w2 = blend_weights(beta_deg)
    return np.where(CO_POLARISED, w1[..., None], w2[..., None])


def blend(sigma_spm: ArrayLike, sigma_kirchhoff: ArrayLike, beta_deg: ArrayLike) -> NDArray:
    """Apply eqs B1-B2 channel by channel.

    Parameters
    ----------
    sigma_spm, sigma_kirchhoff : array_like, shape (..., 4)
        Scattering coefficients of both models [m^2/m^2], HH, HV, VH, VV.
    beta_deg : array_like, shape (...)
        Angle between normal and ``q`` [deg].

    Returns
    -------
    ndarray, shape (..., 4)

    References
    ----------
    .. [1] Paper eqs 10-11.
    """
    w = channel_weights(beta_deg)
    return (1.0 - w) * np.asarray(sigma_spm) + w * np.asarray(sigma_kirchhoff)


def blend_sigma(
    theta_i: ArrayLike,
    phi_i: ArrayLike,
    theta_s: ArrayLike,
    phi_s: ArrayLike,
    k: float,
    eps_r: complex,
    spectrum: HeightSpectrum,
    mss_upwind: float,
    mss_crosswind: float,
    wind_direction: float = 0.0,
    cox_munk: CoxMunkParameters | None = None,
) -> NDArray:
    """Mean-plane blend of SPM (eqs 8-9) and Kirchhoff/GO (eq 7) by eqs 10-11.

    Parameters
    ----------
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad].
    k : float
        Electromagnetic wavenumber [rad/m].
    eps_r : complex
        Sea-water permittivity [-].
    spectrum : callable
        Height spectrum ``W(kx, ky)`` [m^4].
    mss_upwind, mss_crosswind : float
        Slope variances for the Kirchhoff part [-].
    wind_direction : float
        Direction the wind blows towards [rad].
    cox_munk : CoxMunkParameters, optional
        Cox-Munk Gram-Charlier slopes instead of Gaussian ones.

    Returns
    -------
    ndarray, shape (..., 4)
        ``sigma_mn`` [m^2/m^2], HH, HV, VH, VV.
    """
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    beta = np.degrees(frames.beta_angle(n_i, n_s))
    s_spm = spm_sigma(theta_i, phi_i, theta_s, phi_s, k, eps_r, spectrum)
    s_k = kirchhoff_sigma(theta_i, phi_i, theta_s, phi_s, eps_r, mss_upwind, mss_crosswind,
                          wind_direction, cox_munk=cox_munk, warn=False)
    return blend(s_spm, s_k, beta)


__all__ = ["CO_POLARISED", "blend", "blend_sigma", "blend_weights", "channel_weights"]
