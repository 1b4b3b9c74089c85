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
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import SURFACE_TENSION_OVER_DENSITY, G


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
    omega2 = k * (g + surface_tension * k * k)  # Eq. 15' restoring forces
    if depth is not None:
        if not depth > 0:
            raise ValueError(f"depth = {depth} m: must be > 0 (or None for deep water)")
        omega2 = omega2 * np.tanh(k * depth)  # Eq. 15 finite depth
    return np.sqrt(omega2)


def phase_speed(
    k: ArrayLike,
    depth: float | None = None,
    surface_tension: float = SURFACE_TENSION_OVER_DENSITY,
    g: float = G,
) -> NDArray[np.float64]:
    """Phase speed c = omega / K [m/s] (infinite at K = 0 is replaced by sqrt(g d) or inf)."""
    k = np.abs(np.asarray(k, dtype=np.float64))
    with np.errstate(divide="ignore", invalid="ignore"):
        c = angular_frequency(k, depth, surface_tension, g) / k
    limit = np.inf if depth is None else np.sqrt(g * depth)  # shallow-water limit at K -> 0
    return np.where(k > 0, c, limit)


__all__ = ["angular_frequency", "phase_speed"]
