"""Propagation over the sea: the two-ray (direct + sea-reflected) pattern-propagation factor.

A point at height h_2 above the sea, seen from an antenna at height h_1 over ground
distance d, receives the direct wave and the wave reflected by the sea at the specular
point, a distance d_1 from the antenna (d_2 = d - d_1). Their sum, relative to the
direct wave alone, is the propagation factor (pattern ratio 1, see below)

.. math::

    F_{h,v} = 1 + \\Gamma_{h,v}(\\psi)\\,\\rho_s(\\psi)\\,D\\;e^{-j k \\delta}            (P1)

(Blake 1986, eq 6.5 with the reflection coefficient split into its factors; Kerr 1951,
section 2.5; Ward, Tough and Watts 2013, section 3.6; time convention exp(+j w t), so a
path longer by delta lags by exp(-j k delta)), with

- Gamma_h, Gamma_v the Fresnel coefficients of sea water at the grazing angle psi of the
  specular point (:func:`seaecho.scattering.fresnel.fresnel_coefficients` at incidence
  pi/2 - psi; both tend to -1 at grazing incidence, Gamma_v has its minimum at the
  pseudo-Brewster angle), the permittivity from :mod:`seaecho.ocean.seawater`;
- rho_s the coherent (specular) reflection factor of the rough sea of rms height
  sigma_h (Miller, Brown and Vegh 1984: exp(-2 g^2) I0(2 g^2), g = k sigma_h sin psi;
  :func:`seaecho.targets.multipath.specular_reduction`, the one the hulls' SBR
  multipath uses);
- D the divergence factor of the spherical Earth (:func:`divergence_factor`, eq P3);
- delta the path difference (eq P4).

Geometry on the effective Earth of radius R = k a (Kerr 1951, section 2.4; Blake 1986,
chapter 6). The specular point solves Blake's cubic, written in closed form

.. math::

    p = \\tfrac{2}{\\sqrt 3}\\sqrt{R (h_1 + h_2) + d^2/4},\\quad
    \\Phi = \\arccos\\frac{2 R (h_1 - h_2)\\, d}{p^3},\\quad
    d_1 = \\frac d2 + p\\cos\\frac{\\Phi + \\pi}{3}                                 (P2)

(Kerr 1951, section 2.4; flat-Earth limit R -> inf: d_1 = d h_1 / (h_1 + h_2)). The
two legs and the direct path are then measured exactly in the vertical plane through the
antenna, the point and the Earth's centre, in the frame of the specular point S (x
along the surface, y up): a point at distance s along the surface from S and height h
is at ((R + h) sin(s/R), h cos(s/R) - 2 R sin^2(s/(2R))). The grazing angle is the mean
of the two legs' elevations seen from S (equal on a flat Earth, and to O(d^2 / R^2) on
the sphere), and

.. math::

    \\delta = |\\mathbf u_1| + |\\mathbf u_2| - |\\mathbf u_2 - \\mathbf u_1|      (P4)

with u_1, u_2 the vectors from S to the antenna and to the point (flat Earth: delta =
4 h_1 h_2 / (r_reflected + r_direct), ~ 2 h_1 h_2 / d). The divergence factor of the
convex sphere, the spreading of the reflected ray tube in the vertical plane (Kerr 1951,
eq 2.5(9); Blake 1986, chapter 6):

.. math::

    D = \\left[1 + \\frac{2 d_1 d_2}{R\\, d\\, \\sin\\psi}\\right]^{-1/2}            (P3)

Where it is used. The radar equation (``seaecho.radar.kernels``, eq R1) multiplies a
point target's or a sea facet's scattering amplitude S, in the world FSA bases (h, v),
by diag(F_h, F_v) of the receive leg on the left and of the transmit leg on the right:
S' = diag(F_r) S diag(F_t) (:meth:`TwoRay.apply`), so that a monostatic HH echo carries
|F_h|^4 in power. Any port basis (circular, slanted) follows from its (h, v) components.
The hulls' ray-traced echo is not multiplied: their SBR trace follows the sea-reflected
legs itself (``seaecho.targets.multipath``).

Shadowing of the sea-reflected legs (``TwoRay.slope_cov`` given; ``[propagation]
multipath_shadowing``). At low grazing angles the waves hide most of the sea from the
radar, and the reflected leg from the sea to the scatterer runs as low: the wave is
reflected only by the points of the sea that are lit by the antenna *and* seen from the
scatterer's side. For a Gaussian sea of rms height sigma_h and rms slope sigma along the
path, Smith's (1967) probability that a point at height zeta is lit from grazing psi is
F(zeta)^Lambda (:mod:`seaecho.geometry.shadowing`, eqs T1-T3, nu = tan psi /
(sqrt 2 sigma)); for the two legs, on opposite sides of the point in one vertical plane,
F(zeta)^(2 Lambda) (eq T5). The heights of the reflecting points then have the density
of the lit points (Bayes' rule on eq T5, normalised), the illuminated height PDF that
Bourlier, Pinel and Fabbro (2006) and Fabbro, Bourlier and Combes (2006) derive for the
forward (specular) configuration and put into Ament's boundary condition "with shadowing
effect" (their abstracts read; their full text and equation numbers were not checked
here: eq P5 is written from eq T5, and tested against closed forms of order statistics)

.. math::

    p_{ill}(\\zeta) = (1 + 2\\Lambda)\\, p(\\zeta)\\, F(\\zeta)^{2\\Lambda}         (P5)

(normalised: the lit crests reflect the wave that the shadowed troughs do not see; with
2 Lambda = m - 1 an integer, the density of the highest of m independent heights), and
the coherent reflection is its characteristic function at q = 2 k sin psi (Ament's
exp(-2 g^2) where Lambda = 0, at high grazing angles):

.. math::

    \bar\\zeta = \\int \\zeta\\, p_{ill}\\, d\\zeta, \\qquad
    \rho_{ill} = \\int p_{ill}(\\zeta)\\, e^{-j q (\\zeta - \bar\\zeta)}\\, d\\zeta  (P6)

The factor e^{-j q zeta_bar} is the mirror raised to the mean height of the lit crests.
A scatterer among the waves (a facet at height h_2) receives the reflected wave only
from points below it. This extension is derived here, not taken from the papers above
(which treat a receiver far above the waves): the reflected leg rises from zeta to h_2
over a finite length, taken unshadowed with probability (F(zeta) / F(h_2))^Lambda (Smith's
uncorrelated form restricted to heights below h_2), so that for the incident and
reflected legs together

.. math::

    p_{ill}(\\zeta \\mid h_2) = (1 + 2\\Lambda)\\, p(\\zeta)\\, F(\\zeta)^{2\\Lambda}
                            / F(h_2)^{1 + 2\\Lambda}, \\qquad \\zeta < h_2          (P7)

(eq P5 for h_2 -> inf: a target high above the waves). The two-ray geometry (P2-P4) is
evaluated with the heights above zeta_bar, h_1 - zeta_bar and h_2 - zeta_bar (> 0 by
P7), and rho_s of (P1) is rho_ill. Lambda, zeta_bar and rho_ill are
evaluated at the grazing angle of the mean sea's specular point (the raised mirror
changes psi by about 2 zeta_bar / d); the integrals by Gauss-Legendre quadrature in v =
F(zeta)^(1 + 2 Lambda), uniform on (0, 1) under (P5), so that zeta(v) = sigma_h
Phi^-1(F(h_2) v^(1 / (1 + 2 Lambda))); rho_ill = 0 where q sigma_ill > 8 (sigma_ill the spread
of the lit heights; |rho_ill| < 1e-5 there).

Approximations (stated): the scatterer's response to the reflected wave, which arrives
from 2 psi below the direct one, is its response to the direct wave, and the antenna's
gain towards the specular point is its gain towards the point (pattern ratio 1: marine
fan beams are 20-25 deg high, psi a fraction of a degree); the specular point is that of
the mean sea level (z = 0); a point below it (a facet in a trough) is taken at height 0
(F = 1 + Gamma rho_s D, nearly 0 at grazing incidence); the diffuse (incoherent) forward
scatter of the rough sea and diffraction beyond the horizon are not modelled (the
interference region only: points beyond the horizon are hidden, ``seaecho.geometry.earth``).

References
----------
.. [1] Blake, L. V. (1986). *Radar Range-Performance Analysis*, Artech House, chapter 6
   ("Multipath Propagation": the pattern-propagation factor, eq 6.5, over a flat and a
   spherical Earth; the book's chapter 3 is on target cross section, by its table of
   contents; the equation numbers in chapter 6 are not checked here).
.. [2] Kerr, D. E. (ed.) (1951). *Propagation of Short Radio Waves*, MIT Radiation
   Laboratory Series 13, McGraw-Hill, sections 2.4-2.5.
.. [3] Miller, A. R., Brown, R. M. and Vegh, E. (1984). New derivation for the
   rough-surface reflection coefficient and for the distribution of sea-wave elevations.
   *IEE Proc. H* 131(2), 114-116.
.. [4] Ward, K. D., Tough, R. J. A. and Watts, S. (2013). *Sea Clutter: Scattering, the
   K Distribution and Radar Performance*, 2nd ed., IET, section 3.6.
.. [5] Skolnik, M. I. (2001). *Introduction to Radar Systems*, 3rd ed., section 8.2
   (flat-Earth two-ray: F = 2 |sin(2 pi h_1 h_2 / (lambda R))| for Gamma = -1).
.. [6] Smith, B. G. (1967). Geometrical shadowing of a random rough surface. *IEEE
   Trans. Antennas Propag.* 15(5), 668-671.
.. [7] Fabbro, V., Bourlier, C. and Combes, P. F. (2006). Forward propagation modeling
   above Gaussian rough surfaces by the parabolic wave equation: introduction of the
   shadowing effect. *Progress In Electromagnetics Research* 58, 243-269.
.. [8] Bourlier, C., Pinel, N. and Fabbro, V. (2006). Illuminated height PDF of a random
   rough surface and its impact on the forward propagation above oceans at grazing
   angles. *Proc. EuCAP 2006*, Nice.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..geometry.shadowing import directional_slope_std, smith_lambda, smith_nu
from ..scattering.fresnel import fresnel_coefficients
from ..targets.multipath import specular_reduction

__all__ = ["TwoRay", "divergence_factor", "heights_and_distance", "illuminated_reflection",
           "reflection_point", "two_ray_factor", "two_ray_geometry"]

#: Gauss-Legendre nodes of the quadrature of eq (P6): absolute error < 1e-4 for
#: q sigma_ill <= 2, < 1.1e-3 for q sigma_ill <= 8 (against a 40 001-point trapezoid: tests)
_N_GAUSS = 96
#: beyond q sigma_ill = 8 rho_ill is 0 (its value there is below 1e-5 for Lambda <= 100;
#: sigma_ill the rms spread of the lit heights)
_QSIGMA_MAX = 8.0


def reflection_point(h1: ArrayLike, h2: ArrayLike, d: ArrayLike,
                     radius: float = np.inf) -> NDArray[np.float64]:
    """Distance d_1 [m] from the antenna's foot to the specular point, eq (P2).

    Parameters
    ----------
    h1, h2 : array_like
        Heights of the antenna and the point above the sea [m], >= 0.
    d : array_like
        Ground (great-circle) distance between them [m].
    radius : float
        Effective Earth radius k a [m]; ``numpy.inf`` for a flat Earth.

    References
    ----------
    Kerr (1951), section 2.4; Blake (1986), chapter 6.
    """
    h1, h2, d = (np.asarray(a, dtype=np.float64) for a in (h1, h2, d))
    hs = h1 + h2
    with np.errstate(divide="ignore", invalid="ignore"):
        flat = np.where(hs > 0, d * h1 / hs, 0.5 * d)
        if np.isinf(radius):
            return flat
        # Eq (P2)
        p = (2.0 / np.sqrt(3.0)) * np.sqrt(radius * hs + 0.25 * d * d)
        arg = np.clip(2.0 * radius * (h1 - h2) * d / p**3, -1.0, 1.0)
        d1 = 0.5 * d + p * np.cos((np.arccos(arg) + np.pi) / 3.0)
    return np.where(p > 0, np.clip(d1, 0.0, d), flat)


def _in_specular_frame(s: NDArray, h: NDArray, radius: float
                       ) -> tuple[NDArray, NDArray]:
    """(x, y) [m] of a point at surface distance s and height h in the specular point's
    frame (module docstring; no cancellation for s, h << R)."""
    if np.isinf(radius):
        return s, h
    g = s / radius
    return (radius + h) * np.sin(g), h * np.cos(g) - 2.0 * radius * np.sin(0.5 * g) ** 2


def divergence_factor(d1: ArrayLike, d2: ArrayLike, grazing: ArrayLike,
                      radius: float) -> NDArray[np.float64]:
    """Divergence factor D [-] of the reflection by the spherical Earth, eq (P3).

    Parameters
    ----------
    d1, d2 : array_like
        Ground distances from the antenna and from the point to the specular point [m].
    grazing : array_like
        Grazing angle psi at the specular point [rad].
    radius : float
        Effective Earth radius [m] (``numpy.inf``: D = 1).

    References
    ----------
    Kerr (1951), eq 2.5(9); Blake (1986), chapter 6.
    """
    d1, d2, psi = (np.asarray(a, dtype=np.float64) for a in (d1, d2, grazing))
    if np.isinf(radius):
        return np.ones(np.broadcast(d1, d2, psi).shape)
    num = 2.0 * d1 * d2
    den = radius * (d1 + d2) * np.sin(psi)
    with np.errstate(divide="ignore", invalid="ignore"):
        # Eq (P3); no spreading when a leg has zero length, total spreading at psi = 0
        q = np.where(num > 0, num / den, 0.0)
    return np.where(np.isfinite(q) & (q >= 0), 1.0 / np.sqrt(1.0 + np.abs(q)), 0.0)


def two_ray_geometry(h1: ArrayLike, h2: ArrayLike, d: ArrayLike, radius: float = np.inf
                     ) -> tuple[NDArray, NDArray, NDArray]:
    """Grazing angle psi [rad], path difference delta [m] and divergence factor D [-].

    Eqs (P2)-(P4) for an antenna at height h1 [m] and a point at height h2 [m] at
    ground distance d [m] over an Earth of radius ``radius`` [m] (``numpy.inf``: flat).
    Heights below the sea are taken as 0.
    """
    h1 = np.maximum(np.asarray(h1, dtype=np.float64), 0.0)
    h2 = np.maximum(np.asarray(h2, dtype=np.float64), 0.0)
    d = np.asarray(d, dtype=np.float64)
    d1 = reflection_point(h1, h2, d, radius)
    d2 = d - d1
    x1, y1 = _in_specular_frame(-d1, h1, radius)
    x2, y2 = _in_specular_frame(d2, h2, radius)
    r1, r2 = np.hypot(x1, y1), np.hypot(x2, y2)
    rd = np.hypot(x2 - x1, y2 - y1)
    if np.isinf(radius):  # exact, without cancellation: r_refl^2 - r_dir^2 = 4 h1 h2
        delta = 4.0 * h1 * h2 / np.maximum(r1 + r2 + rd, 1e-300)
    else:  # Eq (P4)
        delta = np.maximum(r1 + r2 - rd, 0.0)
    ok1, ok2 = r1 > 0, r2 > 0
    s1 = np.where(ok1, y1 / np.where(ok1, r1, 1.0), 0.0)
    s2 = np.where(ok2, y2 / np.where(ok2, r2, 1.0), 0.0)
    # The two legs' elevations seen from S (equal on a flat Earth)
    s = np.where(ok1 & ok2, 0.5 * (s1 + s2), np.where(ok1, s1, s2))
    psi = np.arcsin(np.clip(s, 0.0, 1.0))
    return psi, delta, divergence_factor(d1, d2, psi, radius)


def two_ray_factor(delta: ArrayLike, divergence: ArrayLike, gamma: ArrayLike,
                   wavelength: float) -> NDArray[np.complex128]:
    """Propagation factor F [-] of eq (P1): 1 + gamma D exp(-j 2 pi delta / lambda).

    Parameters
    ----------
    delta : array_like
        Path difference [m].
    divergence : array_like
        D [-].
    gamma : array_like of complex
        Reflection coefficient of the sea, roughness included (Gamma rho_s) [-].
    wavelength : float
        lambda [m].

    References
    ----------
    Blake (1986), eq 6.5; Kerr (1951), section 2.5.
    """
    delta = np.asarray(delta, dtype=np.float64)
    # Eq (P1)
    return 1.0 + np.asarray(gamma) * np.asarray(divergence) * np.exp(
        -2j * np.pi * delta / wavelength)


def illuminated_reflection(lam: ArrayLike, sigma_h: float, q: ArrayLike,
                           ceiling: ArrayLike = np.inf
                           ) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
    """Mean height of the reflecting (lit) points and their coherent factor, eqs (P5-P7).

    Parameters
    ----------
    lam : array_like
        Smith's Lambda of the legs [-] (:func:`seaecho.geometry.shadowing.smith_lambda`
        at the grazing angle), >= 0, finite; the legs' exponent is 2 Lambda.
    sigma_h : float
        Rms height of the (Gaussian) sea [m], >= 0.
    q : array_like
        Vertical wavenumber of the reflection 2 k sin psi [rad/m].
    ceiling : array_like
        Height of the point that receives the reflected wave [m] (eq P7: the reflecting
        points lie below it); ``inf``: a point far above the waves (eq P5).

    Returns
    -------
    zeta_bar : ndarray
        Mean height of the reflecting points [m] (0 for Lambda = 0).
    rho_ill : ndarray of complex
        Coherent reflection factor about zeta_bar [-]; exp(-q^2 sigma_h^2 / 2) (Ament)
        for Lambda = 0.

    References
    ----------
    Fabbro, Bourlier and Combes (2006); Bourlier, Pinel and Fabbro (2006); Smith (1967).
    """
    from scipy.special import log_ndtr, ndtri

    if not (np.isfinite(sigma_h) and sigma_h >= 0):
        raise ValueError(f"sigma_h = {sigma_h}: must be >= 0 [m]")
    lam, q, ceiling = np.broadcast_arrays(*(np.asarray(a, dtype=np.float64)
                                            for a in (lam, q, ceiling)))
    if np.any(~np.isfinite(lam) | (lam < 0)):
        raise ValueError("Lambda must be finite and >= 0 (a grazing angle > 0)")
    if sigma_h == 0.0:  # a flat sea: the mean sea reflects, smooth
        return np.zeros(lam.shape), np.ones(lam.shape, dtype=np.complex128)
    v, w = np.polynomial.legendre.leggauss(_N_GAUSS)
    v, w = 0.5 * (v + 1.0), 0.5 * w  # on (0, 1)
    m = (1.0 + 2.0 * lam)[..., None]
    # (P5, P7): v = (F(zeta) / F(ceiling))^m is uniform on (0, 1): F(zeta) = F_c v^(1/m)
    log_f = log_ndtr(ceiling / sigma_h)[..., None] + np.log(v) / m
    below = log_f < np.log(0.5)
    # the smaller of F and 1 - F (the latter accurate near the crests): one ndtri
    tail = np.where(below, np.exp(log_f), -np.expm1(log_f))
    zeta = sigma_h * np.where(below, 1.0, -1.0) * ndtri(tail)
    zeta_bar = zeta @ w  # (P6)
    dev = zeta - zeta_bar[..., None]
    sigma_ill = np.sqrt((dev * dev) @ w)  # spread of the lit heights [m]
    qs = np.broadcast_to(q, zeta_bar.shape)
    rough = qs * sigma_ill > _QSIGMA_MAX
    phase = np.where(rough, 0.0, qs)[..., None] * dev
    rho = np.cos(phase) @ w - 1j * (np.sin(phase) @ w)  # (P6)
    return zeta_bar, np.where(rough, 0.0, rho)


def heights_and_distance(a: ArrayLike, b: ArrayLike, radius: float
                         ) -> tuple[NDArray, NDArray, NDArray]:
    """Heights above the sea of Cartesian points a and b (..., 3) [m] and their ground
    distance [m]: z and the horizontal distance on a flat Earth (``radius`` inf); on the
    sphere (centre (0, 0, -R), ``seaecho.geometry.earth``) |P - C| - R and the
    great-circle distance R times the angle between P_a - C and P_b - C."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if np.isinf(radius):
        return (a[..., 2], b[..., 2],
                np.hypot(b[..., 0] - a[..., 0], b[..., 1] - a[..., 1]))
    c = np.array([0.0, 0.0, -radius])
    ua, ub = a - c, b - c
    na, nb = np.linalg.norm(ua, axis=-1), np.linalg.norm(ub, axis=-1)
    angle = np.arctan2(np.linalg.norm(np.cross(ua, ub), axis=-1), np.sum(ua * ub, axis=-1))
    return na - radius, nb - radius, radius * angle


