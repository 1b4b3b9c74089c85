"""Sea wave spectra: omnidirectional spectra, spreading functions, directional spectrum.

The directional wavenumber spectrum is built as in the paper's eq 4 (with the
normalisation of docs/conventions.md):

.. math::

    \\Psi(K_x, K_y) = \\frac{1}{K} S_{1d}(K)\\, D(K, \\psi)                        (4)

with :math:`\\int_0^\\infty S_{1d}\\,dK = \\langle z^2 \\rangle` and
:math:`\\int_{-\\pi}^{\\pi} D\\, d\\psi = 1`, so that
:math:`\\iint \\Psi\\, dK_x\\, dK_y = \\langle z^2 \\rangle`. :math:`\\psi` is the angle
between the direction the wave travels and the direction the wind blows towards.

Symbols -> names: U19.5 -> ``u19_5`` [m/s], U10 -> ``u10`` [m/s], K -> ``k`` [rad/m],
S_1d -> ``omni`` [m^3], D -> ``spreading`` [1/rad], Psi -> ``__call__`` [m^4].

Omnidirectional spectra (registry :data:`OMNI_SPECTRA`, selectable by name):

- ``"pierson-moskowitz"``: Pierson & Moskowitz (1964) in its standard wavenumber form
  (a0 / 2) K^-3 exp(-b0 g^2 / (K^2 U19.5^4)) (the paper's eq 5 without its missing 1/2).
- ``"jonswap"``: Hasselmann et al. (1973), fetch-limited, converted to wavenumber with the
  deep-water dispersion relation.
- ``"elfouhaily"``: the unified spectrum of Elfouhaily et al. (1997), long and short waves
  including the gravity-capillary range that Bragg scattering sees.
- ``"kudryavtsev"``: Elfouhaily's long waves with the short waves of Kudryavtsev et al.
  (2003) from the energy balance (:mod:`seaecho.ocean.kudryavtsev`).

Spreading functions (registry :data:`SPREADINGS`): ``"longuet-higgins"`` cos^2s(psi/2)
(paper eq 6, normalised to unit integral: N(1) = 1/pi), and ``"elfouhaily"`` (Elfouhaily
et al. 1997).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] W. J. Pierson and L. Moskowitz, "A proposed spectral form for fully developed wind
   seas based on the similarity theory of S. A. Kitaigorodskii", J. Geophys. Res. 69(24),
   5181-5190, 1964.
.. [2] K. Hasselmann et al., "Measurements of wind-wave growth and swell decay during the
   Joint North Sea Wave Project (JONSWAP)", Dtsch. Hydrogr. Z. A8(12), 1973.
.. [3] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified directional
   spectrum for long and short wind-driven waves", J. Geophys. Res. 102(C7),
   15781-15796, 1997.
.. [4] M. S. Longuet-Higgins, D. E. Cartwright and N. D. Smith, "Observations of the
   directional spectrum of sea waves using the motions of a floating buoy", in Ocean Wave
   Spectra, Prentice-Hall, 1963, pp. 111-136.
.. [5] R. H. Stewart, *Introduction to Physical Oceanography*, Texas A&M, 2008, ch. 16
   (JONSWAP parameters). Wind heights are converted by :mod:`seaecho.ocean.wind`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import gammaln

from ..constants import G
from ..warnings import ValidityWarning

# The spectra defined in their own modules register themselves on import.
from . import romeiser as _romeiser  # noqa: F401  (Romeiser et al. 1997)
from .dispersion import CAPILLARY_WAVENUMBER, angular_frequency, phase_speed
from .kudryavtsev import SPECTRUM_ANGULAR, short_wave_omni_saturation, total_saturation
from .registry import (
    K_FLOOR,
    OMNI_SPECTRA,
    SPREADINGS,
    register_spectrum,
    register_spreading,
)
from .wind import OMEGA_C_DEVELOPED, friction_velocity, u10_from_u19_5

#: Pierson-Moskowitz constants (paper eq 5; Pierson & Moskowitz 1964).
PM_A0 = 8.1e-3
PM_B0 = 0.74
#: Wavenumber of the minimum phase speed [rad/m] (Elfouhaily et al.'s k_m = 370 rad/m: the
#: dispersion relation's sqrt(g rho / tau) = 369.8 rad/m) and that speed [m/s] (their c_m).
K_M = CAPILLARY_WAVENUMBER
C_M = 0.23


def _positive(k: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.bool_], NDArray[np.float64]]:
    """k as float array, the mask k > K_FLOOR, and k with the rest replaced by 1."""
    k = np.asarray(k, dtype=np.float64)
    pos = k > K_FLOOR
    return k, pos, np.where(pos, k, 1.0)


# --------------------------------------------------------------------------------------
# Pierson-Moskowitz
# --------------------------------------------------------------------------------------


@register_spectrum("pierson-moskowitz")
def pierson_moskowitz(
    k: ArrayLike, u19_5: float, fetch: float | None = None
) -> NDArray[np.float64]:
    """Pierson-Moskowitz omnidirectional wavenumber spectrum (paper eq 5, corrected).

    .. math::

        S_{1d}(K) = \\frac{a_0}{2} K^{-3} \\exp\\left(-b_0 \\frac{g^2}{K^2 U_{19.5}^4}\\right)

    with a0 = 8.1e-3 and b0 = 0.74. This is Pierson & Moskowitz's frequency spectrum
    alpha g^2 omega^-5 exp(-b0 (g / (U omega))^4) mapped to wavenumber with omega^2 = g K;
    the paper's eq 5 drops the 1/2 of that mapping. Its integral is
    a0 U^4 / (4 b0 g^2), hence H_s = 4 sqrt(<z^2>) = 2 sqrt(a0 / b0) U^2 / g = 0.209 U^2/g.

    Parameters
    ----------
    k : array_like
        Wavenumber K [rad/m] (values <= 0 give 0).
    u19_5 : float
        Wind speed at 19.5 m [m/s].
    fetch : None
        Unused (fully developed sea).

    Returns
    -------
    ndarray
        S_1d [m^3].

    References
    ----------
    Pierson & Moskowitz (1964); paper eq 5 (with the standard 1/2, docs/ocean.md).
    """
    k, pos, ks = _positive(k)
    out = 0.5 * PM_A0 * ks**-3 * np.exp(-PM_B0 * G**2 / (ks**2 * u19_5**4))  # Eq. 5 (x 1/2)
    return np.where(pos, out, 0.0)


def pierson_moskowitz_peak(u19_5: float) -> float:
    """Wavenumber of the maximum of the PM wavenumber spectrum [rad/m]: sqrt(2 b0 / 3) g/U^2."""
    return float(np.sqrt(2.0 * PM_B0 / 3.0) * G / u19_5**2)


# --------------------------------------------------------------------------------------
# JONSWAP
# --------------------------------------------------------------------------------------


def jonswap_parameters(u10: float, fetch: float) -> tuple[float, float]:
    """JONSWAP alpha [-] and peak angular frequency omega_p [rad/s] from U10 and fetch.

    alpha = 0.076 (U10^2 / (F g))^0.22 and omega_p = 22 (g^2 / (U10 F))^(1/3)
    (Hasselmann et al. 1973, as given by Stewart 2008 eqs 16.28-16.29).
    """
    alpha = 0.076 * (u10**2 / (fetch * G)) ** 0.22
    omega_p = 22.0 * (G**2 / (u10 * fetch)) ** (1.0 / 3.0)
    return float(alpha), float(omega_p)


@register_spectrum("jonswap")
def jonswap(k: ArrayLike, u19_5: float, fetch: float | None = None) -> NDArray[np.float64]:
    """JONSWAP fetch-limited omnidirectional wavenumber spectrum.

    .. math::

        S(\\omega) = \\frac{\\alpha g^2}{\\omega^5}
        \\exp\\left[-\\frac54 \\left(\\frac{\\omega_p}{\\omega}\\right)^4\\right]
        \\gamma^{r},\\quad
        r = \\exp\\left[-\\frac{(\\omega-\\omega_p)^2}{2\\sigma^2\\omega_p^2}\\right]

    with gamma = 3.3, sigma = 0.07 (omega <= omega_p) or 0.09, alpha and omega_p from
    :func:`jonswap_parameters`; mapped to wavenumber with the deep-water relation
    omega = sqrt(g K): S_1d(K) = S(omega) d omega / dK = S(omega) g / (2 omega).

    Parameters
    ----------
    k : array_like
        Wavenumber K [rad/m].
    u19_5 : float
        Wind speed at 19.5 m [m/s] (U10 from :func:`seaecho.ocean.wind.u10_from_u19_5`).
    fetch : float
        Fetch F [m] (required).

    Returns
    -------
    ndarray
        S_1d [m^3].

    References
    ----------
    Hasselmann et al. (1973); Stewart (2008) eqs 16.27-16.30.
    """
    if fetch is None:
        raise ValueError("fetch = None: the JONSWAP spectrum needs a fetch [m]")
    u10 = float(u10_from_u19_5(u19_5))
    alpha, omega_p = jonswap_parameters(u10, fetch)
    k, pos, ks = _positive(k)
    omega = angular_frequency(ks, surface_tension=0.0)  # JONSWAP's gravity-wave relation
    sigma = np.where(omega <= omega_p, 0.07, 0.09)
    r = np.exp(-((omega - omega_p) ** 2) / (2.0 * sigma**2 * omega_p**2))
    s_omega = alpha * G**2 * omega**-5 * np.exp(-1.25 * (omega_p / omega) ** 4) * 3.3**r
    out = s_omega * G / (2.0 * omega)  # S(K) = S(omega) d omega / dK
    return np.where(pos, out, 0.0)


# --------------------------------------------------------------------------------------
# Elfouhaily et al. (1997)
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ElfouhailyParameters:
    """Wind-dependent parameters of the Elfouhaily et al. (1997) spectrum (SI)."""

    u10: float  #: wind speed at 10 m [m/s]
    omega_c: float  #: inverse wave age U10 / c_p [-]
    k_p: float  #: peak wavenumber [rad/m] (eq 3: k_p = k_0 Omega_c^2)
    c_p: float  #: phase speed at the peak [m/s]
    u_star: float  #: friction velocity [m/s]
    alpha_p: float  #: long-wave generalised Phillips-Kitaigorodskii parameter
    alpha_m: float  #: short-wave generalised Phillips-Kitaigorodskii parameter
    gamma: float  #: peak enhancement factor (eq 3)
    delta: float  #: peak width (eq 3)


def elfouhaily_parameters(u19_5: float, fetch: float | None = None) -> ElfouhailyParameters:
    """Parameters of the Elfouhaily unified spectrum for a wind and a fetch.

    Inverse wave age Omega_c = 0.84 tanh[(X / X0)^0.4]^-0.75 with X = g F / U10^2,
    X0 = 2.2e4, 0.84 for a fully developed sea (fetch None). Peak wavenumber
    k_p = g Omega_c^2 / U10^2; gamma = 1.7 (Omega_c < 1) or 1.7 + 6 ln Omega_c, and
    delta = 0.08 (1 + 4 Omega_c^-3) (eq 3); alpha_p = 6e-3 Omega_c^0.55; friction velocity
    by the wave-age dependent law ``"donelan-1993"`` of :mod:`seaecho.ocean.wind`, the one
    Elfouhaily et al. use (other implementations take u* = sqrt(1.44e-3) U10, 4 %
    lower at 10 m/s); alpha_m = 1e-2 (1 + ln(u*/c_m)) for u* < c_m, else
    1e-2 (1 + 3 ln(u*/c_m)), floored at 0 with a :class:`~seaecho.warnings.ValidityWarning`
    for very light winds where it goes negative. Equation numbers other than 2-3 are not
    given: we could not check them against the paper's text.
    """
    u10 = float(u10_from_u19_5(u19_5))
    if fetch is None:
        omega_c = OMEGA_C_DEVELOPED  # fully developed (fetch law for X -> infinity)
    else:
        x = G * fetch / u10**2
        omega_c = 0.84 * np.tanh((x / 2.2e4) ** 0.4) ** -0.75  # fetch law
    k_p = G * omega_c**2 / u10**2  # k_0 Omega_c^2, k_0 = g / U10^2
    c_p = u10 / omega_c  # phase speed at the peak (definition of Omega_c = U10 / c_p)
    gamma = 1.7 if omega_c < 1.0 else 1.7 + 6.0 * np.log(omega_c)  # Eq. 3
    delta = 0.08 * (1.0 + 4.0 * omega_c**-3)  # Eq. 3
    alpha_p = 6e-3 * omega_c**0.55  # long-wave Phillips-Kitaigorodskii parameter
    u_star = float(friction_velocity("donelan-1993", u10, omega_c))  # wave-age roughness
    if u_star < C_M:
        alpha_m = 1e-2 * (1.0 + np.log(u_star / C_M))  # short-wave parameter
    else:
        alpha_m = 1e-2 * (1.0 + 3.0 * np.log(u_star / C_M))
    if alpha_m < 0:
        # alpha_m turns negative for u* < c_m / e (U10 below about 2 m/s): outside the
        # winds the spectrum was fitted to; no short-wave (capillary) part is left
        warnings.warn(
            f"Elfouhaily spectrum at U10 = {u10:.2f} m/s: friction velocity {u_star:.3f} m/s "
            f"< c_m / e gives alpha_m < 0; the capillary part is set to 0",
            ValidityWarning, stacklevel=2,
        )
        alpha_m = 0.0
    return ElfouhailyParameters(
        u10=u10, omega_c=float(omega_c), k_p=float(k_p), c_p=c_p, u_star=float(u_star),
        alpha_p=float(alpha_p), alpha_m=float(alpha_m), gamma=float(gamma),
        delta=float(delta),
    )


def elfouhaily_long_wave(
    k: NDArray[np.float64], p: ElfouhailyParameters
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Elfouhaily et al.'s long-wave curvature ``B_l`` [-] and its cut-off [-].

    ``B_l = (alpha_p / 2) (c_p / c) F_p``, ``F_p = L_PM J_p F_c`` (eqs 2-3), with the
    long-wave side effect ``F_c = exp[-(Omega_c / sqrt(10)) (sqrt(k / k_p) - 1)]``, which
    ends the long waves' equilibrium range above ``k_p`` (returned as the second value;
    it exceeds 1 below ``k_p``, where ``L_PM`` takes over). Also the long waves of the
    Kudryavtsev et al. (2003) spectrum (:mod:`seaecho.ocean.kudryavtsev`).

    Parameters
    ----------
    k : ndarray
        Wavenumber [rad/m] (> 0).
    p : ElfouhailyParameters
        From :func:`elfouhaily_parameters`.
    """
    c = phase_speed(k)  # phase speed with capillarity
    cutoff = np.exp(-p.omega_c / np.sqrt(10.0) * (np.sqrt(k / p.k_p) - 1.0))  # side effect
    return 0.5 * p.alpha_p * (p.c_p / c) * _peak_shape(k, p) * cutoff, cutoff


