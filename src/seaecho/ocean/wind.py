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

with kappa = 0.41 (:data:`seaecho.constants.VON_KARMAN`) and C_D = 1.3e-3, the value
Stewart (2008) states for his conversion between U19.5 and U10. Eq L1 gives
U19.5 = 1.0587 U10 and U12.5 = 1.0196 U10 (equivalently a roughness length
z0 = 10 m x exp(-kappa / sqrt(C_D)) = 0.115 mm).
Stewart's printed ratio U19.5 = 1.026 U10 (his eq 16.29) does not follow from the drag
coefficient he states with it; seaecho uses the profile, so that the three heights agree
with each other.

**Friction velocity and roughness.** The models of seaecho that need the friction
velocity u* each follow their own source's law; the laws are here, once, by name
(:data:`FRICTION_VELOCITY_LAWS`), and each user names the one it takes:

- ``"constant-drag"``: u* = sqrt(C_D) U10, C_D = 1.3e-3 (Stewart 2008; the law of eq L1);
- ``"wu-1982"``: u* = U10 sqrt(C_D), C_D = (0.8 + 0.065 U10) 1e-3 (Wu 1982), the drag law
  of the breaking-wave model of Kudryavtsev et al. (2003) (:mod:`seaecho.scattering.
  breaking`);
- ``"donelan-1993"``: u* = kappa U10 / ln(10 m / z0), z0 = 3.7e-5 (U10^2 / g)
  Omega_c^0.9 (Donelan, Dobson, Smith & Anderson 1993, in the form of Elfouhaily et al.
  1997), which depends on the inverse wave age Omega_c: the Elfouhaily spectrum's.

At U10 = 10 m/s and Omega_c = 0.84 they give 0.361, 0.381 and 0.396 m/s. The roughness
length of the KHCC03 wind growth rate, z0 = 0.018 u*^2 / g + 0.1 nu_a / u* (Charnock
1955 with a smooth-flow term; Kudryavtsev et al. 2003, eq 21), is
:func:`charnock_roughness_length`.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] R. H. Stewart, *Introduction to Physical Oceanography*, Texas A&M University,
   2008, sections 4.3 (the logarithmic profile, friction velocity and drag coefficient)
   and 16.3 (eq 16.29, U19.5 and U10 for C_D = 1.3e-3).
.. [2] H. Tennekes, "The logarithmic wind profile", J. Atmos. Sci. 30(2), 234-238, 1973.
.. [3] J. Wu, "Wind-stress coefficients over sea surface from breeze to hurricane",
   J. Geophys. Res. 87(C12), 9704-9706, 1982.
.. [4] M. A. Donelan, F. W. Dobson, S. D. Smith and R. J. Anderson, "On the dependence
   of sea surface roughness on wave development", J. Phys. Oceanogr. 23, 2143-2149, 1993.
.. [5] T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified directional
   spectrum for long and short wind-driven waves", J. Geophys. Res. 102(C7),
   15781-15796, 1997.
.. [6] V. Kudryavtsev, D. Hauser, G. Caudal and B. Chapron, "A semiempirical model of
   the normalized radar cross-section of the sea surface, 1. Background model",
   J. Geophys. Res. 108(C3), 8054, 2003, eq 21.
.. [7] H. Charnock, "Wind stress on a water surface", Q. J. R. Meteorol. Soc. 81,
   639-640, 1955.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import NU_AIR, VON_KARMAN, G

#: von Karman constant [-] (the one of :mod:`seaecho.constants`).
KAPPA = VON_KARMAN
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


#: Charnock's constant and the smooth-flow constant of the KHCC03 roughness length [-]
#: (Kudryavtsev et al. 2003, eq 21).
A_CHARNOCK = 0.018
A_SMOOTH = 0.1
#: Inverse wave age of a fully developed sea [-] (Elfouhaily et al. 1997).
OMEGA_C_DEVELOPED = 0.84


def friction_velocity_constant_drag(u10: ArrayLike, inverse_wave_age: float = 0.84
                                    ) -> NDArray[np.float64]:
    """u* = sqrt(C_D) U10 with C_D = 1.3e-3 [m/s] (Stewart 2008 sec. 4.3; eq L1's law).

    ``inverse_wave_age`` is not used (the common signature of the laws).
    """
    return np.sqrt(DRAG_COEFFICIENT_10M) * np.asarray(u10, dtype=np.float64)


