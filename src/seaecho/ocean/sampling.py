"""Sampling advice for sea tiles (paper section IV-A, eqs 13-14).

The low-wavenumber part of the usual spectra follows the Pierson-Moskowitz form
f(K, U) = a0 K^-3 exp(-b0 / (K^2 U^4)) (eq 13), which has the invariant

.. math::

    f(K a^2, U) = f(K, a U) / a^6                                               (14)

so the -3 dB band of the spectral peak scales as U^-2 while its logarithmic width does
not change. :func:`suggest_sampling` computes the -3 dB band once, numerically, for a
reference wind and scales it with eq 14. Following the paper, the wavenumber step is a
quarter of the -3 dB width (tile size L = 2 pi / dk). For the grid spacing, the paper
only says "a compromise ... with the typical height of the capillary waves on the pixel";
we make it precise with the small-perturbation validity bound k_radar h_res <= 0.3
(Thorsos & Jackson 1989; Ulaby, Moore & Fung 1982, vol. II, sec. 12-3) on the rms height
h_res of the unresolved waves, using the asymptote of eq 13 for K >> K_p:
h_res^2 = int_{k_c}^inf (a0/2) K^-3 dK = a0 / (4 k_c^2), so k_c = sqrt(a0) k_radar / (2 x 0.3)
and dx = pi / k_c.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] E. I. Thorsos and D. R. Jackson, "The validity of the perturbation approximation
   for rough surface scattering using a Gaussian roughness spectrum", J. Acoust. Soc. Am.
   86(1), 261-277, 1989.
.. [2] F. T. Ulaby, R. K. Moore and A. K. Fung, *Microwave Remote Sensing*, vol. II,
   Addison-Wesley, 1982.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq

from ..constants import C0
from ..warnings import SamplingWarning
from .spectra import PM_A0, DirectionalSpectrum, pierson_moskowitz, pierson_moskowitz_peak
from .twoscale import ROUGHNESS_K_MAX_RATIO, SPM_KH_MAX, height_variance

_U_REF = 10.0


def pm_shape(k, u):
    """Eq 13 with the paper's a0 and b0 g^2: a0 K^-3 exp(-b0 g^2 / (K^2 U^4))."""
    return 2.0 * pierson_moskowitz(k, u)


@lru_cache(maxsize=1)
def _reference_band() -> tuple[float, float]:
    """-3 dB band (k_lo, k_hi) [rad/m] of the PM peak for U = 10 m/s, numerically."""
    kp = pierson_moskowitz_peak(_U_REF)
    half = pm_shape(kp, _U_REF) / 2.0
    k_lo = brentq(lambda k: pm_shape(k, _U_REF) - half, kp * 0.1, kp)
    k_hi = brentq(lambda k: pm_shape(k, _U_REF) - half, kp, kp * 10)
    return float(k_lo), float(k_hi)


def peak_band(u19_5: float) -> tuple[float, float]:
    """-3 dB band of the spectral peak [rad/m] for a wind U19.5 [m/s], via eq 14.

    Eq 14 with a = u / U_ref: the curve for wind u is the reference curve with K scaled
    by (U_ref / u)^2.
    """
    if not u19_5 > 0:
        raise ValueError(f"u19_5 = {u19_5} m/s: must be > 0")
    scale = (_U_REF / u19_5) ** 2
    k_lo, k_hi = _reference_band()
    return k_lo * scale, k_hi * scale


@dataclass(frozen=True)
class SamplingAdvice:
    """A tile size and grid that resolve the spectral peak and the two-scale split."""

    tile_size: float  #: L = 2 pi / dk [m]
    spacing: float  #: dx [m]
    n: int  #: grid points per side (even, rounded up to a power of two)
    k_step: float  #: dk [rad/m]
    k_cut: float  #: grid cut-off wavenumber [rad/m]