def _peak_shape(k: NDArray[np.float64], p: ElfouhailyParameters) -> NDArray[np.float64]:
    """``L_PM J_p`` [-]: Pierson-Moskowitz shape times the peak enhancement (eqs 2-3)."""
    l_pm = np.exp(-1.25 * (p.k_p / k) ** 2)  # Eq. 2
    big_gamma = np.exp(-((np.sqrt(k / p.k_p) - 1.0) ** 2) / (2.0 * p.delta**2))  # Eq. 3
    return l_pm * p.gamma**big_gamma  # Eq. 3: J_p = gamma^Gamma


@register_spectrum("elfouhaily")
def elfouhaily(k: ArrayLike, u19_5: float, fetch: float | None = None) -> NDArray[np.float64]:
    """Elfouhaily et al. (1997) unified omnidirectional spectrum.

    .. math::

        S_{1d}(k) = k^{-3} (B_l + B_h),\\quad
        B_l = \\frac{\\alpha_p}{2}\\frac{c_p}{c} F_p,\\quad
        B_h = \\frac{\\alpha_m}{2}\\frac{c_m}{c} F_m

    with F_p = L_PM J_p exp[-(Omega_c / sqrt(10)) (sqrt(k / k_p) - 1)],
    L_PM = exp[-(5/4) (k_p / k)^2] (eq 2), J_p = gamma^Gamma,
    Gamma = exp[-(sqrt(k / k_p) - 1)^2 / (2 delta^2)] (eq 3) and
    F_m = L_PM J_p exp[-(1/4) (k / k_m - 1)^2]. Equation numbers other than 2-3 are not
    given: we could not check them against the paper's text.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    u19_5 : float
        Wind speed at 19.5 m [m/s] (U10 from :func:`seaecho.ocean.wind.u10_from_u19_5`).
    fetch : float or None
        Fetch [m]; None for a fully developed sea (Omega_c = 0.84).

    Returns
    -------
    ndarray
        S_1d [m^3].

    References
    ----------
    Elfouhaily et al. (1997), eqs 2-3 and the long- and short-wave curvature spectra;
    parameters cross-checked with independent implementations (Laxague, UNH; Fois, TU Delft).
    """
    p = elfouhaily_parameters(u19_5, fetch)
    k, pos, ks = _positive(k)
    c = phase_speed(ks)  # phase speed with capillarity
    b_l, _ = elfouhaily_long_wave(ks, p)  # long-wave curvature
    f_m = _peak_shape(ks, p) * np.exp(-0.25 * (ks / K_M - 1.0) ** 2)  # short-wave side effect
    b_h = 0.5 * p.alpha_m * (C_M / c) * f_m  # short-wave curvature
    return np.where(pos, (b_l + b_h) / ks**3, 0.0)  # S = k^-3 (B_l + B_h)


