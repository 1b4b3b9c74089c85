"""Wind speed at different heights above the sea: one neutral logarithmic profile.

The models in seaecho quote the wind at three heights: 19.5 m (the Pierson-Moskowitz
spectrum and the paper's eq 5, the scene files' ``wind_speed_m_s``), 10 m (the JONSWAP
and Elfouhaily et al. spectra) and 12.5 m (the anemometer of Cox & Munk's slope
statistics). Every conversion between them goes through this module, so that they all
assume the same profile.

In a neutrally stable surface layer the wind grows logarithmically with height,
U(z) = (u*/kappa) ln(z / z0). With the neutral drag coefficient C_D referred to 10 m,
u* = sqrt(C_D) U10, and the profile reads

.. math::

    U(z) = U_{10}\\left(1 + \\frac{\\sqrt{C_D}}{\\kappa}\\,
        \\ln\\frac{z}{10\\ \\mathrm{m}}\\right)                                  (L1)

with kappa = 0.41 and C_D = 1.3e-3, the value Stewart (2008) states for his conversion
between U19.5 and U10. Eq L1 gives U19.5 = 1.0587 U10 and U12.5 = 1.0196 U10
(equivalently a roughness length z0 = 10 m x exp(-kappa / sqrt(C_D)) = 0.115 mm).
Stewart's printed ratio U19.5 = 1.026 U10 (his eq 16.29) does not follow from the drag
coefficient he states with it; seaecho uses the profile, so that the three heights agree
with each other.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] R. H. Stewart, *Introduction to Physical Oceanography*, Texas A&M University,
   2008, sections 4.3 (the logarithmic profile, friction velocity and drag coefficient)
   and 16.3 (eq 16.29, U19.5 and U10 for C_D = 1.3e-3).
.. [2] H. Tennekes, "The logarithmic wind profile", J. Atmos. Sci. 30(2), 234-238, 1973.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: von Karman constant [-].
KAPPA = 0.41
#: Neutral drag coefficient at 10 m [-] (Stewart 2008, with his eq 16.29).
DRAG_COEFFICIENT_10M = 1.3e-3


def wind_speed_at(u: ArrayLike, z_from: float, z_to: float) -> NDArray[np.float64]:
    """Wind speed at height ``z_to`` from the speed at ``z_from`` [m/s], eq L1.

    Parameters
    ----------
    u : array_like
        Wind speed at ``z_from`` [m/s].
    z_from, z_to : float
        Heights above the mean sea surface [m], > 0.

    Returns
    -------
    ndarray
        Wind speed at ``z_to`` [m/s].
    """
    if not (z_from > 0 and z_to > 0):
        raise ValueError(f"heights z_from = {z_from} m, z_to = {z_to} m: must be > 0")
    a = np.sqrt(DRAG_COEFFICIENT_10M) / KAPPA
    # Eq L1 at both heights: U(z_to) / U(z_from)
    ratio = (1.0 + a * np.log(z_to / 10.0)) / (1.0 + a * np.log(z_from / 10.0))
    return np.asarray(u, dtype=np.float64) * ratio


def u10_from_u19_5(u19_5: ArrayLike) -> NDArray[np.float64]:
    """Wind speed at 10 m from that at 19.5 m [m/s] (eq L1: U10 = U19.5 / 1.0587)."""
    return wind_speed_at(u19_5, 19.5, 10.0)


def u19_5_from_u10(u10: ArrayLike) -> NDArray[np.float64]:
    """Wind speed at 19.5 m from that at 10 m [m/s] (eq L1: U19.5 = 1.0587 U10)."""
    return wind_speed_at(u10, 10.0, 19.5)


def u12_5_from_u19_5(u19_5: ArrayLike) -> NDArray[np.float64]:
    """Wind speed at 12.5 m (Cox & Munk's anemometer) from that at 19.5 m [m/s], eq L1."""
    return wind_speed_at(u19_5, 19.5, 12.5)


__all__ = ["DRAG_COEFFICIENT_10M", "KAPPA", "u10_from_u19_5", "u12_5_from_u19_5",
           "u19_5_from_u10", "wind_speed_at"]