def suggest_sampling(u19_5: float, frequency: float) -> SamplingAdvice:
    """Tile size and grid spacing for a wind (paper section IV-A, eqs 13-14).

    Parameters
    ----------
    u19_5 : float
        Wind speed at 19.5 m [m/s].
    frequency : float
        Radar carrier frequency [Hz] (sets the grid cut-off, see module docstring).
    """
    k_lo, k_hi = peak_band(u19_5)
    dk = (k_hi - k_lo) / 4.0  # paper: a quarter of the -3 dB width
    tile = 2 * np.pi / dk
    k_radar = 2 * np.pi * frequency / C0
    k_cut = np.sqrt(PM_A0) * k_radar / (2 * SPM_KH_MAX)  # h_res = sqrt(a0) / (2 k_c)
    dx = np.pi / k_cut
    n = int(2 ** np.ceil(np.log2(tile / dx)))
    return SamplingAdvice(tile_size=float(tile), spacing=float(dx), n=n, k_step=float(dk),
                          k_cut=float(k_cut))


def check_sampling(spectrum: DirectionalSpectrum, size: tuple[float, float],
                   shape: tuple[int, int], frequency: float | None = None) -> None:
    """Warn (:class:`~seaecho.warnings.SamplingWarning`) if a sea tile is under-sampled.

    The tile must hold the peak wavelength and its wavenumber step must resolve the -3 dB
    band of the peak; with a radar ``frequency`` the unresolved waves (the Bragg
    roughness band of :mod:`seaecho.ocean.twoscale`, from the grid's Nyquist wavenumber
    to 20 k) must satisfy k_radar h_res <= 0.3 (see module docstring).

    Parameters
    ----------
    spectrum : DirectionalSpectrum
        The sea's spectrum.
    size : (float, float)
        Tile extents (Lx, Ly) [m].
    shape : (int, int)
        Grid nodes (ny, nx), array order.
    frequency : float, optional
        Radar carrier frequency [Hz]; None skips the grid-spacing check.
    """
    k_p = spectrum.peak_wavenumber()
    lx, ly = size
    ny, nx = shape
    dk = 2 * np.pi / min(lx, ly)
    if min(lx, ly) < 2 * np.pi / k_p:
        warnings.warn(
            f"sea tile {lx} x {ly} m is smaller than the peak wavelength "
            f"{2 * np.pi / k_p:.1f} m of the {spectrum.spectrum} spectrum at U19.5 = "
            f"{spectrum.u19_5} m/s: the longest waves are missing",
            SamplingWarning, stacklevel=2,
        )
    else:
        k_lo, k_hi = peak_band(spectrum.u19_5)
        if dk > (k_hi - k_lo):
            tile = 2 * np.pi / ((k_hi - k_lo) / 4.0)  # suggest_sampling's tile size
            warnings.warn(
                f"sea wavenumber step {dk:.4g} rad/m of a {min(lx, ly)} m tile is wider "
                f"than the -3 dB band of the spectral peak ({k_hi - k_lo:.4g} rad/m): the "
                f"peak is not resolved; suggested tile >= {tile:.0f} m",
                SamplingWarning, stacklevel=2,
            )
    if frequency is not None:
        k_radar = 2 * np.pi * frequency / C0
        dx = max(lx / nx, ly / ny)
        h_res = np.sqrt(height_variance(spectrum, np.pi / dx, ROUGHNESS_K_MAX_RATIO * k_radar))
        if k_radar * h_res > SPM_KH_MAX:
            advice = suggest_sampling(spectrum.u19_5, frequency)
            warnings.warn(
                f"sea grid spacing {dx:.3g} m is coarse against the radar wavelength "
                f"{2 * np.pi / k_radar:.3g} m: unresolved waves have k h = "
                f"{k_radar * h_res:.2f} > {SPM_KH_MAX}; suggested spacing <= "
                f"{advice.spacing:.3g} m",
                SamplingWarning, stacklevel=2,
            )


__all__ = ["SamplingAdvice", "check_sampling", "peak_band", "suggest_sampling"]