# --------------------------------------------------------------------------------------
# Kudryavtsev et al. (2003)
# --------------------------------------------------------------------------------------


@register_spectrum("kudryavtsev")
def kudryavtsev(
    k: ArrayLike, u19_5: float, fetch: float | None = None, angular: str = SPECTRUM_ANGULAR
) -> NDArray[np.float64]:
    """Kudryavtsev et al. (2003) omnidirectional spectrum: Elfouhaily's long waves and the
    short waves of the energy balance (:mod:`seaecho.ocean.kudryavtsev`, eqs KU1-KU10).

    .. math::

        S_{1d}(k) = k^{-3}\\left[B_l + (1 - F_c)\\int B_{sw}\\, d\\varphi\\right]

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m] (values <= 0 give 0).
    u19_5 : float
        Wind speed at 19.5 m [m/s] (U10 from :func:`seaecho.ocean.wind.u10_from_u19_5`).
    fetch : float or None
        Fetch [m] of the long waves (None: fully developed, Omega_c = 0.84).
    angular : str
        Angular form of the short waves' net growth rate (``"gaussian"``, KHCC03 eq 20,
        eq KU2, the registered spectrum's; ``"cos"``, K05 eq 17, eq KU2', without K05's
        generation of short waves by breaking: a sensitivity study;
        :data:`seaecho.ocean.kudryavtsev.ANGULAR_FORMS`).

    Returns
    -------
    ndarray
        S_1d [m^3]; the saturation ``k^3 S_1d`` at the X-band Bragg wavenumber 384 rad/m
        is 2.2e-3 at U10 = 7 m/s and 8.4e-3 at 12.5 m/s (with K05's angular form: 1.4e-3
        and 6.7e-3; Elfouhaily et al.: 6.8e-3 and 1.7e-2; Romeiser et al.: 1.6e-3 and
        3.2e-3).

    References
    ----------
    Kudryavtsev, Hauser, Caudal & Chapron (2003), eqs 13-30 (KU1-KU10); Elfouhaily et al.
    (1997) for the long waves.
    """
    p = elfouhaily_parameters(u19_5, fetch)
    k, pos, ks = _positive(k)
    b_l, cutoff = elfouhaily_long_wave(ks, p)
    b = total_saturation(b_l, cutoff,
                         short_wave_omni_saturation(ks, p.u10, angular))  # Eq. KU10
    return np.where(pos, b / ks**3, 0.0)


