"""Romeiser, Alpers & Wismann (1997) wave spectrum ("RAW97"), tuned on radar data.

Romeiser et al. built a composite-surface (two-scale) radar model and fitted the short-wave
part of its wave spectrum so that the model reproduces the scatterometer measurements of
the ocean from L to Ka band, in VV and HH, at 20-60 deg incidence and 1-20 m/s (the
HH/VV data of the SASS, ERS and airborne campaigns they list). The Elfouhaily et al.
(1997) spectrum has its short-wave peak at ``k_m = 370 rad/m`` and is flat in saturation
between the C- and X-band Bragg wavenumbers (110-390 rad/m); RAW97's saturation falls by
3-7 dB over that range, which is what the X-band clutter tables (Nathanson 1991, GIT,
NRL) ask of a Bragg model whose C-band VV matches CMOD5.N (docs/scattering.md, "X-band
VV: the short-wave spectrum").

Omnidirectional spectrum (their eqs 38-42; ``S_1d`` with ``int S_1d dk = <z^2>``, U10
[m/s] in units of 1 m/s):

.. math::

    S_{1d}(k) = \\frac{a_0}{k^3}\\,P_L(k)\\,U_{10}^{\\beta(k)}\\,W_H(k)                   (R1)

    P_L = \\exp\\left[-\\left(\\frac{k_p}{k}\\right)^2 + 0.53
          \\exp\\left(-\\frac{(\\sqrt k - \\sqrt{k_p})^2}{0.32 k_p}\\right)\\right],\\quad
    k_p = \\frac{g}{\\sqrt 2\\, U_{10}^2}                                             (R2)

    \\beta = \\left(1 - e^{-(k/k_1)^2}\\right) e^{-k/k_2}
           + \\left(1 - e^{-k/k_3}\\right) e^{-((k - k_4)/k_5)^2}                      (R3)

    W_H = \\frac{\\sqrt{1 + (k/k_6)^{7.2}}}{(1 + (k/k_7)^{2.2})(1 + (k/k_8)^{3.2})^2}
          e^{-(k/k_9)^2}                                                             (R4)

``a_0 = 1.95e-3``; ``k_1..k_9`` = 183, 3333, 33, 140, 220, 280, 75, 1300, 8885 rad/m.
Spreading (their eqs 43-44), a Gaussian about the wind direction, normalised here to a
unit integral over ``(-pi, pi]``:

.. math::

    D(k, \\psi) = \\frac{1}{N} \\exp\\left(-\\frac{\\psi^2}{2\\delta^2}\\right),\\quad
    \\frac{1}{2\\delta^2} = 0.14 + 0.5\\left(1 - e^{-k U_{10}/c_1}\\right)
    + 5\\, e^{2.5 - 2.6 \\ln U_{10} - 1.3 \\ln k},\\ c_1 = 400\\ \\mathrm{rad/s}  (R5)

Symbols -> names: U10 -> ``u10`` [m/s], k -> ``k`` [rad/m], beta -> ``wind_exponent``,
P_L -> ``_long_wave_factor``, W_H -> ``_short_wave_shape``.

References
----------
.. [1] Romeiser, R., Alpers, W. and Wismann, V. (1997). An improved composite surface model
   for the radar backscattering cross section of the ocean surface, 1. Theory of the model
   and optimization/validation by scatterometer data. *J. Geophys. Res.* 102(C11),
   25237-25250, doi:10.1029/97JC00190 (eqs 38-44).
.. [2] The same formulas in the OceanSAR simulator (Lopez-Dekker et al., TU Delft /
   DLR), ``spec/romeiser97.py`` and ``spread/romeiser97.py``, an independent
   implementation that was used to check the coefficients (its spreading is normalised
   over the real line; here over (-pi, pi], which differs for the broad spreads of long
   waves only).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import erf

from ..constants import G
from .registry import K_FLOOR, register_spectrum, register_spreading
from .wind import u10_from_u19_5

#: Level of the RAW97 spectrum a_0 [-] (eq 39).
RAW97_A0 = 1.95e-3
#: Wavenumbers of the wind exponent beta(k), k_1..k_5 [rad/m] (eq 41).
RAW97_K_BETA = (183.0, 3333.0, 33.0, 140.0, 220.0)
#: Wavenumbers of the short-wave shape W_H(k), k_6..k_9 [rad/m] (eq 42).
RAW97_K_SHAPE = (280.0, 75.0, 1300.0, 8885.0)
#: Constant c_1 of the spreading width [rad/s] (eq 44; k U10 / c_1 is dimensionless).
RAW97_C1 = 400.0


def wind_exponent(k: ArrayLike) -> NDArray[np.float64]:
    """Exponent beta(k) of the wind speed in RAW97's spectrum [-] (eq 41, eq R3).

    ``S_1d ~ U10^beta``: 0 for long waves (a saturated equilibrium range), largest near
    216 rad/m (1.59), 1.17-1.32 at the X-band Bragg waves (338-384 rad/m), falling again
    in the capillary range.
    """
    k = np.asarray(k, dtype=np.float64)
    k1, k2, k3, k4, k5 = RAW97_K_BETA
    return ((1.0 - np.exp(-((k / k1) ** 2))) * np.exp(-k / k2)
            + (1.0 - np.exp(-k / k3)) * np.exp(-(((k - k4) / k5) ** 2)))  # Eq. 41


def _long_wave_factor(k: NDArray[np.float64], u10: float) -> NDArray[np.float64]:
    """P_L(k): the low-wavenumber roll-off and JONSWAP-like peak of RAW97 [-] (eqs 38-39)."""
    k_p = G / (np.sqrt(2.0) * u10**2)  # Eq. 38: peak of a fully developed sea
    return np.exp(-((k_p / k) ** 2)
                  + 0.53 * np.exp(-((np.sqrt(k) - np.sqrt(k_p)) ** 2) / (0.32 * k_p)))  # Eq. 39


def _short_wave_shape(k: NDArray[np.float64]) -> NDArray[np.float64]:
    """W_H(k): the shape of RAW97's short-wave saturation [-] (eq 42)."""
    k6, k7, k8, k9 = RAW97_K_SHAPE
    return (np.sqrt(1.0 + (k / k6) ** 7.2)
            / ((1.0 + (k / k7) ** 2.2) * (1.0 + (k / k8) ** 3.2) ** 2)
            * np.exp(-((k / k9) ** 2)))  # Eq. 42