def friction_velocity_wu1982(u10: ArrayLike, inverse_wave_age: float = 0.84
                             ) -> NDArray[np.float64]:
    """u* = U10 sqrt(C_D), C_D = (0.8 + 0.065 U10) 1e-3 [m/s] (Wu 1982).

    The drag law of Kudryavtsev et al. (2003) and (2005). ``inverse_wave_age`` is not used.
    """
    u = np.asarray(u10, dtype=np.float64)
    return u * np.sqrt((0.8 + 0.065 * u) * 1e-3)


def friction_velocity_donelan1993(u10: ArrayLike, inverse_wave_age: float = 0.84
                                  ) -> NDArray[np.float64]:
    """u* = kappa U10 / ln(10 m / z0), z0 = 3.7e-5 (U10^2 / g) Omega_c^0.9 [m/s].

    The wave-age dependent roughness of Donelan et al. (1993) in the neutral log profile,
    as Elfouhaily et al. (1997) use it for their spectrum's short-wave part.

    Parameters
    ----------
    u10 : array_like
        Wind speed at 10 m [m/s].
    inverse_wave_age : float
        Omega_c = U10 / c_p [-] (0.84: fully developed).
    """
    u = np.asarray(u10, dtype=np.float64)
    z0 = 3.7e-5 * u**2 / G * inverse_wave_age**0.9  # roughness length (Donelan et al. 1993)
    return KAPPA * u / np.log(10.0 / z0)  # neutral log profile at 10 m


#: Friction-velocity laws by name: ``law(u10 [m/s], inverse_wave_age [-]) -> u* [m/s]``.
FRICTION_VELOCITY_LAWS: dict[str, Callable[..., NDArray[np.float64]]] = {
    "constant-drag": friction_velocity_constant_drag,
    "wu-1982": friction_velocity_wu1982,
    "donelan-1993": friction_velocity_donelan1993,
}


def friction_velocity(law: str, u10: ArrayLike, inverse_wave_age: float = OMEGA_C_DEVELOPED
                      ) -> NDArray[np.float64]:
    """Friction velocity u* [m/s] of the law named ``law`` (:data:`FRICTION_VELOCITY_LAWS`).

    Parameters
    ----------
    law : str
        ``"constant-drag"``, ``"wu-1982"`` or ``"donelan-1993"``.
    u10 : array_like
        Wind speed at 10 m [m/s].
    inverse_wave_age : float
        Omega_c [-] (only ``"donelan-1993"`` depends on it).
    """
    if law not in FRICTION_VELOCITY_LAWS:
        raise ValueError(f"friction-velocity law = {law!r}: unknown; allowed: "
                         f"{sorted(FRICTION_VELOCITY_LAWS)}")
    return FRICTION_VELOCITY_LAWS[law](u10, inverse_wave_age)


#: Surface wind drift over the friction velocity of the wind [-] (Wu 1975: the
#: wind-induced current at the interface is proportional to u*). The coefficient 0.53 is
#: quoted from memory: Wu's abstract (the text read here) gives the proportionality and a
#: total surface drift (wind + Stokes) approaching 3.5 % of the wind at long fetch, not
#: the number; tank measurements give 0.65-1.2 u* (Polnikov, Qiao & Ma 2020, J. Phys.
#: Oceanogr. 50(10), abstract). Searched again (Wu 1975, Wu 1983, the open Doppler models):
#: not found; the default drift is the sourced total surface drift (SURFACE_DRIFT_OVER_U10).
WIND_DRIFT_OVER_U_STAR = 0.53


def wind_drift_wu(u10: float, wind_direction: float) -> tuple[float, float]:
    """Wind-induced surface drift (U_x, U_y) [m/s]: ``0.53 u*`` along the wind.

    Wu (1975) measured the drift at the air-water interface proportional to the wind's
    friction velocity; ``u*`` here is Wu's (1982) drag law
    (:func:`friction_velocity_wu1982`). At U10 = 10 m/s: 0.20 m/s, 2.0 % of U10 (the
    wave-induced Stokes drift, which linear waves do not carry, is not included).

    Parameters
    ----------
    u10 : float
        Wind speed at 10 m [m/s].
    wind_direction : float
        Direction the wind blows towards, counter-clockwise from +x [rad].

    References
    ----------
    J. Wu, "Wind-induced drift currents", J. Fluid Mech. 68(1), 49-70, 1975.
    """
    u_d = WIND_DRIFT_OVER_U_STAR * float(friction_velocity_wu1982(u10))  # Wu 1975
    return u_d * math.cos(wind_direction), u_d * math.sin(wind_direction)


