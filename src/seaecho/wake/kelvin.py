"""Kelvin wake height field of a ship (paper section IV-B, eq 16) from thin-ship theory.

The far-field wave elevation behind the ship is the superposition of plane waves of
eq W4 (:mod:`seaecho.wake.michell`) with the Michell amplitude function of a Wigley hull
fitted to the ship's length, beam and draft (eqs W5, W7, W8). Each plane wave of angle
theta has wavenumber k0 sec^2(theta), k0 = g / V^2, so that it is steady in the ship's
frame; the transverse waves (theta = 0) have wavelength 2 pi V^2 / g and the divergent
waves lambda = 2 pi V^2 cos^2(theta) / g (paper section IV-B). Stationary phase of eq W4
puts the crests on the curves of paper eq 16 and confines the waves to the wedge of
half-angle asin(1/3) = 19.47 deg (see :func:`kelvin_crest_lines`).

Numerical evaluation
--------------------
*Discretisation of the theta integral.* Eq W4 is a line integral over the curve
k(theta) = k0 sec^2(theta) (cos theta, sin theta) in the wavenumber plane. It is sampled
at nodes evenly spaced in arc length s along that curve, with spacing

.. math::

    \\Delta s \\le \\frac{2\\pi}{\\gamma R_{max}}                              (W10)

where R_max bounds the distance from any hull point to any output point and gamma = 1.5.
By Poisson summation, the error of the trapezoidal sum is the same integral with the
extra phase exp(2 pi i m s / Delta s); since |dk/ds| = 1 its phase k(s) . r + 2 pi m s /
Delta s has no stationary point when |r| < 2 pi / Delta s, so the "ghost" wakes that a
coarse theta grid would create are pushed outside the output region. Sampling evenly in
arc length automatically refines theta near the cusp and at large theta, where
sec^2(theta) grows.

*Resolution limit.* The amplitude of the Wigley hull's divergent waves does not decay as
theta -> pi/2 (the waterline has a corner at the bow and stern), so the integral is cut at
the wavenumber the output grid can represent, k_c = 0.9 pi / max(dx, dy) by default, with
a raised-cosine taper over the last 30 % in k: unresolved short divergent waves are left
out, as the unresolved band of the sea spectrum is.

*Synthesis.* On a uniform grid, sum_j c_j exp(-i k_j . r) is a type-1 non-uniform FFT
(finufft), O(N log N + M); on any other rectilinear grid a separable matrix product
(exact). The ship's motion enters only as the phase exp(+i k_j . p(t)) of each
coefficient (eq W1): the wake is steady in the ship frame and translates with the ship.

*Near-field taper.* Eq W4 is the far-field (free-wave) part of the linear solution: it
omits the local, non-wave disturbance, and evaluated ahead of or alongside the hull it also
carries the mirror image of the wake (the stationary points of eq W4 at x' < 0). The field
is therefore multiplied by a window in the ship frame,

.. math::

    W(x') = \\tfrac12\\left[1 - \\cos\\left(\\pi\\,
        \\mathrm{clip}\\left(\\frac{x' + L/2}{L + \\lambda_0/2}, 0, 1\\right)\\right)\\right]  (W11)

which is 0 ahead of the bow (x' <= -L/2), 1 from half a transverse wavelength
lambda_0 = 2 pi / k0 behind the stern on, and smooth in between (C1), with its own
derivative carried into the slopes. The field is exact (to linear, far-field order)
where W = 1.

*Heights.* Thin-ship theory overpredicts the heights of real hulls (beamy ones above all)
and the Wigley form feeds short divergent waves of undiminished amplitude. With
``amplitude="kriebel-seelig"`` the plane-wave weights are scaled by one factor per ship
and grid so that the largest crest-to-trough height along the lines one ship length from
the track equals the empirical maximum height of Kriebel & Seelig (2005) there
(:mod:`seaecho.wake.empirical`, eq E1); the pattern (angles, wavelengths, phases) is
unchanged. With ``breaking_limit`` each plane wave's amplitude is capped so that the
wave train it forms, at its stationary-phase amplitude where it leaves the near field
(distance ``R = (L/2 + lambda_0/2) / cos alpha`` along its ray ``alpha``), is not steeper
than the breaking limit ``a k = pi 0.1412`` (eq E2):

.. math::

    a(\\theta) = |A(\\theta)| \\min\\left(\\sqrt{\\frac{2\\pi}{k_0 R |f_2|}},\\;
        2\\pi\\,\\mathrm{Ai}_{max}\\left(\\frac{2}{k_0 R |f_3|}\\right)^{1/3}\\right),
    \\quad f(\\vartheta) = \\sec^2\\vartheta\\cos(\\vartheta - \\alpha)      (W12b)

with ``f_2``, ``f_3`` the second and third derivatives of ``f`` at ``theta`` (stationary
phase of eq W4, and its Airy form at the cusp, ``Ai_max = 0.5357``).

*Time.* With p(t) from eq W1, z(r, t) = W(x') zeta(x', y') is steady in the ship frame, so

.. math::

    \\frac{\\partial z}{\\partial t} = -\\mathbf{V}\\cdot\\nabla z            (W12)

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] W. Thomson (Lord Kelvin), "On ship waves", Proc. Inst. Mech. Eng. 38, 409-434
   (1887).
.. [2] J. N. Newman, *Marine Hydrodynamics*, MIT Press (1977), sections 6.16-6.19.
.. [3] J. H. Michell, "The wave resistance of a ship", Phil. Mag. 45, 106-123 (1898).
.. [4] E. O. Tuck, "Wave patterns and minimum wave resistance for high-speed vessels",
   Proc. 17th Symp. Naval Hydrodynamics, The Hague, 1-15 (1989).
.. [5] A. H. Barnett, J. Magland and L. af Klinteberg, "A parallel nonuniform fast
   Fourier transform library based on an 'exponential of semicircle' kernel", SIAM J.
   Sci. Comput. 41, C479-C504 (2019) (finufft).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import RHO_SEA_WATER, G
from ..warnings import SamplingWarning
from .empirical import BREAKING_SLOPE, kriebel_seelig_height
from .michell import (
    kelvin_wavenumber,
    transverse_wavelength,
    wigley_amplitude,
    wigley_wave_resistance,
)
from .ship import WAKE_AMPLITUDE_MODELS, Ship

#: Kelvin half-angle asin(1/3) [rad] (19.47 deg; the paper's 38.54 deg full cone is a typo
#: for 38.94 deg, see docs/wake.md).
KELVIN_HALF_ANGLE = float(np.arcsin(1.0 / 3.0))
#: Maximum of the Airy function Ai [-] (at x = -1.0188).
_AI_MAX = 0.5357


@dataclass(frozen=True)
class WakeFields:
    """Kelvin wake on a grid at one time; every array has shape (ny, nx).

    Attributes
    ----------
    elevation : ndarray
        Wake elevation z [m].
    slope_x, slope_y : ndarray
        dz/dx, dz/dy [-].
    dzdt : ndarray
        dz/dt [m/s] (eq W12).
    """

    elevation: NDArray[np.float64]
    slope_x: NDArray[np.float64]
    slope_y: NDArray[np.float64]
    dzdt: NDArray[np.float64]


def kelvin_crest_lines(
    n: float, speed: float, theta: ArrayLike, g: float = G
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Crest lines of the Kelvin wake in the ship frame (paper eq 16, corrected).

    .. math::

        x' = A \\cos\\theta \\left(1 - \\tfrac12 \\cos^2\\theta\\right), \\qquad
        y' = \\tfrac{A}{2} \\sin\\theta \\cos^2\\theta, \\qquad
        A = 2 n \\lambda_0 = \\frac{4 \\pi n V^2}{g}                         (16)

    These are the lines of constant stationary phase 2 pi n of eq W4 (Newman 1977,
    section 6.17; Lamb 1932, art. 256). The paper prints y = (A/2) sin(theta) cos(theta); the
    extra cos(theta) is needed for the stationary-phase curves, whose envelope
    y'/x' = tan(theta)/(1 + 2 tan^2 theta) peaks at tan(theta) = 1/sqrt(2) with
    y'/x' = 1/sqrt(8), i.e. the half-angle asin(1/3) = 19.47 deg. At theta = 0 the
    crest is at x' = n lambda_0: transverse crests one wavelength 2 pi V^2 / g apart.

    Parameters
    ----------
    n : float
        Crest index (phase / 2 pi) [-].
    speed : float
        Ship speed V > 0 [m/s].
    theta : array_like
        Wave angle, |theta| <= pi/2 [rad]; the sign selects the side (y' sign).
    g : float
        Acceleration of gravity [m/s^2].

    Returns
    -------
    x, y : ndarray
        Ship-frame coordinates of the crest, behind the point source [m].

    References
    ----------
    Paper eq 16; Newman (1977) section 6.17; H. Lamb, *Hydrodynamics* (1932) art. 256.
    """
    theta = np.asarray(theta, dtype=np.float64)
    a = 2.0 * n * transverse_wavelength(speed, g)  # 4 pi n V^2 / g
    c = np.cos(theta)
    # Eq 16 (with the cos^2 in y')
    return a * c * (1.0 - 0.5 * c**2), 0.5 * a * np.sin(theta) * c**2


