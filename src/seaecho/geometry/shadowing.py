r"""Statistical shadowing of a Gaussian rough surface: Smith's function, mono- and bistatic.

A point of a rough surface is *lit* by a source when (a) its facet faces the source
(self-shadowing) and (b) the straight ray to the source does not cut the surface
(shadowing by other parts of the surface). Smith (1967) gives the probability of (b) for a
stationary Gaussian surface, assuming the heights and slopes along the ray are
uncorrelated with those of the point; Bourlier, Berginc & Saillard (2002) extend it to the
bistatic case (illumination by the transmitter *and* visibility from the receiver).

Symbols (``docs/tracing.md``, section "Analytic mode")::

    theta            angle of the ray from the mean-plane normal +z             [rad]
    mu = cot(theta)  slope of the ray                                           [-]
    sigma            rms slope of the surface along the ray's azimuth           [-]
    sigma_h          rms height                                                 [m]
    nu = mu / (sqrt(2) sigma)                                                   [-]
    Lambda(nu) = (exp(-nu^2) / (sqrt(pi) nu) - erfc(nu)) / 2                    (T1)
    F(zeta)  = 1 - erfc(zeta / (sqrt(2) sigma_h)) / 2  (height CDF)             (T2)
    S(theta | zeta) = F(zeta)^Lambda            (not shadowed, given height)    (T3)
    S(theta) = (1 - erfc(nu) / 2) / (1 + Lambda)   (lit, averaged over heights
                                                    and slopes, facing included) (T4)
    bistatic, opposite sides:  S(theta_1, theta_2 | zeta) = F^(Lambda_1 + Lambda_2)  (T5)
    bistatic, same azimuth:    S(theta_1, theta_2 | zeta) = F^max(Lambda_1, Lambda_2) (T6)

References
----------
.. [Smith67] B. G. Smith, "Geometrical shadowing of a random rough surface", IEEE Trans.
   Antennas Propag., vol. AP-15, no. 5, pp. 668-671, 1967.
.. [Bourlier02] C. Bourlier, G. Berginc, J. Saillard, "Monostatic and bistatic statistical
   shadowing functions from a one-dimensional stationary randomly rough surface according
   to the observation length: I. Single scattering", Waves in Random Media, vol. 12,
   no. 2, pp. 145-173, 2002.
.. [Sancer69] M. I. Sancer, "Shadow-corrected electromagnetic scattering from a randomly
   rough surface", IEEE Trans. Antennas Propag., vol. AP-17, no. 5, pp. 577-585, 1969.
"""

from __future__ import annotations

import numpy as np
from scipy.special import erfc, erfcx, ndtr

__all__ = [
    "directional_slope_std",
    "height_cdf",
    "smith_bistatic",
    "smith_conditional",
    "smith_lambda",
    "smith_monostatic",
    "smith_nu",
]

_SQRT_PI = np.sqrt(np.pi)


