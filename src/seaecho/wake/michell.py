"""Michell's thin-ship theory: the free-wave amplitude (Kochin) function of a hull.

The linearised steady flow past a thin ship, in the ship frame (water streaming at speed
V in +x', x' pointing behind the ship, z up, mean free surface z = 0), is that of a sheet
of sources on the centreplane y' = 0 with strength per unit area

.. math::

    \\sigma(x', z) = 2 V \\frac{\\partial f}{\\partial x'}(x', z)               (W3)

(the jump of dphi/dy' across the sheet that makes the hull y' = +-f(x', z) a streamline;
Michell 1898; Newman 1977, section 6.19). Far behind the ship the free-surface elevation
is a superposition of plane waves travelling at angle theta to the track, each steady in
the ship frame, so of wavenumber k0 sec^2(theta) with k0 = g/V^2:

.. math::

    \\zeta(x', y') = \\mathrm{Re} \\int_{-\\pi/2}^{\\pi/2} A(\\theta)
        \\exp\\left[-i k_0 \\sec^2\\theta\\,(x'\\cos\\theta + y'\\sin\\theta)\\right]
        d\\theta                                                            (W4)

(Newman 1977, section 6.18). Solving the linear free-surface problem for a unit source
at depth h (Fourier transform in x', y'; the pole of the free-surface condition taken with
the radiation condition, waves only downstream) gives the contribution
(k0 m / (pi V)) sec^3(theta) exp(-k0 h sec^2 theta) exp(i k0 sec(theta) x_s) of a source
of volume flux m [m^3/s] at (x_s, 0, -h); summing eq W3 over the centreplane:

.. math::

    A(\\theta) = \\frac{2 k_0}{\\pi} \\sec^3\\theta\\,
        \\iint_{\\mathrm{CP}} \\frac{\\partial f}{\\partial x'}
        \\exp\\left(k_0 \\sec^2\\theta\\, z + i k_0 \\sec\\theta\\, x'\\right)
        dx'\\,dz                                                            (W5)

The wave resistance follows from the energy flux of eq W4 (Havelock 1934; Newman 1977,
section 6.18):

.. math::

    R_w = \\frac{\\pi}{2} \\rho V^2 \\int_{-\\pi/2}^{\\pi/2} |A(\\theta)|^2
        \\cos^3\\theta\\, d\\theta                                          (W6)

which, with eq W5, is Michell's integral
R_w = (4 rho g^2 / (pi V^2)) int_1^inf |P + iQ|^2 lambda^2 / sqrt(lambda^2 - 1) dlambda
(Michell 1898; Wehausen 1973, section 3), the classical published form used as a check.

Hull: the Wigley parabolic hull fitted to (L, B, T),

.. math::

    f(x', z) = \\frac{B}{2}\\left[1 - \\left(\\frac{2x'}{L}\\right)^2\\right]
        \\left[1 - \\left(\\frac{z}{T}\\right)^2\\right],
        \\quad |x'| \\le L/2,\\; -T \\le z \\le 0                          (W7)

(Wigley 1934), for which eq W5 has a closed form (eq W8 in :func:`wigley_amplitude`).

Symbols -> names: k0 ``k0``, theta ``theta``, A ``amplitude``, f ``half_breadth``,
rho ``rho``, V ``speed``, R_w ``wave_resistance``.

References
----------
.. [1] J. H. Michell, "The wave resistance of a ship", Phil. Mag. 45, 106-123 (1898).
.. [2] T. H. Havelock, "The calculation of wave resistance", Proc. R. Soc. A 144,
   514-521 (1934).
.. [3] W. C. S. Wigley, "A comparison of experiment and calculated wave-profiles and
   wave-resistances for a form having parabolic waterlines", Proc. R. Soc. A 144,
   144-159 (1934).
.. [4] J. V. Wehausen and E. V. Laitone, "Surface waves", Handbuch der Physik 9,
   446-778 (1960), section 13.
.. [5] J. V. Wehausen, "The wave resistance of ships", Adv. Appl. Mech. 13, 93-245
   (1973).
.. [6] J. N. Newman, *Marine Hydrodynamics*, MIT Press (1977), sections 6.16-6.19.
.. [7] E. O. Tuck, "Wave patterns and minimum wave resistance for high-speed vessels",
   Proc. 17th Symp. Naval Hydrodynamics, The Hague, 1-15 (1989).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import RHO_SEA_WATER, G

_SERIES_TERMS = 24


def kelvin_wavenumber(speed: float, g: float = G) -> float:
    """k0 = g / V^2 [rad/m]: the transverse waves' wavenumber (Lamb 1932, art. 256;
    Arnold-Bos et al. 2006, section IV-B).

    A wave steady in the frame of a ship of speed V travels at V: the gravity branch of the
    dispersion relation (capillarity is negligible at these wavelengths). ``inf`` for a
    ship at rest (no Kelvin wake).
    """
    return g / speed**2 if speed > 0 else math.inf


def transverse_wavelength(speed: float, g: float = G) -> float:
    """lambda_0 = 2 pi V^2 / g [m] of a ship of speed ``speed`` [m/s] (its
    transverse waves, Lamb 1932, art. 256)."""
    return 2.0 * math.pi / kelvin_wavenumber(speed, g)


def _depth_factor(beta: NDArray[np.float64]) -> NDArray[np.float64]:
    """int_0^1 (1 - s^2) exp(-beta s) ds [-] for beta >= 0, stable for small beta."""
    beta = np.asarray(beta, dtype=np.float64)
    out = np.empty_like(beta)
    small = beta < 1.0
    b = np.where(small, 1.0, beta)
    # closed form: 1/b - 2/b^3 + 2 exp(-b) (1/b^2 + 1/b^3)
    out[~small] = (1.0 / b - 2.0 / b**3 + 2.0 * np.exp(-b) * (1.0 / b**2 + 1.0 / b**3))[~small]
    if np.any(small):
        bs = beta[small]
        acc = np.zeros_like(bs)
        term = np.ones_like(bs)  # (-beta)^n / n!
        for n in range(_SERIES_TERMS):
            acc += term * 2.0 / ((n + 1.0) * (n + 3.0))
            term = term * (-bs) / (n + 1.0)
        out[small] = acc
    return out


def _sin_minus_ucos(u: NDArray[np.float64]) -> NDArray[np.float64]:
    """sin(u) - u cos(u) [-], stable for small u (series u^3/3 - u^5/30 + ...)."""
    u = np.asarray(u, dtype=np.float64)
    small = np.abs(u) < 0.1
    us = np.where(small, u, 0.0)
    series = us**3 / 3.0 - us**5 / 30.0 + us**7 / 840.0 - us**9 / 45360.0
    return np.where(small, series, np.sin(u) - u * np.cos(u))


def wigley_amplitude(
    theta: ArrayLike, length: float, beam: float, draft: float, speed: float, g: float = G
) -> NDArray[np.complex128]:
    """Free-wave amplitude function A(theta) of a Wigley hull (eqs W5, W7, W8).

    With a = k0 sec(theta), b = k0 sec^2(theta), u = a L / 2 and beta = b T, the
    centreplane integral of eq W5 over the hull of eq W7 separates:

    .. math::

        A(\\theta) = -\\frac{2 k_0}{\\pi}\\sec^3\\theta\\,\\frac{4B}{L^2}\\,
            \\frac{2i\\,(\\sin u - u\\cos u)}{a^2}\\;
            T\\!\\int_0^1 (1 - s^2) e^{-\\beta s} ds                          (W8)

    The amplitude is purely imaginary and even in theta (fore-aft symmetric hull).

    Parameters
    ----------
    theta : array_like
        Wave angle to the track, |theta| < pi/2 [rad].
    length, beam, draft : float
        Waterline length L, beam B, draft T of the fitted Wigley hull [m].
    speed : float
        Ship speed V > 0 [m/s].
    g : float
        Acceleration of gravity [m/s^2].

    Returns
    -------
    ndarray of complex
        A(theta) [m] (elevation per radian of theta), same shape as ``theta``.

    References
    ----------
    Michell (1898); Wigley (1934); Newman (1977) section 6.19 (see module docstring).
    """
    if speed <= 0.0:
        raise ValueError(f"speed = {speed!r} m/s: the amplitude function needs speed > 0")
    theta = np.asarray(theta, dtype=np.float64)
    if np.any(np.abs(theta) >= np.pi / 2):
        raise ValueError("theta must lie strictly inside (-pi/2, pi/2) [rad]")
    k0 = kelvin_wavenumber(speed, g)
    sec = 1.0 / np.cos(theta)
    a = k0 * sec  # longitudinal wavenumber k0 sec(theta) [rad/m]
    b = k0 * sec**2  # decay rate with depth k0 sec^2(theta) [1/m]
    # Eq W8: x' integral  int x' exp(i a x') dx' = 2 i (sin u - u cos u) / a^2
    x_int = 2j * _sin_minus_ucos(a * length / 2.0) / a**2
    # Eq W8: z integral  int (1 - z^2/T^2) exp(b z) dz = T int_0^1 (1 - s^2) exp(-bT s) ds
    z_int = draft * _depth_factor(b * draft)
    # Eq W5 with df/dx' = -(4 B / L^2) x' (1 - z^2/T^2)
    return (2.0 * k0 / np.pi) * sec**3 * (-4.0 * beam / length**2) * x_int * z_int


def submerged_source_amplitude(
    theta: ArrayLike, strength: float, depth: float, speed: float, g: float = G
) -> NDArray[np.complex128]:
    """Free-wave amplitude function A(theta) of a submerged point source (eq W5 kernel).

    .. math::

        A(\\theta) = \\frac{k_0 m}{\\pi V}\\sec^3\\theta\\, e^{-k_0 h \\sec^2\\theta}   (W9)

    Parameters
    ----------
    theta : array_like
        Wave angle to the track [rad].
    strength : float
        Volume flux m of the source [m^3/s] (potential -m / (4 pi r)).
    depth : float
        Submergence h > 0 [m].
    speed : float
        Speed V > 0 [m/s].
    g : float
        Acceleration of gravity [m/s^2].

    Returns
    -------
    ndarray of complex
        A(theta) [m].

    References
    ----------
    Havelock (1932), "The theory of wave resistance", Proc. R. Soc. A 138, 339-348;
    Wehausen & Laitone (1960) section 13.
    """
    theta = np.asarray(theta, dtype=np.float64)
    k0 = kelvin_wavenumber(speed, g)
    sec = 1.0 / np.cos(theta)
    # Eq W9
    return (k0 * strength / (np.pi * speed) * sec**3 * np.exp(-k0 * depth * sec**2)).astype(
        np.complex128
    )


def havelock_wave_resistance(
    theta: ArrayLike,
    amplitude: ArrayLike,
    speed: float,
    rho: float = RHO_SEA_WATER,
) -> float:
    """Wave resistance from a tabulated amplitude function (Havelock's formula, eq W6).

    Parameters
    ----------
    theta : array_like
        Increasing wave angles covering (-pi/2, pi/2) [rad], shape (n,).
    amplitude : array_like
        A(theta) [m] at ``theta``, shape (n,).
    speed : float
        Ship speed V [m/s].
    rho : float
        Water density [kg/m^3].

    Returns
    -------
    float
        Wave resistance R_w [N] (trapezoidal rule in theta).

    References
    ----------
    Havelock (1934); Newman (1977) section 6.18.
    """
    theta = np.asarray(theta, dtype=np.float64)
    amp = np.asarray(amplitude)
    # Eq W6
    integrand = np.abs(amp) ** 2 * np.cos(theta) ** 3
    return float(0.5 * np.pi * rho * speed**2 * np.trapezoid(integrand, theta))


def wigley_wave_resistance(
    length: float,
    beam: float,
    draft: float,
    speed: float,
    rho: float = RHO_SEA_WATER,
    g: float = G,
    n_theta: int = 20001,
) -> float:
    """Michell wave resistance of the Wigley hull of eq W7, through eqs W6 and W8.

    The theta integral is taken in u = sinh^-1(tan theta) on a uniform grid, which
    removes the crowding of the integrand near theta = +-pi/2.

    Parameters
    ----------
    length, beam, draft : float
        L, B, T [m].
    speed : float
        V > 0 [m/s].
    rho : float
        Water density [kg/m^3].
    g : float
        Acceleration of gravity [m/s^2].
    n_theta : int
        Number of quadrature nodes.

    Returns
    -------
    float
        R_w [N].

    References
    ----------
    Michell (1898); Havelock (1934); Newman (1977) section 6.19.
    """
    # tan(theta) = sinh(u), dtheta = du / cosh(u); the integrand |A|^2 cos^3 decays like
    # sec^-3 at large u (A bounded), so u up to 12 covers it to double precision.
    u = np.linspace(-12.0, 12.0, n_theta)
    theta = np.arctan(np.sinh(u))
    amp = wigley_amplitude(theta, length, beam, draft, speed, g)
    integrand = np.abs(amp) ** 2 * np.cos(theta) ** 3 / np.cosh(u)
    # Eq W6
    return float(0.5 * np.pi * rho * speed**2 * np.trapezoid(integrand, u))


def wigley_wetted_surface(length: float, beam: float, draft: float, n: int = 201) -> float:
    """Wetted surface S of the Wigley hull of eq W7 [m^2] (both sides, exact surface area).

    Used to form the wave-resistance coefficient C_w = R_w / (rho V^2 S / 2).

    Parameters
    ----------
    length, beam, draft : float
        L, B, T [m].
    n : int
        Gauss-Legendre nodes per direction.
    """
    xg, wg = np.polynomial.legendre.leggauss(n)
    x = 0.5 * length * xg  # [-L/2, L/2]
    wx = 0.5 * length * wg
    z = -0.5 * draft * (xg + 1.0)  # [-T, 0]
    wz = 0.5 * draft * wg
    xx, zz = np.meshgrid(x, z, indexing="ij")
    fx = -(4.0 * beam / length**2) * xx * (1.0 - (zz / draft) ** 2)
    fz = 0.5 * beam * (1.0 - (2.0 * xx / length) ** 2) * (-2.0 * zz / draft**2)
    dA = np.sqrt(1.0 + fx**2 + fz**2)
    return float(2.0 * np.einsum("i,j,ij->", wx, wz, dA))


__all__ = [
    "havelock_wave_resistance",
    "kelvin_wavenumber",
    "submerged_source_amplitude",
    "transverse_wavelength",
    "wigley_amplitude",
    "wigley_wave_resistance",
    "wigley_wetted_surface",
]