# --------------------------------------------------------------------------------------
# Spreading functions
# --------------------------------------------------------------------------------------


def longuet_higgins_normalisation(s: float) -> float:
    """N(s) = 2^(2s-1) Gamma^2(s+1) / (pi Gamma(2s+1)) [1/rad] (paper eq 6; N(1) = 1/pi)."""
    return float(
        np.exp((2 * s - 1) * np.log(2.0) + 2 * gammaln(s + 1) - gammaln(2 * s + 1)) / np.pi
    )


@register_spreading("longuet-higgins")
def longuet_higgins(
    k: ArrayLike, psi: ArrayLike, u19_5: float = 0.0, fetch: float | None = None,
    s: float = 1.0,
) -> NDArray[np.float64]:
    """Longuet-Higgins et al. (1963) spreading N(s) cos^2s(psi / 2) (paper eq 6).

    Normalised so that its integral over psi in (-pi, pi] is 1 (for s = 1, N = 1/pi; the
    paper's 4/pi is a typo, see docs/ocean.md). Independent of k.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m] (only broadcast against).
    psi : array_like
        Angle between wave travel and wind directions [rad].
    s : float
        Spreading exponent [-] (> 0).

    Returns
    -------
    ndarray
        D [1/rad].
    """
    if not s > 0:
        raise ValueError(f"s = {s}: the spreading exponent must be > 0")
    psi = np.asarray(psi, dtype=np.float64)
    d = longuet_higgins_normalisation(s) * np.abs(np.cos(0.5 * psi)) ** (2.0 * s)  # Eq. 6
    return np.broadcast_to(d, np.broadcast_shapes(np.shape(k), psi.shape)).copy()


