"""The two-scale split: statistics of the waves the grid does not resolve.

The grid resolves wavenumbers up to its Nyquist wavenumber
k_N = pi / max(dx, dy); shorter waves are the sub-facet roughness that the scattering
models treat statistically (docs/conventions.md, "Two scales"). For a band
k_min < K < k_max of the directional spectrum Psi (paper eq 4):

.. math::

    \\langle z^2 \\rangle_{band} = \\int_{k_{min}}^{k_{max}} S_{1d}(K)\\,dK

    s_u^2 = \\int_{k_{min}}^{k_{max}}\\!\\int_{-\\pi}^{\\pi} K^2\\cos^2\\psi\\;
        S_{1d}(K) D(K,\\psi)\\,d\\psi\\,dK,\\qquad
    s_c^2 = \\int\\!\\!\\int K^2\\sin^2\\psi\\; S_{1d} D\\,d\\psi\\,dK

the height variance and the upwind / crosswind slope variances (Cox & Munk 1954
definitions; e.g. Elfouhaily et al. 1997).

The bands every stage uses are fixed here, once (with k the radar wavenumber):

- the *tilting* band k_N < K < k_cut, k_cut = :data:`TWO_SCALE_CUT_RATIO` k = k / 3:
  waves long against the radar wavelength, whose slopes tilt the specular points of the
  Kirchhoff / geometric-optics part and shadow each other (sub-facet shadowing). The
  split at a third of the radar wavenumber is a modelling choice common to two-scale
  models (Brown 1978 discusses how the result depends on it; Valenzuela 1978 reviews
  the model), not a measured constant; ``seaecho sigma --cut-ratio`` varies it for the
  mean-plane models;
- the *Bragg roughness* k_N < K < k_max, k_max = :data:`ROUGHNESS_K_MAX_RATIO` k = 20 k:
  the height spectrum the small-perturbation part reads at the Bragg wavenumber. The
  local Bragg wavenumber never exceeds 2 k (back-scatter at grazing incidence); the table
  reaches ten times further so that no geometry reads its edge; for a tail
  S_1d ~ K^-3 the variance above 20 k is (1/60)^2 of the variance above k/3;
- the small-perturbation validity bound k h <= :data:`SPM_KH_MAX` = 0.3 on the rms
  height h of the Bragg roughness (Thorsos & Jackson 1989; Ulaby, Moore & Fung 1982).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] C. Cox and W. Munk, "Measurement of the roughness of the sea surface from
   photographs of the sun's glitter", J. Opt. Soc. Am. 44(11), 838-850, 1954.
.. [2] T. Elfouhaily et al., J. Geophys. Res. 102(C7), 15781-15796, 1997.
.. [3] G. S. Brown, "Backscattering from a Gaussian-distributed perfectly conducting
   rough surface", IEEE Trans. Antennas Propag. 26(3), 472-482, 1978.
.. [4] G. R. Valenzuela, "Theories for the interaction of electromagnetic and oceanic
   waves - a review", Boundary-Layer Meteorol. 13, 61-85, 1978.
.. [5] E. I. Thorsos and D. R. Jackson, "The validity of the perturbation approximation
   for rough surface scattering using a Gaussian roughness spectrum", J. Acoust. Soc. Am.
   86(1), 261-277, 1989.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .spectra import DirectionalSpectrum

#: Two-scale split k_cut / k [-]: waves with K < k_cut tilt, shorter ones are Bragg
#: roughness (module docstring; Brown 1978).
TWO_SCALE_CUT_RATIO = 1.0 / 3.0
#: Upper end of the Bragg roughness band k_max / k [-] (module docstring).
ROUGHNESS_K_MAX_RATIO = 20.0
#: Small-perturbation validity bound on k h [-] (Thorsos & Jackson 1989).
SPM_KH_MAX = 0.3

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
    """Statistics of the sub-grid band k_grid < K < k_max of a sea surface (SI)."""

    k_grid: float  #: grid Nyquist wavenumber pi / max(dx, dy) [rad/m], lower band limit
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
    k_grid = np.pi / max(dx, dy)
    if k_max <= k_grid:
        return UnresolvedStatistics(float(k_grid), float(k_max), 0.0, 0.0, 0.0)
    up, cross = slope_variances(spectrum, k_grid, k_max)
    return UnresolvedStatistics(
        k_grid=float(k_grid), k_max=float(k_max),
        height_variance=height_variance(spectrum, k_grid, k_max),
        mss_upwind=up, mss_crosswind=cross,
    )


def orbital_velocity_covariance(spectrum: DirectionalSpectrum, k_min: float, k_max: float,
                                depth: float | None = None) -> np.ndarray:
    r"""Covariance of the surface particle velocity of the band k_min < K < k_max [m^2/s^2].

    Linear waves: a wave of amplitude a, wavenumber K and frequency omega moves the
    surface particles horizontally with ``omega coth(K d) a`` along K, in phase with the
    elevation, and vertically with ``omega a`` in quadrature (Lamb 1932, art. 228), so

    .. math::
        C_{hh} = \int \omega^2 \coth^2(Kd)\, \hat K \hat K^T \Psi\, d^2K, \quad
        C_{zz} = \int \omega^2 \Psi\, d^2K, \quad C_{hz} = 0      (U2)

    (``Psi`` the directional spectrum of eq 4, ``omega`` eq 15 with surface tension).

    Returns
    -------
    ndarray (3, 3)
        Velocity covariance in the world frame (x east, y north, z up) [m^2/s^2].
    """
    from .dispersion import angular_frequency, horizontal_to_vertical_ratio

    k = _band_grid(k_min, k_max)[:, None]
    psi = np.linspace(-np.pi, np.pi, _N_PSI, endpoint=False)[None, :]
    dpsi = 2 * np.pi / _N_PSI
    w2 = angular_frequency(k, depth) ** 2
    coth2 = horizontal_to_vertical_ratio(k, depth) ** 2
    density = spectrum.omni(k) * spectrum.spread(k, psi) * w2  # omega^2 S_1d D
    az = psi + spectrum.wind_direction
    c = np.empty((3, 3))
    c[:] = 0.0
    for i, fi in enumerate((np.cos(az), np.sin(az))):
        for j, fj in enumerate((np.cos(az), np.sin(az))):
            c[i, j] = np.trapezoid((density * coth2 * fi * fj).sum(axis=1) * dpsi, k[:, 0])
    c[2, 2] = np.trapezoid(density.sum(axis=1) * dpsi, k[:, 0])
    return c


def mean_wave_period(spectrum: DirectionalSpectrum, k_min: float, k_max: float,
                     weight: str = "slope", depth: float | None = None) -> float:
    """Mean period ``2 pi / <omega>`` of the band k_min < K < k_max [s].

    ``<omega>`` is weighted by the slope spectrum ``K^2 S_1d`` (``weight="slope"``, the
    waves that tilt the specular points) or by ``S_1d`` (``"height"``).
    """
    from .dispersion import angular_frequency

    k = _band_grid(k_min, k_max)
    s = spectrum.omni(k) * (k**2 if weight == "slope" else 1.0)
    w = angular_frequency(k, depth)
    return float(2 * np.pi * np.trapezoid(s, k) / np.trapezoid(s * w, k))


#: How a facet's normal is made from the grid (:func:`facet_slope_deficit`).
FACET_NORMALS = ("mesh", "vertex-mean")


def _triangle_filters(kx, ky, dx: float, dy: float, normals: str):
    """Slope responses ``(G_x, G_y)`` of the two triangles of a cell to ``exp(j K.r)``.

    ``"mesh"``: the plane through the three vertices (the ray-traced facets);
    ``"vertex-mean"``: the mean of the exact slopes ``j K`` at the three vertices (the
    analytic facets). Triangles of :mod:`seaecho.geometry.mesh`: (0,0), (dx,0), (dx,dy)
    and (0,0), (dx,dy), (0,dy).
    """
    ex, ey = np.exp(1j * kx * dx), np.exp(1j * ky * dy)
    if normals == "mesh":
        return (((ex - 1.0) / dx, ex * (ey - 1.0) / dy),
                (ey * (ex - 1.0) / dx, (ey - 1.0) / dy))
    h0 = (1.0 + ex + ex * ey) / 3.0
    h1 = (1.0 + ex * ey + ey) / 3.0
    return ((1j * kx * h0, 1j * ky * h0), (1j * kx * h1, 1j * ky * h1))


def facet_slope_deficit(spectrum: DirectionalSpectrum, size: tuple[float, float],
                        shape: tuple[int, int], normals: str = "mesh") -> tuple[float, float]:
    """Slope variance of the *resolved* waves that the facets' normals do not carry [-].

    A facet's normal is a plane through (or a mean over) its three vertices: for a
    wave of wavenumber K near the grid's Nyquist wavenumber it is a finite difference
    over the facet, not the slope at its centre, and the facets carry less slope variance
    than the synthesised surface. For a mode ``exp(j K.r)`` the slope of a triangle is
    ``G(K)`` (``(exp(j K_x dx) - 1) / dx`` ... for the plane through the vertices,
    ``j K`` times the mean of the vertex phases for the mean of the vertex slopes) instead
    of ``j K``; summed over the tile's modes with the spectrum's variances,

    .. math::
        \\Delta C = \\sum_{\\mathbf K} \\Psi(\\mathbf K)\\,\\delta K_x\\delta K_y
        \\left[\\mathbf K \\mathbf K^T - \\overline{\\mathrm{Re}\\,\\mathbf G\\mathbf G^H}
        \right] \\qquad \text{(U1)}

    (bar: mean over the two triangles of a cell), projected on the wind axes. The
    two-scale model must give this variance to the sub-facet slopes as well, or the tilts
    between the facets' effective resolution and the grid's Nyquist wavenumber are lost.

    Parameters
    ----------
    spectrum : DirectionalSpectrum
    size : (float, float)
        Tile extents (Lx, Ly) [m].
    shape : (int, int)
        Grid nodes (ny, nx).
    normals : {"mesh", "vertex-mean"}
        Facet normals of the ray-traced mode (plane through the vertices) or of the
        analytic mode (mean of the analytic slopes at the vertices).

    Returns
    -------
    (float, float)
        Deficit of the slope variance along and across the wind [-].
    """
    if normals not in FACET_NORMALS:
        raise ValueError(f"normals = {normals!r}: allowed {FACET_NORMALS}")
    lx, ly = (float(v) for v in size)
    ny, nx = (int(v) for v in shape)
    dx, dy = lx / nx, ly / ny
    kx = (2 * np.pi * np.fft.fftfreq(nx, dx))[None, :]
    ky = (2 * np.pi * np.fft.fftfreq(ny, dy))[:, None]
    psi = np.asarray(spectrum(np.broadcast_to(kx, (ny, nx)), np.broadcast_to(ky, (ny, nx))),
                     dtype=float).copy()
    psi[0, 0] = 0.0
    psi[ny // 2, :] = 0.0  # the synthesis leaves the Nyquist row and column empty
    psi[:, nx // 2] = 0.0
    w = psi * (2 * np.pi / lx) * (2 * np.pi / ly)
    c_true = np.array([[np.sum(w * kx * kx), np.sum(w * kx * ky)],
                       [np.sum(w * kx * ky), np.sum(w * ky * ky)]])
    c_facet = np.zeros((2, 2))
    for g in _triangle_filters(kx, ky, dx, dy, normals):
        for i in range(2):
            for j in range(2):
                c_facet[i, j] += 0.5 * np.sum(w * (g[i] * np.conj(g[j])).real)
    d = c_true - c_facet  # Eq U1
    u = np.array([np.cos(spectrum.wind_direction), np.sin(spectrum.wind_direction)])
    c = np.array([-u[1], u[0]])
    return float(u @ d @ u), float(c @ d @ c)


__all__ = ["FACET_NORMALS", "ROUGHNESS_K_MAX_RATIO", "SPM_KH_MAX", "TWO_SCALE_CUT_RATIO",
           "UnresolvedStatistics", "facet_slope_deficit", "height_variance",
           "mean_wave_period", "orbital_velocity_covariance", "slope_variances",
           "unresolved_statistics"]
