"""Amplitude statistics of sea clutter: K, Rayleigh and Weibull models and their fits.

**K distribution** (compound model; Jakeman & Pusey 1976, Ward 1981; Ward, Tough & Watts
2013, ch. 4): the intensity ``z = |E|^2`` of a range cell is speckle (exponential, mean
``x``) modulated by a gamma-distributed local power ``x`` of shape ``nu`` and mean ``mu``:

.. math::
    p(z) = \\frac{2}{\\Gamma(\\nu)}\\left(\\frac{\\nu}{\\mu}\\right)^{(\\nu+1)/2}
    z^{(\\nu-1)/2} K_{\\nu-1}\\!\\left(2\\sqrt{\\nu z/\\mu}\\right),\\qquad
    \\langle z^n\\rangle = \\mu^n\\, n!\\,\\frac{\\Gamma(\\nu+n)}{\\nu^n\\Gamma(\\nu)}  (ST1, ST2)

(the amplitude ``E = sqrt(z)`` has ``p(E) = 2 E p(z = E^2)``). Small ``nu`` is spiky
clutter; ``nu -> infinity`` is Rayleigh (exponential intensity).

**Estimators of nu** from N intensity samples:

* moments (ST2 with n = 2): ``<z^2>/<z>^2 = 2 (1 + 1/nu)``, so
  ``nu = 1 / (<z^2> / (2 <z>^2) - 1)`` (ST3);
* "z log z" (Blacknell & Tough 2001): ``<z ln z>/<z> - <ln z> = 1 + 1/nu`` (ST4), from
  ``psi(nu + 1) - psi(nu) = 1/nu`` for the gamma texture and 1 for the exponential
  speckle; more robust than ST3 for spiky clutter;
* maximum likelihood: ST1 maximised over (nu, mu) (ST5).

**Empirical shape law** (Watts & Wicks 1990; restated by Ward, Tough & Watts):

.. math::
    \\log_{10}\\nu = \\tfrac{2}{3}\\log_{10}\\phi_{gr} + \\tfrac{5}{8}\\log_{10}A_c
    - k_{pol} - \\frac{\\cos 2\\theta_{sw}}{3}                                   (ST6)

``phi_gr`` grazing angle [deg], ``A_c`` resolved area [m^2], ``k_pol = 1.39`` (VV) or
``2.09`` (HH), ``theta_sw`` the look direction relative to the swell; stated for
0.1-10 deg grazing.

References
----------
.. [1] Ward, K. D., Tough, R. J. A. and Watts, S. (2013). *Sea Clutter: Scattering, the
   K Distribution and Radar Performance*, 2nd ed., IET.
.. [2] Blacknell, D. and Tough, R. J. A. (2001). Parameter estimation for the
   K-distribution based on [z log(z)]. *IEE Proc. Radar Sonar Navig.* 148(6), 309-312.
.. [3] Watts, S. and Wicks, D. (1990). Empirical models for detection prediction in
   K-distribution radar sea clutter. *Proc. IEEE Int. Radar Conf.*, 189-194.
.. [4] Jakeman, E. and Pusey, P. N. (1976). A model for non-Rayleigh sea echo. *IEEE
   Trans. Antennas Propag.* 24(6), 806-814.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize, special, stats

#: Polarisation constants k_pol of eq ST6 [-].
K_POL = {"VV": 1.39, "HH": 2.09}


def _intensities(z: ArrayLike, name: str = "z") -> NDArray:
    z = np.asarray(z, dtype=float).ravel()
    if z.size < 2:
        raise ValueError(f"{name}: need at least two samples, got {z.size}")
    if not np.all(np.isfinite(z)) or np.any(z <= 0.0):
        raise ValueError(f"{name}: intensities must be finite and > 0")
    return z


def _log_kv(v: float, x: NDArray) -> NDArray:
    """log K_v(x) for x > 0: scipy's scaled Bessel function up to order 50, above it the
    uniform (Debye) expansion to second order (DLMF 10.41.4, 10.41.10; relative error
    below 1e-5 for v >= 50)."""
    v = abs(float(v))
    if v < 50.0:
        return np.log(special.kve(v, x)) - x
    t = x / v
    r = np.sqrt(1.0 + t * t)
    eta = r + np.log(t / (1.0 + r))
    p = 1.0 / r
    u1 = (3.0 * p - 5.0 * p**3) / 24.0
    u2 = (81.0 * p**2 - 462.0 * p**4 + 385.0 * p**6) / 1152.0
    return (0.5 * np.log(np.pi / (2.0 * v)) - v * eta - 0.5 * np.log(r)
            + np.log1p(-u1 / v + u2 / v**2))


def k_intensity_pdf(z: ArrayLike, nu: float, mean: float) -> NDArray:
    """K-distribution intensity density ``p(z)`` [1/intensity] (eq ST1).

    Parameters
    ----------
    z : array_like
        Intensity >= 0 (any unit).
    nu : float
        Shape parameter > 0 [-].
    mean : float
        Mean intensity ``mu`` > 0 (unit of ``z``).
    """
    z = np.asarray(z, dtype=float)
    b = nu / mean
    arg = 2.0 * np.sqrt(b * np.maximum(z, 0.0))
    pos = z > 0.0
    zz = np.where(pos, z, 1.0)
    # Eq ST1 in logarithms.
    logp = (np.log(2.0) - special.gammaln(nu) + 0.5 * (nu + 1.0) * np.log(b)
            + 0.5 * (nu - 1.0) * np.log(zz) + _log_kv(nu - 1.0, np.where(pos, arg, 1.0)))
    return np.where(pos, np.exp(logp), 0.0)


def k_intensity_moment(n: ArrayLike, nu: float, mean: float) -> NDArray:
    """``<z^n> = mu^n Gamma(n+1) Gamma(nu+n) / (nu^n Gamma(nu))`` (eq ST2), real n > -nu."""
    n = np.asarray(n, dtype=float)
    return np.exp(n * np.log(mean / nu) + special.gammaln(n + 1.0)
                  + special.gammaln(nu + n) - special.gammaln(nu))


def k_intensity_samples(nu: float, mean: float, size, rng: np.random.Generator) -> NDArray:
    """Draw K-distributed intensities: gamma texture (shape nu, mean mu) x exp. speckle."""
    if not (nu > 0 and mean > 0):
        raise ValueError(f"nu = {nu!r}, mean = {mean!r}: both must be > 0")
    return rng.gamma(nu, mean / nu, size) * rng.exponential(1.0, size)


def k_shape_moments(z: ArrayLike) -> float:
    """Method-of-moments estimate of nu (eq ST3); ``inf`` when <z^2> <= 2 <z>^2."""
    z = _intensities(z)
    r = np.mean(z**2) / (2.0 * np.mean(z) ** 2) - 1.0
    return float(1.0 / r) if r > 0 else float("inf")


def k_shape_zlogz(z: ArrayLike) -> float:
    """"z log z" estimate of nu (eq ST4; Blacknell & Tough 2001); ``inf`` if no excess."""
    z = _intensities(z)
    lz = np.log(z)
    r = np.mean(z * lz) / np.mean(z) - np.mean(lz) - 1.0
    return float(1.0 / r) if r > 0 else float("inf")


@dataclass(frozen=True)
class KFit:
    """Maximum-likelihood K fit (eq ST5): shape ``nu`` [-], mean intensity ``mean``."""

    nu: float
    mean: float
    log_likelihood: float


def fit_k(z: ArrayLike, nu_max: float = 1e4) -> KFit:
    """Maximum-likelihood K-distribution fit of intensities (eq ST5).

    Starts from the z log z estimate; ``nu`` is bounded to ``[1e-3, nu_max]``.
    """
    z = _intensities(z)
    nu0 = min(max(k_shape_zlogz(z), 1e-2), nu_max)
    mu0 = float(np.mean(z))

    def nll(p):
        nu, mu = np.exp(p[0]), np.exp(p[1])
        return -np.sum(np.log(np.maximum(k_intensity_pdf(z, nu, mu), 1e-300)))

    res = optimize.minimize(nll, [np.log(nu0), np.log(mu0)], method="L-BFGS-B",
                            bounds=[(np.log(1e-3), np.log(nu_max)), (None, None)])
    return KFit(float(np.exp(res.x[0])), float(np.exp(res.x[1])), float(-res.fun))


@dataclass(frozen=True)
class RayleighFit:
    """Rayleigh amplitude fit: ``p(E) = E/s^2 exp(-E^2 / 2s^2)``, ML ``s^2 = <E^2>/2``."""

    sigma: float
    log_likelihood: float


def fit_rayleigh(amplitude: ArrayLike) -> RayleighFit:
    """Maximum-likelihood Rayleigh fit of amplitudes ``E = |a|``."""
    e = np.sqrt(_intensities(np.square(np.asarray(amplitude, dtype=float)), "amplitude"))
    s2 = 0.5 * np.mean(e**2)
    ll = np.sum(np.log(e / s2) - e**2 / (2.0 * s2))
    return RayleighFit(float(np.sqrt(s2)), float(ll))


@dataclass(frozen=True)
class WeibullFit:
    """Weibull amplitude fit ``p(E) = (c/b)(E/b)^(c-1) exp(-(E/b)^c)``: shape c, scale b."""

    shape: float
    scale: float
    log_likelihood: float


def fit_weibull(amplitude: ArrayLike) -> WeibullFit:
    """Maximum-likelihood Weibull fit of amplitudes (location fixed at 0)."""
    e = np.sqrt(_intensities(np.square(np.asarray(amplitude, dtype=float)), "amplitude"))
    c, _, b = stats.weibull_min.fit(e, floc=0.0)
    ll = float(np.sum(stats.weibull_min.logpdf(e, c, 0.0, b)))
    return WeibullFit(float(c), float(b), ll)


def k_shape_empirical(grazing_deg: ArrayLike, area_m2: ArrayLike, pol: str,
                      swell_aspect: ArrayLike = np.pi / 4) -> NDArray:
    """Empirical K shape parameter of sea clutter (eq ST6; Watts & Wicks 1990).

    Parameters
    ----------
    grazing_deg : array_like
        Grazing angle [deg] (stated for 0.1-10 deg).
    area_m2 : array_like
        Resolved (clutter cell) area [m^2].
    pol : {"VV", "HH"}
        Polarisation.
    swell_aspect : array_like
        Look direction relative to the swell direction [rad]; the default pi/4 removes
        the swell term (no swell).

    Returns
    -------
    ndarray
        nu [-].
    """
    if pol not in K_POL:
        raise ValueError(f"pol = {pol!r}: choose from {sorted(K_POL)}")
    g = np.asarray(grazing_deg, dtype=float)
    a = np.asarray(area_m2, dtype=float)
    if np.any(g <= 0) or np.any(a <= 0):
        raise ValueError("grazing_deg and area_m2 must be > 0")
    # Eq ST6.
    log_nu = (2.0 / 3.0) * np.log10(g) + 0.625 * np.log10(a) - K_POL[pol] - np.cos(
        2.0 * np.asarray(swell_aspect, dtype=float)) / 3.0
    return 10.0**log_nu


__all__ = [
    "K_POL", "KFit", "RayleighFit", "WeibullFit", "fit_k", "fit_rayleigh", "fit_weibull",
    "k_intensity_moment", "k_intensity_pdf", "k_intensity_samples", "k_shape_empirical",
    "k_shape_moments", "k_shape_zlogz",
]