@register_spectrum("romeiser")
def romeiser(k: ArrayLike, u19_5: float, fetch: float | None = None) -> NDArray[np.float64]:
    """Romeiser, Alpers & Wismann (1997) omnidirectional spectrum (eqs 38-42, eq R1).

    Parameters
    ----------
    k : array_like
        Wavenumber K [rad/m] (values <= 0 give 0).
    u19_5 : float
        Wind speed at 19.5 m [m/s] (U10 from :func:`seaecho.ocean.wind.u10_from_u19_5`).
    fetch : None
        Unused: RAW97 describes a fully developed sea (peak at ``g / (sqrt 2 U10^2)``).

    Returns
    -------
    ndarray
        S_1d [m^3]; the saturation ``k^3 S_1d`` at the X-band Bragg wavenumber 384 rad/m
        is 1.6e-3 at U10 = 7 m/s and 3.2e-3 at 12.5 m/s (Elfouhaily et al.: 6.8e-3 and
        1.7e-2).

    References
    ----------
    Romeiser, Alpers & Wismann (1997), eqs 38-42.
    """
    u10 = float(u10_from_u19_5(u19_5))
    k = np.asarray(k, dtype=np.float64)
    pos = k > K_FLOOR
    ks = np.where(pos, k, 1.0)
    saturation = (RAW97_A0 * _long_wave_factor(ks, u10) * u10 ** wind_exponent(ks)
                  * _short_wave_shape(ks))  # Eq. R1 times k^3
    return np.where(pos, saturation / ks**3, 0.0)


def spreading_width(k: ArrayLike, u10: float) -> NDArray[np.float64]:
    """``1 / (2 delta^2)`` of RAW97's Gaussian spreading [1/rad^2] (eq 44, eq R5)."""
    ks = np.maximum(np.asarray(k, dtype=np.float64), K_FLOOR)
    return (0.14 + 0.5 * (1.0 - np.exp(-ks * u10 / RAW97_C1))
            + 5.0 * np.exp(2.5 - 2.6 * np.log(u10) - 1.3 * np.log(ks)))  # Eq. 44


@register_spreading("romeiser")
def romeiser_spreading(
    k: ArrayLike, psi: ArrayLike, u19_5: float, fetch: float | None = None, s: float = 1.0
) -> NDArray[np.float64]:
    """RAW97 spreading ``exp(-psi^2 / (2 delta^2)) / N`` (eqs 43-44, eq R5) [1/rad].

    Peaked on waves travelling with the wind (not centro-symmetric; the height spectrum of
    the frozen surface symmetrises it). ``N = sqrt(pi / a) erf(pi sqrt a)``,
    ``a = 1 / (2 delta^2)``, makes the integral over ``psi`` in ``(-pi, pi]`` exactly 1.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    psi : array_like
        Angle between wave travel and wind directions [rad] (wrapped to (-pi, pi]).
    u19_5 : float
        Wind speed at 19.5 m [m/s].
    fetch, s
        Unused.
    """
    u10 = float(u10_from_u19_5(u19_5))
    a = spreading_width(k, u10)
    psi = np.angle(np.exp(1j * np.asarray(psi, dtype=np.float64)))  # wrap to (-pi, pi]
    norm = np.sqrt(np.pi / a) * erf(np.pi * np.sqrt(a))
    return np.exp(-a * psi**2) / norm  # Eq. 43


__all__ = ["RAW97_A0", "romeiser", "romeiser_spreading", "spreading_width", "wind_exponent"]