def smith_nu(theta: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    """Smith's argument nu = cot(theta) / (sqrt(2) sigma) [-].

    Parameters
    ----------
    theta : array
        Angle of the ray to the source from the mean-plane normal [rad], in [0, pi/2].
    sigma : array
        Rms surface slope along the ray's azimuth [-], > 0.
    """
    theta = np.asarray(theta, dtype=np.float64)
    sigma = np.asarray(sigma, dtype=np.float64)
    if np.any(sigma <= 0):
        raise ValueError(f"sigma = {np.min(sigma)}: rms slope must be > 0 [-]")
    if np.any((theta < 0) | (theta > np.pi / 2)):
        raise ValueError("theta must lie in [0, pi/2] [rad] (a source above the mean plane)")
    with np.errstate(divide="ignore"):
        mu = np.cos(theta) / np.sin(theta)  # slope of the ray, cot(theta)
    return mu / (np.sqrt(2.0) * sigma)


def smith_lambda(nu: np.ndarray) -> np.ndarray:
    r"""Smith's Lambda function (eq T1).

    .. math:: \Lambda(\nu) = \frac{1}{2}\left(\frac{e^{-\nu^2}}{\sqrt{\pi}\,\nu}
              - \operatorname{erfc}\nu\right)

    Parameters
    ----------
    nu : array
        ``cot(theta) / (sqrt(2) sigma)`` [-], >= 0 (inf allowed: Lambda = 0).

    Returns
    -------
    array
        Lambda [-], >= 0; infinite at nu = 0 (grazing ray: everything shadowed).

    References
    ----------
    [Smith67]_ (definition of Lambda); [Bourlier02]_ (same function).
    """
    nu = np.asarray(nu, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # erfc(nu) = erfcx(nu) exp(-nu^2): factor exp(-nu^2) out to keep precision  (T1)
        lam = 0.5 * np.exp(-nu * nu) * (1.0 / (_SQRT_PI * nu) - erfcx(nu))
    lam = np.where(np.isinf(nu), 0.0, lam)
    return np.where(nu == 0.0, np.inf, np.maximum(lam, 0.0))


def height_cdf(zeta: np.ndarray, sigma_h: float) -> np.ndarray:
    """Gaussian height CDF F(zeta) = 1 - erfc(zeta / (sqrt(2) sigma_h)) / 2 (eq T2) [-].

    Parameters
    ----------
    zeta : array
        Height above the mean plane [m].
    sigma_h : float
        Rms height [m], > 0.
    """
    if not sigma_h > 0:
        raise ValueError(f"sigma_h = {sigma_h}: rms height must be > 0 [m]")
    return ndtr(np.asarray(zeta, dtype=np.float64) / sigma_h)  # (T2)


def smith_conditional(lam: np.ndarray, zeta: np.ndarray, sigma_h: float) -> np.ndarray:
    """Probability that a point at height zeta is not shadowed, F(zeta)^Lambda (eq T3).

    Facing (self-shadowing) is *not* included: multiply by the facing test of the facet.
    For the bistatic forms pass ``lam = Lambda_1 + Lambda_2`` (eq T5, Tx and Rx on
    opposite sides / independent rays) or ``max(Lambda_1, Lambda_2)`` (eq T6, same azimuth).

    Parameters
    ----------
    lam : array
        Smith's Lambda of the ray(s) [-] (:func:`smith_lambda`).
    zeta : array
        Height of the point [m].
    sigma_h : float
        Rms height of the surface [m].

    Returns
    -------
    array
        Probability in [0, 1] [-].

    References
    ----------
    [Smith67]_ (shadowing given the height); [Bourlier02]_ (bistatic forms).
    """
    f = height_cdf(zeta, sigma_h)
    with np.errstate(divide="ignore"):
        return np.where(np.asarray(lam) == 0.0, 1.0, f ** np.asarray(lam))  # (T3)


def smith_monostatic(theta: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    """Fraction of a Gaussian surface lit by a far source (eq T4) [-].

    Averaged over heights and slopes, self-shadowing (facets turned away) included: the
    probability that a point drawn uniformly over the mean plane is lit.

    Parameters
    ----------
    theta : array
        Angle of the source from +z [rad].
    sigma : array
        Rms slope along the source's azimuth [-].

    References
    ----------
    [Smith67]_ (average shadowing function with self-shadowing); [Bourlier02]_.
    """
    nu = smith_nu(theta, sigma)
    # facing probability P(slope along the ray < cot theta) over 1 + Lambda  (T4)
    return (1.0 - 0.5 * erfc(nu)) / (1.0 + smith_lambda(nu))


def directional_slope_std(slope_cov: np.ndarray, azimuth: np.ndarray) -> np.ndarray:
    """Rms slope along an azimuth for a Gaussian slope covariance [-].

    Parameters
    ----------
    slope_cov : (2, 2) array
        Covariance of (dz/dx, dz/dy) [-].
    azimuth : array
        Azimuth of the direction, counter-clockwise from +x [rad].

    Returns
    -------
    array
        sqrt(e^T C e) with e = (cos azimuth, sin azimuth) [-].
    """
    c = np.asarray(slope_cov, dtype=np.float64)
    ca, sa = np.cos(azimuth), np.sin(azimuth)
    return np.sqrt(c[0, 0] * ca * ca + 2.0 * c[0, 1] * ca * sa + c[1, 1] * sa * sa)


def smith_bistatic(theta_1: float, azimuth_1: float, theta_2: float, azimuth_2: float,
                   slope_cov: np.ndarray) -> float:
    """Fraction of a Gaussian surface lit by source 1 and seen from source 2 [-].

    Averaged over heights and slopes, both facing tests included. The facing probability
    is the bivariate normal probability that the slopes along both azimuths stay below
    the rays' slopes; the shadowing factor is ``1 / (1 + Lambda_1 + Lambda_2)`` (eq T5
    averaged over heights) when the azimuths differ, ``1 / (1 + max Lambda)`` (eq T6)
    when they coincide (monostatic, or Tx and Rx in one vertical half-plane). For other
    azimuths the rays cross different surface profiles, taken as independent
    ([Sancer69]_, [Bourlier02]_), which is exact for opposite azimuths.

    Parameters
    ----------
    theta_1, theta_2 : float
        Angles of the two rays from +z [rad].
    azimuth_1, azimuth_2 : float
        Their azimuths, counter-clockwise from +x [rad] (direction from the surface
        towards the source / receiver).
    slope_cov : (2, 2) array
        Covariance of the slopes (dz/dx, dz/dy) [-].

    References
    ----------
    [Bourlier02]_; [Sancer69]_.
    """
    from scipy.stats import multivariate_normal

    c = np.asarray(slope_cov, dtype=np.float64)
    e1 = np.array([np.cos(azimuth_1), np.sin(azimuth_1)])
    e2 = np.array([np.cos(azimuth_2), np.sin(azimuth_2)])
    s1, s2 = np.sqrt(e1 @ c @ e1), np.sqrt(e2 @ c @ e2)
    mu1, mu2 = 1.0 / np.tan(theta_1), 1.0 / np.tan(theta_2)
    lam1 = float(smith_lambda(smith_nu(theta_1, s1)))
    lam2 = float(smith_lambda(smith_nu(theta_2, s2)))
    rho = (e1 @ c @ e2) / (s1 * s2)
    same_azimuth = abs(np.angle(np.exp(1j * (azimuth_1 - azimuth_2)))) < 1e-9
    if same_azimuth:
        facing = float(ndtr(min(mu1, mu2) / s1))
        return facing / (1.0 + max(lam1, lam2))  # (T6), averaged over heights
    if abs(rho) > 1.0 - 1e-12:  # opposite azimuths: -mu2 < slope_1 < mu1
        facing = float(ndtr(mu1 / s1) - ndtr(-mu2 / s1))
    else:
        facing = float(multivariate_normal(mean=[0.0, 0.0], cov=[[1.0, rho], [rho, 1.0]]).cdf(
            [mu1 / s1, mu2 / s2]))
    return max(facing, 0.0) / (1.0 + lam1 + lam2)  # (T5), averaged over heights
