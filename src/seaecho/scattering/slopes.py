"""Sea-surface slope probability densities for geometric optics (paper eq 7).

Slopes are expressed in a wind-aligned frame: ``z_u`` is the slope along the direction
the wind blows *towards* (``dz/du``, u downwind), ``z_c`` the slope along the crosswind
axis (90 deg counter-clockwise from u).

- :func:`gaussian_slope_pdf`: anisotropic Gaussian with upwind and crosswind mean
  square slopes (e.g. from the spectrum, ``seaecho.ocean.twoscale.slope_variances``).
- :func:`cox_munk_pdf`: the Gram-Charlier series of Cox and Munk (1954), with skewness
  and peakedness; :func:`cox_munk_parameters` gives their clean-surface fit.

Cox and Munk's normalised slopes are ``xi = z_c / sigma_c`` and ``eta`` the slope
*towards upwind* divided by ``sigma_u``, so ``eta = -z_u / sigma_u`` here. With their
``c03 < 0`` the downwind component ``z_u`` then has skewness ``c03 < 0``: the long tail
is on the steep leeward (downwind-facing) wave faces.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] Cox, C. and Munk, W. (1954). Measurement of the roughness of the sea surface from
   photographs of the sun's glitter. *J. Opt. Soc. Am.* 44(11), 838-850 (eqs 1-4 and
   the clean-surface fit of sec. 6).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import NUMPY
from ..ocean.wind import u12_5_from_u19_5


@dataclass(frozen=True)
class CoxMunkParameters:
    """Gram-Charlier parameters of Cox and Munk (1954) [-]."""

    mss_upwind: float
    mss_crosswind: float
    c21: float
    c03: float
    c40: float = 0.40
    c22: float = 0.12
    c04: float = 0.23


def cox_munk_parameters(u12_5: float) -> CoxMunkParameters:
    """Clean-surface slope statistics of Cox and Munk (1954).

    .. math::
        \\sigma_c^2 = 0.003 + 1.92\\times10^{-3} U, \\quad
        \\sigma_u^2 = 3.16\\times10^{-3} U, \\quad
        c_{21} = 0.01 - 0.0086 U, \\quad c_{03} = 0.04 - 0.033 U \\qquad \\text{(K5)}

    with ``c40 = 0.40``, ``c22 = 0.12``, ``c04 = 0.23``.

    Parameters
    ----------
    u12_5 : float
        Wind speed 12.5 m above the sea [m/s] (Cox and Munk's anemometer height).

    Returns
    -------
    CoxMunkParameters

    References
    ----------
    .. [1] Cox and Munk (1954), sec. 6 (clean surface).
    """
    if not 0.0 <= u12_5 <= 30.0:
        raise ValueError(f"u12_5 = {u12_5} m/s: Cox-Munk fit defined for 0..30 m/s "
                         "(measured 1-14 m/s)")
    # Eq K5: clean-surface regressions.
    return CoxMunkParameters(
        mss_upwind=3.16e-3 * u12_5,
        mss_crosswind=0.003 + 1.92e-3 * u12_5,
        c21=0.01 - 0.0086 * u12_5,
        c03=0.04 - 0.033 * u12_5,
    )


def gaussian_log_pdf(z_u: ArrayLike, z_c: ArrayLike, mss_upwind: ArrayLike,
                     mss_crosswind: ArrayLike, *, xp=None) -> NDArray:
    """Natural log of :func:`gaussian_slope_pdf` (eq K3; finite for any slope).

    ``xp``: array namespace of the arguments (:mod:`seaecho.backend`), numpy by default;
    the facet kernels call this same formula on Dr.Jit arrays.
    """
    if xp is None:
        xp = NUMPY
        z_u, z_c, mss_upwind, mss_crosswind = (np.asarray(a, dtype=float) for a in
                                               (z_u, z_c, mss_upwind, mss_crosswind))
    su2, sc2 = mss_upwind, mss_crosswind
    # Eq K3
    return -0.5 * (z_u * z_u / su2 + z_c * z_c / sc2) - math.log(2.0 * math.pi) - 0.5 * xp.log(
        su2 * sc2)


def gaussian_slope_pdf(z_u: ArrayLike, z_c: ArrayLike, mss_upwind: ArrayLike,
                       mss_crosswind: ArrayLike) -> NDArray:
    """Anisotropic Gaussian slope density [-].

    .. math::
        P(z_u, z_c) = \\frac{1}{2\\pi\\sigma_u\\sigma_c}
        \\exp\\left(-\\frac{z_u^2}{2\\sigma_u^2} - \\frac{z_c^2}{2\\sigma_c^2}\\right)
        \\qquad \\text{(K3)}

    Parameters
    ----------
    z_u, z_c : array_like
        Upwind (downwind-positive) and crosswind slopes [-].
    mss_upwind, mss_crosswind : array_like
        Mean square slopes ``sigma_u^2``, ``sigma_c^2`` [-], > 0.

    Returns
    -------
    ndarray
        Probability density per unit slope area [-].

    References
    ----------
    .. [1] Cox and Munk (1954), eq 1 (first term of the series).
    """
    return np.exp(gaussian_log_pdf(z_u, z_c, mss_upwind, mss_crosswind))


def cox_munk_factor(z_u: ArrayLike, z_c: ArrayLike, p: CoxMunkParameters, *,
                    xp=None) -> NDArray:
    """Gram-Charlier factor of Cox and Munk's density (>= 0, clipped).

    .. math::
        F = 1 - \\tfrac12 c_{21}(\\xi^2 - 1)\\eta - \\tfrac16 c_{03}(\\eta^3 - 3\\eta)
        + \\tfrac1{24}c_{40}(\\xi^4 - 6\\xi^2 + 3)
        + \\tfrac14 c_{22}(\\xi^2-1)(\\eta^2-1) + \\tfrac1{24}c_{04}(\\eta^4 - 6\\eta^2 + 3)
        \\qquad \\text{(K4)}

    The truncated series can dip below zero at large slopes; there it is set to 0 (the
    density then integrates to 1 within 1e-3 for the clean-surface fit up to 14 m/s).

    References
    ----------
    .. [1] Cox and Munk (1954), eq 2.

    ``xp``: array namespace of ``z_u``, ``z_c`` (:mod:`seaecho.backend`), numpy by
    default; the facet kernels call this same formula on Dr.Jit arrays.
    """
    if xp is None:
        xp = NUMPY
        z_u, z_c = np.asarray(z_u, dtype=float), np.asarray(z_c, dtype=float)
    xi = z_c / math.sqrt(p.mss_crosswind)
    eta = -z_u / math.sqrt(p.mss_upwind)
    xi2 = xi * xi
    eta2 = eta * eta
    # Eq K4.
    f = (1.0 - 0.5 * p.c21 * (xi2 - 1.0) * eta - p.c03 / 6.0 * (eta2 * eta - 3.0 * eta)
         + p.c40 / 24.0 * (xi2 * xi2 - 6.0 * xi2 + 3.0)
         + 0.25 * p.c22 * (xi2 - 1.0) * (eta2 - 1.0)
         + p.c04 / 24.0 * (eta2 * eta2 - 6.0 * eta2 + 3.0))
    return xp.maximum(f, 0.0)


def cox_munk_pdf(z_u: ArrayLike, z_c: ArrayLike, p: CoxMunkParameters) -> NDArray:
    """Cox and Munk (1954) Gram-Charlier slope density [-] (eqs K3 x K4).

    Parameters
    ----------
    z_u, z_c : array_like
        Upwind (downwind-positive) and crosswind slopes [-].
    p : CoxMunkParameters
        Variances and series coefficients (:func:`cox_munk_parameters`).

    Returns
    -------
    ndarray
        Probability density per unit slope area [-].

    References
    ----------
    .. [1] Cox and Munk (1954), eqs 1-2.
    """
    return gaussian_slope_pdf(z_u, z_c, p.mss_upwind, p.mss_crosswind) * cox_munk_factor(
        z_u, z_c, p)


__all__ = [
    "CoxMunkParameters",
    "cox_munk_factor",
    "cox_munk_parameters",
    "cox_munk_pdf",
    "gaussian_log_pdf",
    "gaussian_slope_pdf",
    "u12_5_from_u19_5",
]
