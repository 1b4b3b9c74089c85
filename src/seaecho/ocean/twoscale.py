"""The two-scale split: statistics of the waves the grid does not resolve.

The grid resolves wavenumbers up to its Nyquist wavenumber
k_N = pi / max(dx, dy); shorter waves are the sub-facet roughness that the scattering
models treat statistically (``../shared/DESIGN.md``, "Two scales"). For a band
k_min < K < k_max of the directional spectrum Psi (paper eq 4):

.. math::

    \\langle z^2 \\rangle_{band} = \\int_{k_{min}}^{k_{max}} S_{1d}(K)\\,dK

    s_u^2 = \\int_{k_{min}}^{k_{max}}\\!\\int_{-\\pi}^{\\pi} K^2\\cos^2\\psi\\;
        S_{1d}(K) D(K,\\psi)\\,d\\psi\\,dK,\\qquad
    s_c^2 = \\int\\!\\!\\int K^2\\sin^2\\psi\\; S_{1d} D\\,d\\psi\\,dK

the height variance and the upwind / crosswind slope variances (Cox & Munk 1954
definitions; e.g. Elfouhaily et al. 1997).

References
----------
.. [1] C. Cox and W. Munk, "Measurement of the roughness of the sea surface from
   photographs of the sun's glitter", J. Opt. Soc. Am. 44(11), 838-850, 1954.
.. [2] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781-15796, 1997.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .spectra import DirectionalSpectrum

_N_K = 2000
_N_PSI = 360


def _band_grid(k_min: float, k_max: float) -> np.ndarray:
    if not (0 <= k_min < k_max and np.isfinite(k_max)):
        raise ValueError(f"band k_min = {k_min}, k_max = {k_max} rad/m: need 0 <= k_min < k_max")
    lo = max(k_min, 1e-6)
    return np.geomspace(lo, k_max, _N_K)


def _empty_band(k_min: float, k_max: float) -> bool:
    """True if the band k_min < K < k_max holds no wavenumber (its integrals are 0)."""
    if not (k_min >= 0 and np.isfinite(k_min) and k_max >= 0 and np.isfinite(k_max)):
        raise ValueError(f"band k_min = {k_min}, k_max = {k_max} rad/m: need finite limits "
                         ">= 0")
    return k_max <= k_min


def height_variance(spectrum: DirectionalSpectrum, k_min: float, k_max: float) -> float:
    """Height variance of the band k_min < K < k_max [m^2] (0 for an empty band).

    Parameters
    ----------
    spectrum : DirectionalSpectrum
    k_min, k_max : float
        Band limits [rad/m].
    """
    if _empty_band(k_min, k_max):
        return 0.0
    k = _band_grid(k_min, k_max)
    return float(np.trapezoid(spectrum.omni(k), k))


def slope_variances(
    spectrum: DirectionalSpectrum, k_min: float, k_max: float
) -> tuple[float, float]:
    """Upwind and crosswind slope variances of the band k_min < K < k_max [-].

    Upwind is along the wind direction of ``spectrum``. Computed by quadrature on a
    logarithmic wavenumber grid and a uniform azimuth grid.

    Returns
    -------
    (float, float)
        (s_u^2, s_c^2) [-]; (0, 0) for an empty band (k_max <= k_min).
    """
    if _empty_band(k_min, k_max):
        return 0.0, 0.0
    k = _band_grid(k_min, k_max)[:, None]
    psi = np.linspace(-np.pi, np.pi, _N_PSI, endpoint=False)[None, :]
    dpsi = 2 * np.pi / _N_PSI
    density = spectrum.omni(k) * spectrum.spread(k, psi) * k**2  # K^2 S_1d D
    up = np.trapezoid((density * np.cos(psi) ** 2).sum(axis=1) * dpsi, k[:, 0])
    cross = np.trapezoid((density * np.sin(psi) ** 2).sum(axis=1) * dpsi, k[:, 0])
    return float(up), float(cross)


@dataclass(frozen=True)
class UnresolvedStatistics:
    """Statistics of the sub-grid band k_cut < K < k_max of a sea surface (SI)."""

    k_cut: float  #: grid cut-off wavenumber pi / max(dx, dy) [rad/m]
    k_max: float  #: upper band limit [rad/m]
    height_variance: float  #: [m^2]
    mss_upwind: float  #: slope variance along the wind [-]
    mss_crosswind: float  #: slope variance across the wind [-]

    @property
    def mss(self) -> float:
        """Total mean square slope [-]."""
        return self.mss_upwind + self.mss_crosswind


def unresolved_statistics(
    spectrum: DirectionalSpectrum, dx: float, dy: float, k_max: float
) -> UnresolvedStatistics:
    """Statistics of the waves shorter than a grid of spacing dx, dy [m] resolves.

    Parameters
    ----------
    spectrum : DirectionalSpectrum
    dx, dy : float
        Grid spacings [m].
    k_max : float
        Upper limit of the band [rad/m], e.g. a fraction of the radar wavenumber for the
        slopes that geometric optics sees.
    """
    k_cut = np.pi / max(dx, dy)
    if k_max <= k_cut:
        return UnresolvedStatistics(k_cut, k_max, 0.0, 0.0, 0.0)
    up, cross = slope_variances(spectrum, k_cut, k_max)
    return UnresolvedStatistics(
        k_cut=float(k_cut), k_max=float(k_max),
        height_variance=height_variance(spectrum, k_cut, k_max),
        mss_upwind=up, mss_crosswind=cross,
    )


__all__ = ["UnresolvedStatistics", "height_variance", "slope_variances",
           "unresolved_statistics"]