@dataclass(frozen=True)
class TwoRay:
    """The sea as a mirror between the radar and its scatterers (module docstring).

    Attributes
    ----------
    wavelength : float
        Carrier wavelength lambda [m].
    eps_r : complex
        Sea-water relative permittivity at the carrier eps' - j eps'' [-].
    sigma_h : float
        Rms height of the sea [m] (Hs / 4, from the scene's spectrum).
    radius : float
        Effective Earth radius k a [m]; ``numpy.inf`` on a flat Earth.
    roughness : str
        Specular reduction model (:func:`seaecho.targets.multipath.specular_reduction`)
        without shadowing.
    slope_cov : ((float, float), (float, float)), optional
        Covariance of the sea's slopes (dz/dx, dz/dy) [-] in the simulation frame: the
        reflected legs are shadowed by the waves (eqs P5-P6, module docstring), and the
        roughness is that of the lit crests (``roughness`` is not used). None: no
        shadowing.
    """

    wavelength: float
    eps_r: complex
    sigma_h: float
    radius: float = np.inf
    roughness: str = "miller-brown-vegh"
    slope_cov: tuple[tuple[float, float], tuple[float, float]] | None = None

    def factors(self, antenna: ArrayLike, points: ArrayLike
                ) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """F_h, F_v [-] (eq P1) between an antenna at ``antenna`` (3,) and points (K, 3),
        Cartesian [m] in the simulation frame (the tangent frame on a sphere)."""
        h1, h2, d = heights_and_distance(antenna, points, self.radius)
        k = 2.0 * np.pi / self.wavelength
        if self.slope_cov is None:
            psi, delta, div = two_ray_geometry(h1, h2, d, self.radius)
            rho = specular_reduction(psi, self.sigma_h, k, self.roughness)
        else:  # the legs shadowed: the mirror at the lit crests' mean height (P5-P6)
            psi0, _, _ = two_ray_geometry(h1, h2, d, self.radius)
            a, b = np.asarray(antenna, dtype=np.float64), np.asarray(points, dtype=np.float64)
            azimuth = np.arctan2(a[..., 1] - b[..., 1], a[..., 0] - b[..., 0])
            sigma = directional_slope_std(np.asarray(self.slope_cov), azimuth)
            # a leg at grazing psi0 from the specular point towards the antenna (T1)
            theta = np.pi / 2 - np.maximum(psi0, 1e-9)
            lam = smith_lambda(smith_nu(theta, np.maximum(sigma, 1e-12)))
            zeta_bar, rho = illuminated_reflection(lam, self.sigma_h,
                                                   2.0 * k * np.sin(psi0), ceiling=h2)
            psi, delta, div = two_ray_geometry(h1 - zeta_bar, h2 - zeta_bar, d,
                                               self.radius)
        r_h, r_v = fresnel_coefficients(np.sin(psi), self.eps_r)
        return (two_ray_factor(delta, div, r_h * rho, self.wavelength),
                two_ray_factor(delta, div, r_v * rho, self.wavelength))

    def apply(self, s: ArrayLike, points: ArrayLike, tx: ArrayLike, rx: ArrayLike,
              monostatic: bool) -> NDArray[np.complex128]:
        """diag(F_r) S diag(F_t) of scattering amplitudes S (K, 2, 2) [m] in (h, v)
        order (p scattered, q incident) of points (K, 3) [m], transmitter at ``tx`` and
        receiver at ``rx`` (3,) [m]."""
        s = np.asarray(s, dtype=np.complex128)
        ft = np.stack(self.factors(tx, points), axis=-1)  # (K, 2): incident h, v
        fr = ft if monostatic else np.stack(self.factors(rx, points), axis=-1)
        return fr[:, :, None] * s * ft[:, None, :]