@register_spreading("elfouhaily")
def elfouhaily_spreading(
    k: ArrayLike, psi: ArrayLike, u19_5: float, fetch: float | None = None, s: float = 1.0
) -> NDArray[np.float64]:
    """Elfouhaily et al. (1997) spreading (1 / 2 pi) [1 + Delta(k) cos 2 psi].

    Delta(k) = tanh[a0 + a_p (c / c_p)^2.5 + a_m (c_m / c)^2.5] with a0 = ln 2 / 4,
    a_p = 4, a_m = 0.13 u* / c_m. Centro-symmetric: it does not tell
    upwind from downwind travel.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m].
    psi : array_like
        Angle between wave travel and wind directions [rad].
    u19_5 : float
        Wind speed at 19.5 m [m/s].
    fetch : float or None
        Fetch [m].

    Returns
    -------
    ndarray
        D [1/rad].
    """
    p = elfouhaily_parameters(u19_5, fetch)
    k = np.asarray(k, dtype=np.float64)
    ks = np.maximum(k, K_FLOOR)
    c = phase_speed(ks)
    a0 = np.log(2.0) / 4.0
    a_m = 0.13 * p.u_star / C_M
    delta = np.tanh(a0 + 4.0 * (c / p.c_p) ** 2.5 + a_m * (C_M / c) ** 2.5)  # Delta(k)
    return (1.0 + delta * np.cos(2.0 * np.asarray(psi, dtype=np.float64))) / (2.0 * np.pi)