def _arc_speed(theta: NDArray[np.float64], k0: float) -> NDArray[np.float64]:
    """|dk/dtheta| along k = k0 sec^2(theta) (cos theta, sin theta) [rad/m per rad]."""
    sec = 1.0 / np.cos(theta)
    tan = np.tan(theta)
    # dk/dtheta = k0 (sec tan, sec tan^2 + sec^3)
    return k0 * sec * np.sqrt(tan**2 + (tan**2 + sec**2) ** 2)


@lru_cache(maxsize=32)
def _nodes(
    k0: float, k_cut: float, ds: float, taper_fraction: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Theta nodes evenly spaced in arc length, and their weights dtheta * taper."""
    theta_c = float(np.arccos(np.sqrt(k0 / k_cut)))
    # fine parametrisation, refined towards +-theta_c where the curve lengthens
    u_c = np.arcsinh(np.tan(theta_c))
    u = np.linspace(-u_c, u_c, 8193)
    th = np.arctan(np.sinh(u))
    speed = _arc_speed(th, k0) / np.cosh(u)  # ds/du
    s = np.concatenate(([0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(u))))
    n = max(int(np.ceil(s[-1] / ds)) + 1, 3)
    s_nodes = np.linspace(0.0, s[-1], n)
    theta = np.interp(s_nodes, s, th)
    dtheta = (s_nodes[1] - s_nodes[0]) / _arc_speed(theta, k0)
    # raised-cosine taper over the last taper_fraction of the band in k
    k = k0 / np.cos(theta) ** 2
    k_lo = (1.0 - taper_fraction) * k_cut
    ramp = np.clip((k - k_lo) / max(k_cut - k_lo, 1e-300), 0.0, 1.0)
    taper = 0.5 * (1.0 + np.cos(np.pi * ramp))
    return theta, dtheta * taper


def _uniform_spacing(v: NDArray[np.float64]) -> float | None:
    """Spacing of a uniform, increasing 1-D grid, or None."""
    if v.size < 2:
        return None
    d = np.diff(v)
    if d[0] <= 0 or not np.allclose(d, d[0], rtol=1e-9, atol=1e-12 * abs(d[0])):
        return None
    return float(d[0])


class KelvinWake:
    """Kelvin wake of a ship from Michell's thin-ship theory (eqs W4-W12, paper eq 16).

    Parameters
    ----------
    ship : Ship
        The ship; its hull is modelled as the Wigley hull (eq W7) of the same L, B, T.
    k_max : float or None
        Largest wavenumber kept [rad/m]; None (default) takes 0.9 pi / max(dx, dy) of the
        output grid. The grid's own limit always applies.
    taper_fraction : float
        Fraction of the band [0, k_max] over which the amplitude is tapered to zero [-].
    ghost_margin : float
        gamma of eq W10 [-], > 1.
    max_nodes : int
        Upper bound on the number of plane waves; above it a SamplingWarning is issued and
        the arc-length spacing is relaxed (ghost wakes may then enter the grid).
    eps : float
        Relative tolerance of the non-uniform FFT [-].
    nthreads : int or None
        Threads of the non-uniform FFT; None lets finufft use every core. One thread is
        the default: on a small, shared machine it was 2x faster than two (benchmark).
    g : float
        Acceleration of gravity [m/s^2].
    amplitude : {"kriebel-seelig", "michell"} or None
        Heights from Michell's theory as they are, or scaled to the empirical maximum
        height of Kriebel & Seelig (2005) one ship length from the track (see the
        module docstring). None takes ``ship.wake_amplitude``.
    breaking_limit : bool or None
        Cap each plane wave at the breaking steepness (eq W12b). None takes
        ``ship.wake_breaking_limit``.

    Notes
    -----
    Thin-ship theory assumes B/L small (and T/L small); the paper's 10 m motor boat
    (B/L = 0.4) is well outside that range, and Michell's heights for it are 4-5 times the
    empirical ones (docs/wake.md). The shape of the pattern (angles, wavelengths) does not
    depend on the hull model nor on the amplitude scaling.
    """

    def __init__(
        self,
        ship: Ship,
        *,
        k_max: float | None = None,
        taper_fraction: float = 0.3,
        ghost_margin: float = 1.5,
        max_nodes: int = 40000,
        eps: float = 1e-7,
        nthreads: int | None = 1,
        g: float = G,
        amplitude: str | None = None,
        breaking_limit: bool | None = None,
    ) -> None:
        if k_max is not None and not k_max > 0:
            raise ValueError(f"k_max = {k_max!r} rad/m: must be > 0")
        if not 0.0 < taper_fraction < 1.0:
            raise ValueError(f"taper_fraction = {taper_fraction!r}: must be in (0, 1)")
        if not ghost_margin > 1.0:
            raise ValueError(f"ghost_margin = {ghost_margin!r}: must be > 1")
        self.ship = ship
        self.k_max = k_max
        self.taper_fraction = float(taper_fraction)
        self.ghost_margin = float(ghost_margin)
        self.max_nodes = int(max_nodes)
        self.eps = float(eps)
        self.nthreads = nthreads
        self.g = float(g)
        self.k0 = kelvin_wavenumber(ship.speed, g)
        self.amplitude_model = ship.wake_amplitude if amplitude is None else amplitude
        if self.amplitude_model not in WAKE_AMPLITUDE_MODELS:
            raise ValueError(f"amplitude = {self.amplitude_model!r}: choose from "
                             f"{WAKE_AMPLITUDE_MODELS}")
        self.breaking_limit = (ship.wake_breaking_limit if breaking_limit is None
                               else bool(breaking_limit))
        self._factors: dict = {}
        self._waves: dict = {}

    # -- physics --------------------------------------------------------------------
    @property
    def transverse_wavelength(self) -> float:
        """lambda_0 = 2 pi V^2 / g [m] (paper section IV-B)."""
        return transverse_wavelength(self.ship.speed, self.g)

    def divergent_wavelength(self, theta: ArrayLike) -> NDArray[np.float64]:
        """lambda(theta) = 2 pi V^2 cos^2(theta) / g [m] (paper section IV-B)."""
        return self.transverse_wavelength * np.cos(np.asarray(theta, dtype=np.float64)) ** 2

    def amplitude(self, theta: ArrayLike) -> NDArray[np.complex128]:
        """Free-wave amplitude function A(theta) [m] (eqs W5, W8) of the ship's hull."""
        s = self.ship
        return wigley_amplitude(theta, s.length, s.beam, s.draft, s.speed, self.g)

    def wave_resistance(self, rho: float = RHO_SEA_WATER) -> float:
        """Michell wave resistance R_w [N] of the fitted hull (eq W6)."""
        s = self.ship
        if s.speed == 0:
            return 0.0
        return wigley_wave_resistance(s.length, s.beam, s.draft, s.speed, rho, self.g)

    def near_field_window(self, xs: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Window W(x') of eq W11 and its derivative dW/dx' [1/m].

        Parameters
        ----------
        xs : array_like
            Distance behind midship along the track x' [m].
        """
        xs = np.asarray(xs, dtype=np.float64)
        x_a = -0.5 * self.ship.length
        span = self.ship.length + 0.5 * self.transverse_wavelength
        s = (xs - x_a) / span
        # W = 0 ahead (s <= 0, cos 0 = 1) and 1 behind (s >= 1, cos pi = -1 exactly): the
        # trigonometric functions are evaluated on the transition band only
        w = (s >= 1.0).astype(np.float64)
        dw = np.zeros(s.shape)
        inside = (s > 0.0) & (s < 1.0)
        band = s[inside]
        # Eq W11
        w[inside] = 0.5 * (1.0 - np.cos(np.pi * band))
        dw[inside] = 0.5 * np.pi / span * np.sin(np.pi * band)
        return w, dw

    # -- synthesis ------------------------------------------------------------------
    def plane_waves(
        self, k_cut: float, r_max: float
    ) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
        """Ship-frame plane waves of eq W4: angles and complex weights A(theta) dtheta.

        Parameters
        ----------
        k_cut : float
            Largest wavenumber [rad/m] (> k0).
        r_max : float
            Largest distance from a hull point to an output point [m] (eq W10).

        Returns
        -------
        theta : ndarray, shape (M,)
            Wave angles [rad].
        weights : ndarray of complex, shape (M,)
            A(theta_j) * dtheta_j * taper_j [m].
        """
        ds = 2.0 * np.pi / (self.ghost_margin * r_max)
        # arc length of the curve up to k_cut, to bound the node count (Eq W10)
        theta_c = np.arccos(np.sqrt(self.k0 / k_cut))
        th = np.linspace(-theta_c, theta_c, 4001)
        length = float(np.trapezoid(_arc_speed(th, self.k0), th))
        if length / ds > self.max_nodes:
            warnings.warn(
                f"the Kelvin wake needs {int(length / ds)} plane waves to be free of ghost "
                f"images over {r_max:.0f} m; using {self.max_nodes}: ghost wakes may appear "
                "far from the ship (reduce the grid extent or the ship's distance)",
                SamplingWarning,
                stacklevel=3,
            )
            ds = length / self.max_nodes
        # quantise ds (cache key) to 1/64 octave steps downwards
        ds = float(2.0 ** (np.floor(64.0 * np.log2(ds)) / 64.0))
        key = (float(k_cut), ds)
        if key not in self._waves:  # the ship's, the grid's and ds's: kept per key
            theta, dtheta = _nodes(float(self.k0), float(k_cut), ds, self.taper_fraction)
            weights = self.amplitude(theta) * dtheta
            if self.amplitude_model == "kriebel-seelig":
                weights = weights * self.empirical_factor(k_cut)
            if self.breaking_limit:
                weights = weights * self.breaking_factor(theta, weights)
            if len(self._waves) >= 16:
                self._waves.pop(next(iter(self._waves)))
            self._waves[key] = (theta, weights)
        theta, weights = self._waves[key]
        return theta.copy(), weights.copy()

    def line_height(self, theta: NDArray, weights: NDArray, y: float, k_cut: float) -> float:
        """Largest crest-to-trough height of eq W4 along the lines y' = +-y [m].

        The lines run from the end of the near field (x' = L/2 + lambda_0/2) past the
        cusp (x' = y cot 19.47 deg) by eight transverse wavelengths, sampled at four
        points per shortest wavelength 2 pi / k_cut.

        Parameters
        ----------
        theta, weights : ndarray
            Plane waves (angles [rad], weights [m]).
        y : float
            Distance from the track [m].
        k_cut : float
            Band limit [rad/m].
        """
        import finufft

        lam0 = self.transverse_wavelength
        x0 = 0.5 * self.ship.length + 0.5 * lam0
        x1 = x0 + y / np.tan(KELVIN_HALF_ANGLE) + 8.0 * lam0
        step = 0.5 * np.pi / k_cut
        n = len(np.arange(x0, x1, step))  # the dense sum's sample count, as arange rounds
        kappa = self.k0 / np.cos(theta) ** 2
        kx, ky = kappa * np.cos(theta), kappa * np.sin(theta)
        # Eq W4 on the line x'_n = x0 + n step (ship frame) is a type-1 non-uniform FFT:
        # sum_j w_j e^{-i (x0 kx_j + y' ky_j)} e^{-i n p_j} with p_j = step kx_j (|p_j| <=
        # pi / 2 below the band limit); finufft's modes m = n - n // 2 take the factor
        # e^{-i (n // 2) p_j} into the strengths.
        p = step * kx
        h = 0.0
        for side in (1.0, -1.0):
            c = weights * np.exp(-1j * (x0 * kx + side * y * ky + (n // 2) * p))
            z = finufft.nufft1d1(p, c, n_modes=n, eps=1e-12, isign=-1, nthreads=1).real
            h = max(h, float(z.max() - z.min()))
        return h

    def empirical_factor(self, k_cut: float) -> float:
        """Scale that makes the height one ship length from the track that of eq E1 [-].

        Michell's height is measured on the lines y' = +-L of the band-limited field
        (:meth:`line_height`, plane waves ghost-free over those lines); cached per
        ``k_cut``.

        Parameters
        ----------
        k_cut : float
            Band limit of the synthesis [rad/m].

        References
        ----------
        Kriebel & Seelig (2005) (:func:`seaecho.wake.empirical.kriebel_seelig_height`).
        """
        key = float(k_cut)
        if key not in self._factors:
            s = self.ship
            lam0 = self.transverse_wavelength
            r_line = (0.5 * s.length + 0.5 * lam0 + s.length / np.tan(KELVIN_HALF_ANGLE)
                      + 8.0 * lam0 + 1.5 * s.length)
            ds = float(2.0 ** (np.floor(64.0 * np.log2(2.0 * np.pi / (self.ghost_margin
                                                                         * r_line))) / 64.0))
            theta, dtheta = _nodes(float(self.k0), key, ds, self.taper_fraction)
            h_michell = self.line_height(theta, self.amplitude(theta) * dtheta, s.length, key)
            h_emp = float(kriebel_seelig_height(s.length, s.speed, s.length, g=self.g))
            self._factors[key] = h_emp / h_michell if h_michell > 0.0 else 0.0
        return self._factors[key]

    def breaking_factor(self, theta: NDArray, weights: NDArray) -> NDArray:
        """Per-wave cap at the breaking steepness ``a k <= pi 0.1412`` (eq W12b) [-].

        Parameters
        ----------
        theta, weights : ndarray
            Plane-wave angles [rad] and weights A dtheta [m] (evenly spaced in arc
            length, so ``|A| = |weights| / gradient(theta)``).

        Returns
        -------
        ndarray
            Factors in (0, 1].

        References
        ----------
        Williams (1981); Michell (1893); stationary phase of eq W4 (Newman 1977, 6.17).
        """
        th = np.asarray(theta, dtype=float)
        if th.size < 3:
            return np.ones(th.shape)
        amp = np.abs(weights) / np.abs(np.gradient(th))
        # ray of stationary phase of each wave (Kelvin): tan a = tan t / (1 + 2 tan^2 t)
        t = np.tan(th)
        alpha = np.arctan(t / (1.0 + 2.0 * t * t))
        r = (0.5 * self.ship.length + 0.5 * self.transverse_wavelength) / np.cos(alpha)

        def f(v):
            return np.cos(v - alpha) / np.cos(v) ** 2

        h = 1e-3
        f2 = (f(th + h) - 2.0 * f(th) + f(th - h)) / h**2
        f3 = (f(th + 2 * h) - 2.0 * f(th + h) + 2.0 * f(th - h) - f(th - 2 * h)) / (2.0 * h**3)
        kr = self.k0 * r
        # Eq W12b: stationary-phase amplitude, bounded by its Airy form at the cusp.
        sp = np.sqrt(2.0 * np.pi / (kr * np.maximum(np.abs(f2), 1e-300)))
        airy = 2.0 * np.pi * _AI_MAX * (2.0 / (kr * np.maximum(np.abs(f3), 1e-300))) ** (1 / 3)
        k = self.k0 / np.cos(th) ** 2
        slope = k * amp * np.minimum(sp, airy)
        return np.minimum(1.0, BREAKING_SLOPE / np.maximum(slope, 1e-300))

    def fields(
        self, x: ArrayLike, y: ArrayLike, t: float = 0.0, method: str = "auto"
    ) -> WakeFields:
        """Wake elevation, slopes and dz/dt on the grid (x, y) at time t (eqs W4-W12).

        Parameters
        ----------
        x : array_like, shape (nx,)
            Increasing x coordinates (east) [m].
        y : array_like, shape (ny,)
            Increasing y coordinates (north) [m].
        t : float
            Time [s]; the ship is at ``ship.position(t)``.
        method : {"auto", "nufft", "direct"}
            "nufft" needs uniform grids; "direct" (separable matrix product) works on any
            rectilinear grid; "auto" picks "nufft" when it can.

        Returns
        -------
        WakeFields
            Arrays of shape (ny, nx).
        """
        x = np.asarray(x, dtype=np.float64)
        y = np.asarray(y, dtype=np.float64)
        if x.ndim != 1 or y.ndim != 1 or x.size == 0 or y.size == 0:
            raise ValueError("x and y must be non-empty 1-D coordinate arrays [m]")
        if method not in ("auto", "nufft", "direct"):
            raise ValueError(f"method = {method!r}: must be 'auto', 'nufft' or 'direct'")
        shape = (y.size, x.size)
        zero = np.zeros(shape)
        if self.ship.speed == 0.0:
            return WakeFields(zero, zero.copy(), zero.copy(), zero.copy())

        dx, dy = _uniform_spacing(x), _uniform_spacing(y)
        uniform = dx is not None and dy is not None
        if method == "nufft" and not uniform:
            raise ValueError("method='nufft' needs uniformly spaced, increasing x and y")
        if method == "auto":
            method = "nufft" if uniform and x.size >= 4 and y.size >= 4 else "direct"

        # resolution limit of the grid
        spacings = [abs(d) for d in (dx, dy) if d is not None]
        if not spacings:
            spacings = [float(np.median(np.diff(v))) for v in (x, y) if v.size > 1]
        k_grid = 0.9 * np.pi / max(spacings) if spacings else np.inf
        k_cut = min(self.k_max, k_grid) if self.k_max is not None else k_grid
        if not np.isfinite(k_cut):
            raise ValueError("a single grid point needs k_max to be given")
        if k_cut <= self.k0 / (1.0 - self.taper_fraction):
            warnings.warn(
                f"the grid cannot resolve the Kelvin wake: its cut-off wavenumber "
                f"{k_cut:.3g} rad/m leaves no untapered band above the transverse "
                f"wavenumber {self.k0:.3g} rad/m (wavelength {self.transverse_wavelength:.3g} "
                f"m; needs > {self.k0 / (1.0 - self.taper_fraction):.3g} rad/m); the wake "
                "is left out",
                SamplingWarning,
                stacklevel=2,
            )
            return WakeFields(zero, zero.copy(), zero.copy(), zero.copy())

        # the window (eq W11) is zero ahead of the bow: nothing to synthesise there. A
        # ship on a route: the steady pattern of its course at t (quasi-steady, docs/wake.md)
        ship = self.ship.at(t)
        h = ship.heading
        xs, _ = ship.to_ship_frame(x[None, :], y[:, None], t)
        if np.all(xs <= -0.5 * self.ship.length):
            return WakeFields(zero, zero.copy(), zero.copy(), zero.copy())

        p = ship.position(t)
        corners_x = np.array([x[0], x[-1], x[0], x[-1]]) - p[0]
        corners_y = np.array([y[0], y[0], y[-1], y[-1]]) - p[1]
        r_max = float(np.max(np.hypot(corners_x, corners_y))) + 0.5 * self.ship.length
        theta, weights = self.plane_waves(k_cut, max(r_max, self.ship.length))

        # world wavevectors of eq W4: k = -k0 sec^2(theta) (h_hat cos theta + n_hat sin theta)
        kappa = self.k0 / np.cos(theta) ** 2
        kx = -kappa * (np.cos(h) * np.cos(theta) - np.sin(h) * np.sin(theta))
        ky = -kappa * (np.sin(h) * np.cos(theta) + np.cos(h) * np.sin(theta))
        # translation with the ship (eq W1): exp(-i k.(r - p)) = exp(+i k.p) exp(-i k.r)
        c = weights * np.exp(1j * (kx * p[0] + ky * p[1]))
        coeffs = np.stack([c, -1j * kx * c, -1j * ky * c])

        if method == "nufft":
            z, zx, zy = self._synth_nufft(coeffs, kx, ky, x, y, dx, dy)
        else:
            z, zx, zy = self._synth_direct(coeffs, kx, ky, x, y)

        # near-field window (eq W11) in the ship frame, with its gradient
        w, dw = self.near_field_window(xs)
        wx, wy = -np.cos(h) * dw, -np.sin(h) * dw  # dx'/dx = -cos h, dx'/dy = -sin h
        elevation = w * z
        slope_x = wx * z + w * zx
        slope_y = wy * z + w * zy
        vx, vy = ship.velocity
        # Eq W12
        dzdt = -(vx * slope_x + vy * slope_y)
        return WakeFields(elevation, slope_x, slope_y, dzdt)

    def _synth_nufft(self, coeffs, kx, ky, x, y, dx, dy):
        """Re sum_j c_j exp(-i k_j . r) of three coefficient sets on a uniform grid by
        two type-1 NUFFTs.

        Two real fields travel as one complex one: with the plane waves and their
        mirrors (-k_j, conjugate weights), ``sum_j [(a_j + i b_j) e^(-i k_j.r)
        + (a_j^* + i b_j^*) e^(+i k_j.r)] / 2 = Re A(r) + i Re B(r)``, so the elevation
        and the x slope come out of one transform (2M points, which cost little next to
        the transform's FFT) and the y slope out of a second.
        """
        import finufft

        nx, ny = x.size, y.size
        # grid point i <-> mode m = i - n//2 (finufft CMCL order): r = r_c + m d
        xc, yc = x[nx // 2], y[ny // 2]
        a, b, c = coeffs * np.exp(-1j * (kx * xc + ky * yc))[None, :]
        packed = np.stack([np.concatenate([a + 1j * b, np.conj(a) + 1j * np.conj(b)]),
                           np.concatenate([c, np.conj(c)])]) * 0.5
        out = finufft.nufft2d1(
            np.concatenate([ky * dy, -ky * dy]),
            np.concatenate([kx * dx, -kx * dx]),
            packed,
            (ny, nx),
            isign=-1,
            eps=self.eps,
            **({} if self.nthreads is None else {"nthreads": int(self.nthreads)}),
        )
        return out[0].real, out[0].imag, out[1].real

    @staticmethod
    def _synth_direct(coeffs, kx, ky, x, y, chunk: int = 2048):
        """Re sum_j c_j exp(-i k_j . r) on a rectilinear grid (separable, exact)."""
        out = np.zeros((3, y.size, x.size))
        for j0 in range(0, kx.size, chunk):
            sl = slice(j0, j0 + chunk)
            ex = np.exp(-1j * np.outer(kx[sl], x))  # (m, nx)
            ey = np.exp(-1j * np.outer(ky[sl], y))  # (m, ny)
            for i in range(3):
                out[i] += ((ey * coeffs[i, sl, None]).T @ ex).real
        return out[0], out[1], out[2]


__all__ = ["KELVIN_HALF_ANGLE", "KelvinWake", "WakeFields", "kelvin_crest_lines",
           "kelvin_wavenumber", "transverse_wavelength"]
