"""Where a wave spectrum describes the sea: its fetch law's range and the depth it needs.

Two limits the builder checks for every use of ``[sea]``
(:func:`seaecho.build.check_sea`):

- **Fetch.** JONSWAP's peak law U10 omega_p / g = 22 X^(-1/3) (Hasselmann et al. 1973)
  and Elfouhaily's fetch law Omega_c = 0.84 tanh((X / X0)^0.4)^(-0.75) (Elfouhaily et
  al. 1997, X0 = 2.2e4) were fitted on seas of inverse wave age U10 / c_p from 5 (young)
  to 0.84 (fully developed), X = g F / U10^2 the dimensionless fetch. Younger is beyond
  the fitted seas (a fetch of 1e-300 m divided by zero); JONSWAP's law older than 0.84
  overshoots the fully developed sea (its energy keeps growing with fetch: H_s = 37 m at
  19 m/s for 22,000 km, where Pierson-Moskowitz gives 7.7 m).
- **Depth.** A wave of height H breaks in water shallower than H / 0.78 (McCowan 1894),
  so linear waves on finite depth (paper eq 15) do not describe a sea whose significant
  height H_s exceeds 0.78 d (a depth of 1e-300 m gave NaN wave velocities).

References
----------
A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic & polarimetric marine
radar simulator", Proc. 2006 IEEE Conference on Radar, Verona, NY, USA, 2006,
doi:10.1109/RADAR.2006.1631862 ("the paper").
K. Hasselmann et al., "Measurements of wind-wave growth and swell decay during the Joint
North Sea Wave Project (JONSWAP)", Dtsch. Hydrogr. Z. A8(12), 1973.
T. Elfouhaily, B. Chapron, K. Katsaros and D. Vandemark, "A unified directional spectrum
for long and short wind-driven waves", J. Geophys. Res. 102(C7), 15781-15796, 1997.
J. McCowan, "On the highest wave of permanent type", Philosophical Magazine 38(5),
351-358, 1894.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..constants import G
from .spectra import DirectionalSpectrum
from .twoscale import height_variance
from .wind import u10_from_u19_5

#: McCowan's limit on the height of a wave in water of depth d: H <= 0.78 d.
BREAKING_RATIO = 0.78
#: Inverse wave age U10 / c_p of the fetch laws' seas: 0.84 fully developed to 5 young
#: (Elfouhaily et al. 1997: 0.84 fully developed, about 1 mature, 2 to 5 young).
OMEGA_RANGE = (0.84, 5.0)
#: Elfouhaily's fetch law Omega_c = 0.84 tanh((X / X0)^0.4)^-0.75 reaches 5 at this
#: dimensionless fetch X = g F / U10^2 (X0 = 2.2e4); it saturates at 0.84 for long fetch.
MIN_DIMENSIONLESS_FETCH = 2.2e4 * float(np.arctanh((0.84 / 5.0) ** (4.0 / 3.0))) ** 2.5
#: Upper wavenumber of the significant height's integral [rad/m] (1 mm waves).
K_MAX_HS = 1.0e4


def significant_height(spectrum: DirectionalSpectrum) -> float:
    """Significant wave height H_s = 4 sqrt(m0) [m], m0 the spectrum's height variance
    over 0 < K < 1e4 rad/m."""
    with warnings.catch_warnings():  # validity warnings come with the run, not here
        warnings.simplefilter("ignore")
        return 4.0 * height_variance(spectrum, 0.0, K_MAX_HS) ** 0.5


def min_depth(spectrum: DirectionalSpectrum) -> float:
    """Shallowest water that holds the spectrum's waves, H_s / 0.78 [m] (McCowan 1894)."""
    return significant_height(spectrum) / BREAKING_RATIO


def fetch_range(spectrum: str, u19_5: float) -> tuple[float, float]:
    """Fetches [m] whose sea a spectrum's fetch law describes at a wind speed.

    Parameters
    ----------
    spectrum : str
        ``"jonswap"`` or ``"elfouhaily"`` (the spectra with a fetch law).
    u19_5 : float
        Wind speed at 19.5 m [m/s].

    Returns
    -------
    (lo, hi) : float
        Inverse wave age 5 to 0.84 (module docstring); ``hi`` infinite for Elfouhaily's
        law, which saturates at full development.
    """
    u10 = float(u10_from_u19_5(u19_5))
    scale = u10**2 / G  # F = X U10^2 / g
    if spectrum == "jonswap":
        lo, hi = OMEGA_RANGE
        return (22.0 / hi) ** 3 * scale, (22.0 / lo) ** 3 * scale
    return MIN_DIMENSIONLESS_FETCH * scale, float("inf")


__all__ = ["BREAKING_RATIO", "K_MAX_HS", "MIN_DIMENSIONLESS_FETCH", "OMEGA_RANGE",
           "fetch_range", "min_depth", "significant_height"]