# --------------------------------------------------------------------------------------
# Directional spectrum
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DirectionalSpectrum:
    """Directional wavenumber spectrum Psi(Kx, Ky) = S_1d(K) D(K, psi) / K (paper eq 4).

    Parameters
    ----------
    spectrum : str
        Name in :data:`OMNI_SPECTRA`.
    spreading : str
        Name in :data:`SPREADINGS`.
    u19_5 : float
        Wind speed at 19.5 m [m/s].
    wind_direction : float
        Direction the wind blows towards, counter-clockwise from +x [rad].
    fetch : float or None
        Fetch [m] (None: fully developed).
    s : float
        Longuet-Higgins spreading exponent [-].
    """

    spectrum: str = "elfouhaily"
    spreading: str = "elfouhaily"
    u19_5: float = 5.0
    wind_direction: float = 0.0
    fetch: float | None = None
    s: float = 1.0

    def __post_init__(self) -> None:
        if self.spectrum not in OMNI_SPECTRA:
            raise ValueError(
                f"spectrum = {self.spectrum!r}: unknown; allowed: {sorted(OMNI_SPECTRA)}"
            )
        if self.spreading not in SPREADINGS:
            raise ValueError(
                f"spreading = {self.spreading!r}: unknown; allowed: {sorted(SPREADINGS)}"
            )
        if not self.u19_5 > 0:
            raise ValueError(f"u19_5 = {self.u19_5} m/s: must be > 0")
        if self.fetch is not None and not self.fetch > 0:
            raise ValueError(f"fetch = {self.fetch} m: must be > 0 or None")

    def omni(self, k: ArrayLike) -> NDArray[np.float64]:
        """Omnidirectional spectrum S_1d(k) [m^3]."""
        return OMNI_SPECTRA[self.spectrum](np.asarray(k, dtype=np.float64), self.u19_5,
                                           self.fetch)

    def spread(self, k: ArrayLike, psi: ArrayLike) -> NDArray[np.float64]:
        """Spreading D(k, psi) [1/rad]; psi relative to the wind direction."""
        return SPREADINGS[self.spreading](
            np.asarray(k, dtype=np.float64), np.asarray(psi, dtype=np.float64), self.u19_5,
            self.fetch, self.s,
        )

    # the name the scattering stage was promised
    spreading_function = spread

    def __call__(self, kx: ArrayLike, ky: ArrayLike) -> NDArray[np.float64]:
        """Psi(kx, ky) [m^4]: spectrum of waves travelling along (kx, ky) (eq 4)."""
        kx = np.asarray(kx, dtype=np.float64)
        ky = np.asarray(ky, dtype=np.float64)
        k = np.hypot(kx, ky)
        psi = np.arctan2(ky, kx) - self.wind_direction
        pos = k > K_FLOOR
        ks = np.where(pos, k, 1.0)
        return np.where(pos, self.omni(ks) * self.spread(ks, psi) / ks, 0.0)  # Eq. 4

    def height_spectrum(self, kx: ArrayLike, ky: ArrayLike) -> NDArray[np.float64]:
        """W(K) = (Psi(K) + Psi(-K)) / 2 [m^4]: spectrum of the frozen height field.

        A snapshot of the surface does not tell which way a wave travels; its height
        spectrum is centro-symmetric. This is the spectrum the small perturbation model
        (Bragg scattering) needs; its integral over the plane is also <z^2>.
        """
        kx = np.asarray(kx, dtype=np.float64)
        ky = np.asarray(ky, dtype=np.float64)
        return 0.5 * (self(kx, ky) + self(-kx, -ky))

    def peak_wavenumber(self) -> float:
        """Wavenumber of the maximum of S_1d [rad/m] (numerical, on a log grid)."""
        k = np.logspace(-4, 2, 6001)
        return float(k[np.argmax(self.omni(k))])


__all__ = [
    "OMNI_SPECTRA",
    "SPREADINGS",
    "DirectionalSpectrum",
    "ElfouhailyParameters",
    "elfouhaily",
    "elfouhaily_long_wave",
    "elfouhaily_parameters",
    "elfouhaily_spreading",
    "jonswap",
    "jonswap_parameters",
    "kudryavtsev",
    "longuet_higgins",
    "longuet_higgins_normalisation",
    "pierson_moskowitz",
    "pierson_moskowitz_peak",
    "register_spectrum",
    "register_spreading",
    "u10_from_u19_5",
]
