"""Short-wave spectrum of Kudryavtsev et al. from the energy balance ("KHCC03").

Kudryavtsev, Makin & Chapron (1999) and Kudryavtsev, Hauser, Caudal & Chapron (2003,
"KHCC03", part 1, sec. 3) derive the saturation spectrum of the short wind waves
(wavelengths from millimetres to metres) from the balance of the wind input, a
dissipation whose exponent ``n(k)`` goes from ``n_g = 5`` for gravity waves to 1 for
capillary waves, and the generation of parasitic capillaries on the crests of steep short
gravity waves. Below ``k_gamma`` the spectrum is ``a (beta_nu / C_beta_mean)^(1/n)``:
it grows with the wind as ``u*^(2/n)`` (0.4 for gravity waves, 2 for gravity-capillary
waves) and follows the growth rate's fall with ``k`` instead of Elfouhaily et al.'s
(1997) short-wave peak at ``k_m = 370 rad/m``. seaecho uses the breaking statistics of
the same model (:mod:`seaecho.scattering.breaking`), whose growth rate and dissipation
exponent are defined here.

Directional saturation ``B(k, phi)`` (``phi`` the direction of travel relative to the
wind; ``int B dphi`` is the omnidirectional saturation ``k^3 S_1d``), energy balance and
its solution (KHCC03 eqs 13 and 17):

.. math::

    \\beta_\\nu B - B\\left(\\frac{B}{\\alpha}\\right)^{n} + I_{pc} = 0,\\qquad
    B_{sw} = \\alpha\\left[\\frac{\\beta_\\nu + \\sqrt{\\beta_\\nu^2 + 4 I_{pc}/\\alpha}}{2}
    \\right]^{1/n}                                                           (KU1)

(exact for ``n = 1``, where the parasitic capillaries live), with the effective growth
rate and the wind growth rate (KHCC03 eqs 19-21; K05 eq 17, the angular form
``cos phi |cos phi|``):

.. math::

    \\beta_\\nu = \\beta - \\frac{4\\nu k^2}{\\omega}                              (KU2)

    \\beta = C_\\beta \\left(\\frac{u_*}{c}\\right)^2 \\cos\\varphi|\\cos\\varphi|,\\quad
    C_\\beta = 1.5\\frac{\\rho_a}{\\rho_w}\\left(\\frac{1}{\\kappa}\\ln\\frac{\\pi}{k z_0}
    - \\frac{c}{u_*}\\right)_+                                                 (KU3)

    z_0 = 0.018\\frac{u_*^2}{g} + 0.1\\frac{\\nu_a}{u_*}                         (KU4)

the exponent of the dissipation and its tuning function (KHCC03 eqs 22-25), and the
constant ``alpha`` (KHCC03 eq 26):

.. math::

    \\frac{1}{n} = \\left(1 - \\frac{1}{n_g}\\right) f(k/k_b) + \\frac{1}{n_g},\\quad
    n_g = 5                                                                  (KU5)

    f(x) = \\frac{1 + \\tanh(2 \\ln x)}{2},\\quad k_b = k_\\gamma / 4             (KU6)

    \\ln\\alpha = \\ln a - \\frac{\\ln \\bar C_\\beta}{n},\\quad a = 2.5\\times10^{-3},\\
    \\bar C_\\beta = 0.03                                                       (KU7)

and the source of parasitic capillaries: the energy that the short gravity waves of
wavenumber ``k_g = k_gamma^2 / k`` (KHCC03 eq 14) lose, in their equilibrium
``B_w = alpha beta_nu^(1/n)`` (K05 eq 24), goes to the capillaries at ``k`` (KHCC03 eqs
15-16), within a band set by the filter ``phi_pc``:

.. math::

    I_{pc}(k, \\varphi) = \\phi_{pc}(k)\\,\\left[\\beta_\\nu B_w\\right]_{k_g},\\quad
    B_w = \\alpha\\,(\\beta_\\nu)_+^{1/n}                                         (KU8)

    \\phi_{pc}(k) = f(k/k_l) - f(k/k_h),\\quad k_l = \\tfrac32 k_\\gamma,\\
    k_h = k_\\gamma^2 / k_b = 4 k_\\gamma                                        (KU9)

The long waves are Elfouhaily et al.'s (1997), as KHCC03 take them, and the short-wave
spectrum is switched on above the spectral peak by the complement of Elfouhaily's
long-wave cut-off (KHCC03 eq 30):

.. math::

    k^3 S_{1d} = B_l + (1 - F_c)\\int_{-\\pi}^{\\pi} B_{sw}\\, d\\varphi,\\quad
    F_c = \\exp\\left[-\\frac{\\Omega_c}{\\sqrt{10}}
    \\left(\\sqrt{k/k_p} - 1\\right)_+\\right]                                   (KU10)

(``B_l`` and ``Omega_c``, ``k_p`` from :func:`seaecho.ocean.spectra.elfouhaily_parameters`;
the registered spectrum, :func:`seaecho.ocean.spectra.kudryavtsev`, puts them together).
``u_*`` is Wu's (1982) law (``"wu-1982"`` of :mod:`seaecho.ocean.wind`, the drag law of
KHCC03 and K05), ``c`` and ``omega`` the dispersion relation with capillarity
(:mod:`seaecho.ocean.dispersion`), ``k_gamma = sqrt(g / tau)`` its minimum phase speed
wavenumber, ``nu`` the viscosity of sea water, ``rho_a``, ``rho_w``, ``nu_a`` and
``kappa = 0.41`` those of :mod:`seaecho.constants` (KHCC03 round kappa to 0.4).

Symbols -> names: B_sw -> :func:`short_wave_saturation`, beta -> :func:`wind_growth_rate`,
beta_nu -> :func:`net_growth_rate`, n -> :func:`dissipation_exponent`, f ->
:func:`transition_function`, alpha -> :func:`saturation_constant`, phi_pc ->
:func:`parasitic_filter`, ``int B_sw dphi`` -> :func:`short_wave_omni_saturation`,
``k^3 S_1d`` -> :func:`total_saturation`,
a -> :data:`A_SATURATION`, C_beta_mean -> :data:`MEAN_C_BETA`, n_g -> :data:`N_GRAVITY`.

**Sources read.** The papers' text was not readable here. The equations are those quoted,
with KHCC03's equation numbers, by two independent open implementations and one open
text, which agree on them: the Fortran ocean emissivity model of Dinnat et al. (NASA
GSFC; ``Ocean/Sea_Spectrum/spectrum_Kudryavtsev.f``, eqs 14, 17, 19-22, 26, 30, with
``a = 2.5e-3``, ``n_g = 5``, ``C_beta_mean = 0.03``, ``c_beta`` from ``1.5 rho_a /
rho_w`` and eq 21's roughness; KHCC03's third author is one of that model's authors);
stereoid (TU Delft / ESA; ``stereoid/oceans/waves/wave_spectra.py``, eqs 19-28 of
KHCC03 and eqs 17 and 24-26 of K05); and the appendix of an open book on ocean emission
models restating Kudryavtsev et al. (1999, 2003, 2005) and Yurovskaya et al. (2013), which
gives eqs KU5-KU7 and KU9 in the form above. No code was copied.

**Where the sources differ** (what was chosen and what it does, docs/ocean.md):

* The angular form of ``beta``: ``cos phi |cos phi|`` (K05 eq 17, stereoid, and the
  breaking model of seaecho) or ``exp(-phi^2)`` times the downwind net rate, viscous loss
  included (Dinnat's transcription of KHCC03 eq 20). The first is the spectrum's; the
  second is available as ``angular="gaussian"`` to measure the difference (a larger
  omnidirectional saturation, most where the viscous loss nearly cancels the wind input:
  ``examples/xband_spectrum_comparison.py``).
* The tuning functions: Dinnat's code reads ``f`` and ``phi_pc`` from tables, not from
  formulas, whose ``f`` is 0.5 at 0.41 ``k_gamma`` (not 0.25) and whose ``phi_pc`` falls
  at 10 ``k_gamma`` (not 4). The analytic forms KU6 and KU9 are those of the open text
  (K05, Yurovskaya et al.) and of stereoid.
* The generation of short waves by the breaking of longer ones (K05's source ``Q_wb``,
  near their eqs 20 and 29 as stereoid cites them, which fills the cross-wind directions
  and is solved by iteration from K05 eqs 24-26) is **not implemented**: the readable
  sources weight its integral by ``omega`` (the open text) or by ``c`` (stereoid), and
  give its constant as 1.2e-2 (K05, stereoid), 2.7e-2 (Kudryavtsev et al. 2014) or
  4.5e-3 (Yurovskaya et al. 2013, with another growth rate); which of these K05 prints
  could not be checked. Without it the spectrum is KHCC03's, which (the open text notes)
  has a gap in the cross-wind gravity-capillary range that K05 filled.

References
----------
.. [1] Kudryavtsev, V. N., Makin, V. K. and Chapron, B. (1999). Coupled sea surface -
   atmosphere model. 2. Spectrum of short wind waves. *J. Geophys. Res.* 104(C4),
   7625-7639.
.. [2] Kudryavtsev, V., Hauser, D., Caudal, G. and Chapron, B. (2003). A semiempirical
   model of the normalized radar cross-section of the sea surface, 1. Background model.
   *J. Geophys. Res.* 108(C3), 8054, doi:10.1029/2001JC001003 (sec. 3, eqs 13-30).
.. [3] Kudryavtsev, V., Akimov, D., Johannessen, J. and Chapron, B. (2005). On radar
   imaging of current features: 1. Model and comparison with observations. *J. Geophys.
   Res.* 110, C07016, doi:10.1029/2004JC002505 (eqs 17, 24-26).
.. [4] Yurovskaya, M. V., Dulov, V. A., Chapron, B. and Kudryavtsev, V. N. (2013).
   Directional short wind wave spectra derived from the sea surface photography.
   *J. Geophys. Res. Oceans* 118, 4380-4394 (appendix A).
.. [5] Elfouhaily, T., Chapron, B., Katsaros, K. and Vandemark, D. (1997). A unified
   directional spectrum for long and short wind-driven waves. *J. Geophys. Res.*
   102(C7), 15781-15796.
.. [6] Implementations read: Dinnat, E. et al., ocean emissivity model
   (github.com/edinnat/Ocean-reference-model-mirror, ``Ocean/Sea_Spectrum/
   spectrum_Kudryavtsev.f`` and ``Radar/NRCS.f``); Kleinherenbrink, M., Lopez-Dekker, P.
   et al., stereoid (``stereoid/oceans/waves/wave_spectra.py``,
   ``stereoid/oceans/forward_models/RIM_constants.py``).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import NU_SEA_WATER, RHO_AIR, RHO_SEA_WATER, VON_KARMAN
from .dispersion import CAPILLARY_WAVENUMBER, angular_frequency, phase_speed
from .registry import K_FLOOR
from .wind import charnock_roughness_length, friction_velocity

#: Saturation level a [-] of the equilibrium range (KHCC03 eq 26, eq KU7).
A_SATURATION = 2.5e-3
#: Mean growth-rate constant C_beta over the transition interval [-] (KHCC03 eq 26, KU7).
MEAN_C_BETA = 0.03
#: Exponent n of the dissipation for gravity waves n_g [-] (KHCC03, eq KU5).
N_GRAVITY = 5.0
#: Centre of the gravity-to-capillary transition k_b = k_gamma / 4 [rad/m] (eq KU6).
K_TRANSITION = 0.25 * CAPILLARY_WAVENUMBER
#: Band of the parasitic capillaries k_l = 1.5 k_gamma, k_h = k_gamma^2 / k_b [rad/m] (KU9).
K_PC_LOW = 1.5 * CAPILLARY_WAVENUMBER
K_PC_HIGH = CAPILLARY_WAVENUMBER**2 / K_TRANSITION
#: The friction-velocity law of KHCC03 and K05 (:data:`seaecho.ocean.wind.
#: FRICTION_VELOCITY_LAWS`): Wu (1982).
FRICTION_LAW = "wu-1982"

#: Wavenumber table of the omnidirectional short-wave saturation [rad/m]: 200 points per
#: decade from 1e-3 to 1e5 rad/m (linear interpolation in ln k; 0 outside).
_K_TABLE = np.logspace(-3.0, 5.0, 1601)
#: Directions of the quadrature over half the circle [rad] (trapezoid rule; B_sw is even
#: in phi).
_PHI_TABLE = np.linspace(0.0, np.pi, 513)
#: Angular forms of the net growth rate: ``"cos"``, ``beta = beta(k, 0) cos phi |cos phi|``
#: less the viscous loss (K05 eq 17, the form seaecho's breaking model uses, the
#: default); ``"gaussian"``, ``exp(-phi^2)`` times the downwind net rate ``beta(k, 0) - 4 nu
#: k^2 / omega`` (KHCC03 eq 20 as Dinnat et al.'s code has it, which also scales the viscous
#: loss).
ANGULAR_FORMS = ("cos", "gaussian")


def wind_growth_rate(k: ArrayLike, phi: ArrayLike, u10: float) -> NDArray[np.float64]:
    """Wind growth rate ``beta`` of waves of wavenumber ``k`` travelling at ``phi`` [-].

    ``beta = C_beta (u_*/c)^2 cos(phi) |cos(phi)|`` with ``C_beta`` of eq KU3 clipped at 0
    (waves faster than the wind do not grow); the energy growth rate is ``beta omega``.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    phi : array_like
        Direction of travel relative to the direction the wind blows towards [rad].
    u10 : float
        Wind speed at 10 m [m/s].

    References
    ----------
    .. [1] K05 eq 17; KHCC03 eqs 19-21 (eqs KU3-KU4).
    """
    k = np.asarray(k, dtype=float)
    us = float(friction_velocity(FRICTION_LAW, u10))
    z0 = float(charnock_roughness_length(us))  # Eq. KU4
    c = phase_speed(k)
    # Eq. KU3: C_beta and beta.
    c_beta = 1.5 * (RHO_AIR / RHO_SEA_WATER) * (np.log(np.pi / (k * z0)) / VON_KARMAN - c / us)
    cp = np.cos(np.asarray(phi, dtype=float))
    return np.maximum(c_beta, 0.0) * (us / c) ** 2 * cp * np.abs(cp)


def transition_function(x: ArrayLike) -> NDArray[np.float64]:
    """``f(x) = (1 + tanh(2 ln x)) / 2`` [-]: 0 for ``x << 1``, 1 for ``x >> 1`` (eq KU6)."""
    return 0.5 * (1.0 + np.tanh(2.0 * np.log(np.asarray(x, dtype=float))))


def dissipation_exponent(k: ArrayLike) -> NDArray[np.float64]:
    """Exponent ``n(k)`` of the KHCC03 dissipation term [-]: ``n_g = 5`` for gravity waves.

    ``1/n = (1 - 1/n_g) f(k / k_b) + 1/n_g``, ``k_b = k_gamma / 4``,
    ``k_gamma = sqrt(g / tau)`` (KHCC03 eqs 22-25, eqs KU5-KU6; n -> 1 for capillary
    waves). The wind exponent of the equilibrium spectrum is ``2 / n``.
    """
    f = transition_function(np.asarray(k, dtype=float) / K_TRANSITION)  # Eq. KU6
    return 1.0 / ((1.0 - 1.0 / N_GRAVITY) * f + 1.0 / N_GRAVITY)  # Eq. KU5


def saturation_constant(k: ArrayLike) -> NDArray[np.float64]:
    """``alpha(k) = a / C_beta_mean^(1/n(k))`` [-] (KHCC03 eq 26, eq KU7).

    So that the equilibrium spectrum ``alpha beta_nu^(1/n)`` is ``a`` wherever the
    growth rate equals its mean ``C_beta_mean``, whatever ``n``.
    """
    n = dissipation_exponent(k)
    return np.exp(np.log(A_SATURATION) - np.log(MEAN_C_BETA) / n)  # Eq. KU7


def net_growth_rate(
    k: ArrayLike, phi: ArrayLike, u10: float, angular: str = "cos"
) -> NDArray[np.float64]:
    """``beta_nu = beta - 4 nu k^2 / omega`` [-]: wind growth less viscous loss (eq KU2).

    The viscous damping rate of a free surface wave, ``4 nu k^2`` (Lamb 1932, art. 348),
    over ``omega`` of the dispersion relation; ``nu`` the kinematic viscosity of sea water
    (KHCC03, after their eq 13). ``angular = "gaussian"`` gives instead ``exp(-phi^2)``
    times the downwind value (:data:`ANGULAR_FORMS`).

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    phi : array_like
        Direction of travel relative to the wind [rad].
    u10 : float
        Wind speed at 10 m [m/s].
    angular : str
        ``"cos"`` (K05 eq 17, default) or ``"gaussian"`` (Dinnat et al.'s KHCC03 eq 20).
    """
    k = np.asarray(k, dtype=float)
    if angular == "gaussian":
        psi = np.angle(np.exp(1j * np.asarray(phi, dtype=float)))  # wrap to (-pi, pi]
        return np.exp(-(psi**2)) * net_growth_rate(k, 0.0, u10)  # KHCC03 eq 20 (Dinnat)
    if angular != "cos":
        raise ValueError(f"angular = {angular!r}: allowed {ANGULAR_FORMS}")
    omega = angular_frequency(k)
    return wind_growth_rate(k, phi, u10) - 4.0 * NU_SEA_WATER * k**2 / omega  # Eq. KU2


def parasitic_filter(k: ArrayLike) -> NDArray[np.float64]:
    """Band ``phi_pc(k) = f(k / k_l) - f(k / k_h)`` of the parasitic capillaries [-] (KU9).

    ``k_l = 1.5 k_gamma``, ``k_h = k_gamma^2 / k_b = 4 k_gamma``: capillaries from about
    550 to 1500 rad/m (wavelengths 4-11 mm).
    """
    k = np.asarray(k, dtype=float)
    return transition_function(k / K_PC_LOW) - transition_function(k / K_PC_HIGH)  # Eq. KU9


def equilibrium_saturation(
    k: ArrayLike, phi: ArrayLike, u10: float, angular: str = "cos"
) -> NDArray[np.float64]:
    """``B_w = alpha (beta_nu)_+^(1/n)`` [-]: wind input balanced by dissipation (eq KU8).

    The solution of eq KU1 without the parasitic source (K05 eq 24); 0 where the waves
    lose more energy to viscosity (and to an opposing wind) than they gain.
    """
    k = np.asarray(k, dtype=float)
    beta_nu = np.maximum(net_growth_rate(k, phi, u10, angular), 0.0)
    return saturation_constant(k) * beta_nu ** (1.0 / dissipation_exponent(k))  # Eq. KU8


def short_wave_saturation(
    k: ArrayLike, phi: ArrayLike, u10: float, angular: str = "cos"
) -> NDArray[np.float64]:
    """Directional saturation ``B_sw(k, phi)`` of the short waves [1/rad] (eqs KU1, KU8).

    ``int B_sw dphi`` over ``(-pi, pi]`` is the omnidirectional saturation ``k^3 S_1d``
    of the short waves.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m] (> 0).
    phi : array_like
        Direction of travel relative to the direction the wind blows towards [rad].
    u10 : float
        Wind speed at 10 m [m/s].
    angular : str
        Angular form of the net growth rate (:data:`ANGULAR_FORMS`; default ``"cos"``).

    Returns
    -------
    ndarray
        B_sw [1/rad], broadcast of ``k`` and ``phi``.

    References
    ----------
    KHCC03 eqs 13-17 (eq KU1), with the parasitic source of eqs 14-16 (eq KU8).
    """
    k = np.asarray(k, dtype=float)
    phi = np.asarray(phi, dtype=float)
    k_g = CAPILLARY_WAVENUMBER**2 / k  # KHCC03 eq 14: the carrying gravity waves
    beta_g = np.maximum(net_growth_rate(k_g, phi, u10, angular), 0.0)
    i_pc = (parasitic_filter(k) * beta_g
            * equilibrium_saturation(k_g, phi, u10, angular))  # Eq. KU8
    alpha = saturation_constant(k)
    beta_nu = net_growth_rate(k, phi, u10, angular)
    root = 0.5 * (beta_nu + np.sqrt(beta_nu**2 + 4.0 * i_pc / alpha))  # Eq. KU1
    return alpha * np.maximum(root, 0.0) ** (1.0 / dissipation_exponent(k))


@lru_cache(maxsize=32)
def _omni_table(u10: float, angular: str) -> NDArray[np.float64]:
    """``int B_sw dphi`` [-] on :data:`_K_TABLE` (trapezoid over ``[0, pi]``, doubled:
    ``B_sw`` is even in ``phi``)."""
    b = short_wave_saturation(_K_TABLE[:, None], _PHI_TABLE[None, :], u10, angular)
    out = 2.0 * np.trapezoid(b, _PHI_TABLE, axis=1)
    out.setflags(write=False)
    return out


def short_wave_omni_saturation(
    k: ArrayLike, u10: float, angular: str = "cos"
) -> NDArray[np.float64]:
    """Omnidirectional saturation of the short waves ``int B_sw dphi`` [-] (eq KU10).

    Interpolated (linearly in ``ln k``) in a table of 200 points per decade from 1e-3
    to 1e5 rad/m, computed once per wind speed; 0 outside it.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    u10 : float
        Wind speed at 10 m [m/s].
    angular : str
        Angular form of the net growth rate (:data:`ANGULAR_FORMS`; default ``"cos"``).
    """
    k = np.asarray(k, dtype=float)
    table = _omni_table(float(u10), angular)
    lk = np.log(np.maximum(k, K_FLOOR))
    return np.interp(lk, np.log(_K_TABLE), table, left=0.0, right=0.0)


def total_saturation(
    b_long: ArrayLike, cutoff: ArrayLike, b_short: ArrayLike
) -> NDArray[np.float64]:
    """Omnidirectional saturation ``k^3 S_1d`` of the whole spectrum [-] (KHCC03 eq 30, KU10).

    ``B_l + (1 - F_c) int B_sw dphi``: the long waves' curvature ``B_l`` and their cut-off
    ``F_c`` (Elfouhaily et al.'s, :func:`seaecho.ocean.spectra.elfouhaily_long_wave`;
    ``F_c`` is taken as 1 below the peak, where it exceeds 1) and the short waves'
    omnidirectional saturation (:func:`short_wave_omni_saturation`). The registered
    spectrum ``"kudryavtsev"`` is :func:`seaecho.ocean.spectra.kudryavtsev`.

    Parameters
    ----------
    b_long, cutoff, b_short : array_like
        ``B_l`` [-], ``F_c`` [-] and ``int B_sw dphi`` [-] at the same wavenumbers.
    """
    weight = 1.0 - np.minimum(np.asarray(cutoff, dtype=float), 1.0)
    return np.asarray(b_long, dtype=float) + weight * np.asarray(b_short, dtype=float)  # KU10


__all__ = ["ANGULAR_FORMS", "A_SATURATION", "FRICTION_LAW", "K_PC_HIGH", "K_PC_LOW", "K_TRANSITION",
           "MEAN_C_BETA", "N_GRAVITY", "dissipation_exponent", "equilibrium_saturation",
           "net_growth_rate", "parasitic_filter", "saturation_constant",
           "short_wave_omni_saturation", "short_wave_saturation", "total_saturation",
           "transition_function", "wind_growth_rate"]
