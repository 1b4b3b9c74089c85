"""Dispersion relation of linear surface waves (paper eq 15), with capillarity.

.. math::

    \\omega^2 = \\left(g K + \\frac{\\tau}{\\rho} K^3\\right) \\tanh(K d)        (15')

The paper's eq 15 is the gravity-wave form (tau = 0). The capillary term (Lamb 1932,
Hydrodynamics, art. 267) matters for the short waves that Bragg scattering sees; it is on
by default and changes the phase speed by (tau/rho) K^2 / (2 g): 0.5 % at K = 25 rad/m.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] H. Lamb, *Hydrodynamics*, 6th ed., Cambridge University Press, 1932, arts. 228, 267.
.. [2] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified directional
   spectrum for long and short wind-driven waves", J. Geophys. Res. 102(C7),
   15781-15796, 1997.
.. [3] O. M. Phillips, *The Dynamics of the Upper Ocean*, 2nd ed., Cambridge University
   Press, 1977, section 3.6 (waves on a current: the Doppler-shifted frequency).
.. [4] J. T. Kirby and T.-M. Chen, "Surface waves on vertically sheared flows:
   approximate dispersion relations", J. Geophys. Res. 94(C1), 1013-1027, 1989 (the
   depth-uniform current as their limiting case).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import SURFACE_TENSION_OVER_DENSITY, G

#: Wavenumber of the minimum phase speed k_m = sqrt(g rho / tau) [rad/m]: 369.8 rad/m, the
#: k_m = 370 rad/m of Elfouhaily et al. (1997) and the k_gamma of Kudryavtsev et al.
#: (2003), where gravity and surface tension restore the surface equally (eq 15').
CAPILLARY_WAVENUMBER = math.sqrt(G / SURFACE_TENSION_OVER_DENSITY)


def omega_squared_deep(k: Any, surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
                       g: float = G) -> Any:
    """omega^2 = g K + (tau/rho) K^3 of deep water [rad^2/s^2] (eq 15', tanh -> 1).

    The one place the restoring forces are written: plain arithmetic, so that it runs on
    numpy arrays and on the Dr.Jit arrays of a fused kernel alike (the Bragg lines of
    :mod:`seaecho.scattering.dynamics`).

    Parameters
    ----------
    k : array_like or Dr.Jit array
        Wavenumber modulus K >= 0 [rad/m].
    surface_tension : float
        Kinematic surface tension tau/rho [m^3/s^2].
    g : float
        Acceleration of gravity [m/s^2].
    """
    return k * (g + surface_tension * k * k)  # Eq. 15' restoring forces


def angular_frequency(
    k: ArrayLike,
    depth: float | None = None,
    surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
    g: float = G,
) -> NDArray[np.float64]:
    """Angular frequency of a surface wave of wavenumber ``k`` (paper eq 15).

    Parameters
    ----------
    k : array_like
        Wavenumber modulus K >= 0 [rad/m].
    depth : float or None
        Water depth d [m]; None for deep water (tanh -> 1).
    surface_tension : float
        Kinematic surface tension tau/rho [m^3/s^2]; 0 gives the paper's eq 15 exactly.
    g : float
        Acceleration of gravity [m/s^2].

    Returns
    -------
    ndarray
        omega >= 0 [rad/s], same shape as ``k``.
    """
    k = np.abs(np.asarray(k, dtype=np.float64))
    omega2 = omega_squared_deep(k, surface_tension, g)
    if depth is not None:
        if not depth > 0:
            raise ValueError(f"depth = {depth} m: must be > 0 (or None for deep water)")
        omega2 = omega2 * np.tanh(k * depth)  # Eq. 15 finite depth
    return np.sqrt(omega2)


def doppler_shifted_frequency(omega0: Any, kx: Any, ky: Any, current: Any) -> Any:
    """Absolute angular frequency of a wave of vector K on a uniform current [rad/s].

    .. math::

        \\omega(\\mathbf K) = \\omega_0(|\\mathbf K|) + \\mathbf K \\cdot \\mathbf U     (C1)

    ``omega_0`` the intrinsic frequency of eq 15' (in the frame moving with the water) and
    ``U`` a depth-uniform horizontal current: the waves are carried by the water
    (Phillips 1977, section 3.6; Kirby & Chen 1989, the uniform-current limit). A wave
    along ``-K`` has ``omega_0 - K . U``. Plain arithmetic, so that it runs on numpy and
    Dr.Jit arrays alike; with ``omega0 = 0`` it is the rate ``K . U`` at which a frozen
    pattern advected by ``U`` changes phase at a fixed point.

    Parameters
    ----------
    omega0 : array_like or Dr.Jit array
        Intrinsic angular frequency omega_0 [rad/s] (or 0).
    kx, ky : array_like or Dr.Jit array
        Wave vector components [rad/m] (scene frame).
    current : (float, float)
        Current U = (U_x, U_y) [m/s] (scene frame).
    """
    ux, uy = (float(v) for v in current)
    return omega0 + kx * ux + ky * uy  # Eq. C1 (Phillips 1977, sec. 3.6)


def phase_speed(
    k: ArrayLike,
    depth: float | None = None,
    surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
    g: float = G,
) -> NDArray[np.float64]:
    """Phase speed c = omega / K [m/s] (infinite at K = 0 is replaced by sqrt(g d) or inf).

    In deep water c = sqrt(g / K (1 + (K / k_m)^2)), the form of Elfouhaily et al.
    (1997) with k_m = :data:`CAPILLARY_WAVENUMBER`.
    """
    k = np.abs(np.asarray(k, dtype=np.float64))
    with np.errstate(divide="ignore", invalid="ignore"):
        c = angular_frequency(k, depth, surface_tension, g) / k
    limit = np.inf if depth is None else np.sqrt(g * depth)  # shallow-water limit at K -> 0
    return np.where(k > 0, c, limit)


def group_to_phase_ratio(k: ArrayLike, surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
                         g: float = G) -> NDArray[np.float64]:
    """n = c_g / c of deep-water capillary-gravity waves [-] (eq N1 of
    :mod:`seaecho.wake.narrow_v`).

    ``d omega / dk`` over ``omega / k`` for ``omega^2 = g k + tau k^3`` (eq 15'):
    1/2 for gravity waves, 3/2 for capillary waves, 1 at k_m.

    Parameters
    ----------
    k : array_like
        Wavenumber [rad/m], > 0.
    surface_tension : float
        Kinematic surface tension tau [m^3/s^2].
    g : float
        Gravity [m/s^2].

    References
    ----------
    M. J. Lighthill, *Waves in Fluids* (1978) section 3.10; Lamb (1932) art. 267.
    """
    tk2 = surface_tension * np.asarray(k, dtype=np.float64) ** 2
    return (g + 3.0 * tk2) / (2.0 * (g + tk2))  # d omega / dk over omega / k


def wavenumber_of_phase_speed(c: ArrayLike, capillary: bool = False,
                              surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
                              g: float = G) -> NDArray[np.float64]:
    """Deep-water wavenumber whose phase speed is c (inverse of eq 15') [rad/m].

    ``tau k^2 - c^2 k + g = 0``: two roots above the minimum phase speed
    ``(4 g tau)^(1/4)``, the gravity branch (k < k_m, default) and the capillary branch
    (``capillary=True``); below it, the double root k_m.

    Parameters
    ----------
    c : array_like
        Phase speed [m/s], > 0.
    capillary : bool
        Return the capillary-branch root.
    surface_tension : float
        Kinematic surface tension tau [m^3/s^2].
    g : float
        Gravity [m/s^2].
    """
    c2 = np.asarray(c, dtype=np.float64) ** 2
    disc = np.sqrt(np.maximum(c2 * c2 - 4.0 * g * surface_tension, 0.0))
    if capillary:
        return (c2 + disc) / (2.0 * surface_tension)
    return 2.0 * g / (c2 + disc)  # the smaller root, without cancellation


def horizontal_to_vertical_ratio(k: ArrayLike, depth: float | None = None
                                 ) -> NDArray[np.float64] | float:
    """coth(K d) [-]: the horizontal over the vertical orbital amplitude at the surface.

    Airy waves (Lamb 1932, art. 228): the surface particles of a wave of height amplitude
    a move horizontally by a coth(K d) and vertically by a; 1 in deep water (``depth``
    None), where the orbits are circles. ``inf`` at K = 0 in finite depth.
    """
    if depth is None:
        return 1.0
    k = np.abs(np.asarray(k, dtype=np.float64))
    with np.errstate(divide="ignore"):
        return 1.0 / np.tanh(k * depth)  # Lamb art. 228


__all__ = ["CAPILLARY_WAVENUMBER", "angular_frequency", "doppler_shifted_frequency",
           "group_to_phase_ratio",
           "horizontal_to_vertical_ratio", "omega_squared_deep", "phase_speed",
           "wavenumber_of_phase_speed"]