#: Total surface drift (wind-induced current plus the waves' Stokes drift) over U10 [-]:
#: "Empirically, it is found that the drift current at the surface is 2.5%-3.0% of the
#: wind speed" and "a rough estimate of wind drift is 3% of the wind speed" (American
#: Meteorological Society, Glossary of Meteorology, entries "Surface current" and "Wind
#: drift"); Wu (1975, abstract) measured the total surface drift approaching "about 3.5%"
#: of the wind at very long fetch; Elyouncha et al. (2021) use "~3% of wind speed" for the
#: wind-induced drift in their X-band Doppler budget.
SURFACE_DRIFT_OVER_U10 = 0.03


def surface_drift_3pct(u10: float, wind_direction: float) -> tuple[float, float]:
    """Total surface drift (U_x, U_y) [m/s]: ``0.03 U10`` along the wind.

    The empirical surface drift of the AMS Glossary of Meteorology (2.5-3.0 % of the wind;
    "a rough estimate of wind drift is 3% of the wind speed"), which is the wind-induced
    current *and* the Stokes drift of the waves (Wu 1975: their sum approaches 3.5 % of
    the wind at long fetch): the synthesised waves are linear and carry neither, so the
    whole drift is added. 0.30 m/s at U10 = 10 m/s. The Ekman veering of the glossary's
    entry ("about 10 deg to the right (left) of the wind direction in the Northern
    (Southern) Hemisphere") is not applied: a scene has no latitude.

    Parameters
    ----------
    u10 : float
        Wind speed at 10 m [m/s].
    wind_direction : float
        Direction the wind blows towards, counter-clockwise from +x [rad].

    References
    ----------
    American Meteorological Society, Glossary of Meteorology, "Surface current" and "Wind
    drift". J. Wu, "Wind-induced drift currents", J. Fluid Mech. 68(1), 49-70, 1975.
    """
    u_d = SURFACE_DRIFT_OVER_U10 * float(u10)  # AMS Glossary; Wu 1975
    return u_d * math.cos(wind_direction), u_d * math.sin(wind_direction)


#: Wind-drift laws of ``[sea] wind_drift`` by name: ``law(u10 [m/s], direction [rad]) ->
#: (U_x, U_y) [m/s]``.
WIND_DRIFT_LAWS: dict[str, Callable[[float, float], tuple[float, float]]] = {
    "wu": wind_drift_wu,
    "3pct": surface_drift_3pct,
}


def charnock_roughness_length(u_star: ArrayLike) -> NDArray[np.float64]:
    """Aerodynamic roughness z0 = 0.018 u*^2 / g + 0.1 nu_a / u* [m] (KHCC03 eq 21).

    Charnock's (1955) law for the rough flow plus the smooth-flow term, as in
    Kudryavtsev et al. (2003).

    Parameters
    ----------
    u_star : array_like
        Friction velocity [m/s].
    """
    us = np.asarray(u_star, dtype=np.float64)
    return A_CHARNOCK * us**2 / G + A_SMOOTH * NU_AIR / np.maximum(us, 1e-12)


__all__ = ["A_CHARNOCK", "A_SMOOTH", "DRAG_COEFFICIENT_10M", "FRICTION_VELOCITY_LAWS", "KAPPA",
           "OMEGA_C_DEVELOPED", "charnock_roughness_length", "friction_velocity",
           "friction_velocity_constant_drag", "friction_velocity_donelan1993",
           "friction_velocity_wu1982", "u10_from_u19_5", "u12_5_from_u19_5",
           "u19_5_from_u10", "SURFACE_DRIFT_OVER_U10", "surface_drift_3pct",
           "WIND_DRIFT_LAWS", "WIND_DRIFT_OVER_U_STAR", "wind_drift_wu", "wind_speed_at"]
