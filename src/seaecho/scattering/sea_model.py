"""The sea as the per-facet scattering model sees it: :class:`SeaModel`, plain values.

A facet of the resolved surface carries the waves the grid does not resolve (the
two-scale split of :mod:`seaecho.ocean.twoscale`): their slopes (tilting band, up to
k_cut = k/3) for the Kirchhoff / geometric-optics part and for the sub-facet shadowing,
their height spectrum at the Bragg vector (roughness band, grid Nyquist to 20 k) for
the small-perturbation part. :func:`seaecho.build.build_sea_model` makes the one of a
scene; the simulation, ``seaecho compare`` and the tracing stage's sub-facet shadowing
all read this one object, so they cannot disagree.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from dataclasses import dataclass

from .breaking import THETA_WB, BreakingStatistics
from .dynamics import SeaDynamics
from .facet import FacetModel, TiltQuadrature
from .spectrum_table import BraggSpectrumTable


@dataclass(frozen=True)
class SeaModel:
    """Radar-frequency view of a sea state (SI).

    Attributes
    ----------
    frequency : float
        Radar carrier frequency [Hz].
    k : float
        Electromagnetic wavenumber 2 pi f / c [rad/m].
    eps_r : complex
        Sea-water relative permittivity eps' - j eps'' at ``frequency`` [-].
    wind_direction : float
        Direction the wind blows towards, counter-clockwise from +x [rad].
    k_grid : float
        Grid Nyquist wavenumber pi / max(dx, dy) [rad/m]: the start of both bands.
    k_cut : float
        Two-scale split [rad/m]: end of the tilting band.
    k_max : float
        End of the Bragg roughness band [rad/m].
    mss_upwind, mss_crosswind : float
        Slope variances of the tilting band k_grid < K < k_cut, along and across the
        wind [-].
    roughness_height_variance : float
        Height variance of the roughness band k_grid < K < k_max [m^2] (SPM validity).
    bragg_spectrum : BraggSpectrumTable
        Height spectrum W(K) of the roughness band, tabulated (0 outside it) [m^4].
    tilt : TiltQuadrature or None
        Nodes of the average of the Bragg term over the unresolved tilts (eq P6), or None
        for the paper's facet model (Bragg term of the facet's own plane only).
    breaking : BreakingStatistics or None
        Breaking zones of the sea at this carrier (KHCC03, eq BR3), or None without them.
    dynamics : SeaDynamics or None
        How the facets' speckle evolves between pulses (eqs D2-D8), or None for a held
        sea.
    """

    frequency: float
    k: float
    eps_r: complex
    wind_direction: float
    k_grid: float
    k_cut: float
    k_max: float
    mss_upwind: float
    mss_crosswind: float
    roughness_height_variance: float
    bragg_spectrum: BraggSpectrumTable
    tilt: TiltQuadrature | None = None
    breaking: BreakingStatistics | None = None
    dynamics: SeaDynamics | None = None

    @property
    def facet_model(self) -> FacetModel:
        """The sea's scattering inputs of ``scattering.facet`` (eqs P1-P7), whole: k,
        eps_r, the Bragg spectrum table, the tilting band's slope variances, the wind
        direction, the tilt nodes (eq P6) and the breaking zones' forward tilt
        ``theta_wb A_wb`` (BR5). The simulation, its fused kernel and ``seaecho compare``
        take this one object."""
        eps = 0.0 if self.breaking is None else THETA_WB * self.breaking.mean_direction
        return FacetModel(k=self.k, eps_r=self.eps_r, spectrum=self.bragg_spectrum,
                          mss_upwind=self.mss_upwind, mss_crosswind=self.mss_crosswind,
                          wind_direction=self.wind_direction, tilt=self.tilt,
                          breaking_tilt=float(eps))

    @property
    def subfacet(self) -> tuple[float, float, float]:
        """(mss_upwind, mss_crosswind, wind_direction) of the tilting band, for the
        tracing stage's sub-facet shadowing."""
        return (self.mss_upwind, self.mss_crosswind, self.wind_direction)


__all__ = ["SeaModel"]
