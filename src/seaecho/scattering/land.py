"""Land clutter: the constant-gamma model and Weibull amplitudes.

The land's normalised radar cross section per unit area of the surface is the
constant-gamma law

.. math::

    \\sigma^0 = \\gamma \\sin\\psi                                               (L1)

with psi the grazing angle on the surface and gamma a property of the terrain at the
frequency (Barton 1985; Nathanson et al. 1999, section 7.3; Long 2001, chapter 2): it
holds over the "plateau" of grazing angles, between the near-grazing interference
region and the near-vertical specular one. Its bistatic form, used when the
transmitter and the receiver are apart, takes the geometric mean of the two grazing
angles (the bistatic extension of the constant-gamma model; Willis 2005, section 9.2,
a section number and attribution not checked against the book here):

.. math::

    \\sigma^0_B = \\gamma \\sqrt{\\sin\\psi_i \\sin\\psi_s}                          (L2)

which is (L1) for a monostatic radar. Values of gamma at 10 GHz (:data:`GAMMA_DB`,
Barton 1985, table 1; the same in Barton 2013, chapter 9: mountains and urban -5 dB,
wooded hills -10 dB, rolling hills -12 dB, farmland and desert -15 dB, flatland -20 dB)
scale with frequency as

.. math::

    \\gamma(f) = \\gamma(f_0) + 5 \\log_{10}(f / f_0)\\ \\mathrm{dB},\\quad
    f_0 = 10\\ \\mathrm{GHz}                                                        (L3)

(Barton 1985: gamma grows as f^(1/2)).

Amplitude statistics. Low-angle land clutter is far from Rayleigh: Billingsley (2002,
chapter 2) fits the spatial distribution of the clutter of cells over a patch of terrain
with Weibull distributions of shape parameter a_w (1: Rayleigh); his interim model
(chapter 4, p. 295, as restated by J. Champagne's open radar-clutter-simulator, 2019)
gives a_w = 2.0 to 5.4 by terrain class and depression angle, larger at the smaller
depression angles (general rural terrain: 2.6 above 4 deg, 3.8 between 0 and 0.25
deg). In Billingsley's parametrisation the clutter power w = sigma / <sigma> has

.. math::

    P(w > x) = \\exp\\left[-\\left(x / b\\right)^{1/a_w}\\right],\\qquad
    b = 1 / \\Gamma(1 + a_w)                                                       (L4)

(unit mean; a_w = 1 is the exponential power of Rayleigh amplitudes): drawn as
w = b E^(a_w) with E a unit exponential (:func:`weibull_power`). Each land facet carries
one such w and a uniform phase, fixed over a run (land clutter is mostly steady:
Billingsley 2002, chapter 4, the "DC" component of its Doppler spectrum); the facets
are about a resolution cell in size so that the cells' amplitudes follow (L4).

References
----------
.. [1] D. K. Barton, "Land clutter models for radar design and analysis", *Proc. IEEE*
   73(2), 198-204 (1985).
.. [2] D. K. Barton, *Radar Equations for Modern Radar*, Artech House (2013), chapter 9.
.. [3] F. E. Nathanson, J. P. Reilly and M. N. Cohen, *Radar Design Principles*, 2nd
   ed., SciTech (1999), section 7.3 (constant gamma, land gamma by terrain).
.. [4] M. W. Long, *Radar Reflectivity of Land and Sea*, 3rd ed., Artech House (2001),
   chapter 2.
.. [5] J. B. Billingsley, *Low-Angle Radar Land Clutter: Measurements and Empirical
   Models*, William Andrew / SciTech (2002), chapters 2 (Weibull statistics, a_w) and 4.
.. [6] N. J. Willis, *Bistatic Radar*, SciTech (2005), section 9.2 (not checked here;
   the only clutter chapter whose contents were read is chapter 9, "Bistatic clutter",
   of N. J. Willis and H. D. Griffiths (eds.), *Advances in Bistatic Radar*, SciTech
   (2007): 9.2 "System Parameters and Properties", 9.3 "Clutter Cross-Section Per Unit
   Area"; its text, and whether it gives eq L2, were not read).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

#: gamma [dB] at 10 GHz by terrain (Barton 1985, table 1; Barton 2013, chapter 9; the
#: table was not read here: farmland, wooded hills and flatland are checked against
#: Nathanson et al. 1999 as restated by MATLAB's ``surfacegamma``, the other four are
#: not, docs/land.md).
GAMMA_DB: dict[str, float] = {
    "mountains": -5.0,
    "urban": -5.0,
    "wooded-hills": -10.0,
    "rolling-hills": -12.0,
    "farmland": -15.0,
    "desert": -15.0,
    "flatland": -20.0,
}
#: Reference frequency f_0 of :data:`GAMMA_DB` and eq (L3) [Hz].
GAMMA_REFERENCE_HZ = 10.0e9


def terrain_gamma_db(terrain: str, frequency_hz: float) -> float:
    """gamma [dB] of a terrain of :data:`GAMMA_DB` at a frequency [Hz], eq (L3).

    References
    ----------
    Barton (1985), table 1 and the f^(1/2) law.
    """
    if terrain not in GAMMA_DB:
        raise ValueError(f"terrain = {terrain!r}: allowed {sorted(GAMMA_DB)}")
    if not frequency_hz > 0:
        raise ValueError(f"frequency_hz = {frequency_hz}: must be > 0 [Hz]")
    # Eq (L3)
    return GAMMA_DB[terrain] + 5.0 * math.log10(frequency_hz / GAMMA_REFERENCE_HZ)


def constant_gamma_sigma0(gamma: float, sin_psi_i: ArrayLike,
                          sin_psi_s: ArrayLike | None = None) -> NDArray[np.float64]:
    """Land NRCS per unit surface area [m^2/m^2], eqs (L1)-(L2).

    Parameters
    ----------
    gamma : float
        gamma [-] (linear, not dB).
    sin_psi_i : array_like
        Sine of the grazing angle of the incident ray on the surface [-]; <= 0: not lit.
    sin_psi_s : array_like, optional
        Sine of the grazing angle towards the receiver [-] (bistatic, eq L2); default the
        incident one (monostatic, eq L1).

    Returns
    -------
    ndarray
        sigma0 [-], 0 where a grazing angle is <= 0.

    References
    ----------
    Barton (1985); Nathanson et al. (1999), section 7.3; Willis (2005), section 9.2.
    """
    si = np.clip(np.asarray(sin_psi_i, dtype=np.float64), 0.0, 1.0)
    if sin_psi_s is None:
        return gamma * si  # Eq (L1)
    ss = np.clip(np.asarray(sin_psi_s, dtype=np.float64), 0.0, 1.0)
    return gamma * np.sqrt(si * ss)  # Eq (L2)


def weibull_power(shape: float, n: int, rng: np.random.Generator) -> NDArray[np.float64]:
    """Unit-mean clutter powers w of Weibull amplitudes with shape a_w, eq (L4).

    Parameters
    ----------
    shape : float
        Billingsley's Weibull shape parameter a_w >= 1 [-] (1: Rayleigh amplitudes).
    n : int
        Number of draws.
    rng : numpy.random.Generator
        A stream of :mod:`seaecho.rng`.

    Returns
    -------
    ndarray (n,)
        w >= 0 with E[w] = 1 and P(w > x) = exp(-(x / b)^(1 / a_w)).

    References
    ----------
    Billingsley (2002), chapter 2 (Weibull shape parameter a_w).
    """
    if not shape >= 1.0:
        raise ValueError(f"shape = {shape}: the Weibull shape a_w must be >= 1")
    # Eq (L4): w = b E^a_w, E unit exponential, b = 1 / Gamma(1 + a_w)
    return rng.standard_exponential(n) ** shape / math.gamma(1.0 + shape)


__all__ = ["GAMMA_DB", "GAMMA_REFERENCE_HZ", "constant_gamma_sigma0", "terrain_gamma_db",
           "weibull_power"]
