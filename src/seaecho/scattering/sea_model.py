"""The sea as the per-facet scattering model sees it: :class:`SeaModel`, plain values.

A facet of the resolved surface carries the waves the grid does not resolve (the
two-scale split of :mod:`seaecho.ocean.twoscale`): their slopes (tilting band, up to
k_cut = k/3) for the Kirchhoff / geometric-optics part and for the sub-facet shadowing,
their height spectrum at the Bragg vector (roughness band, grid Nyquist to 20 k) for
the small-perturbation part. :func:`seaecho.build.build_sea_model` makes the one of a
scene; the simulation, ``seaecho compare`` and the tracing stage's sub-facet shadowing
all read this one object, so they cannot disagree.
"""

from __future__ import annotations

from dataclasses import dataclass

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

    @property
    def facet_model(self) -> tuple:
        """The positional arguments after the geometry of ``scattering.facet.facet_terms``,
        ``facet_sigma`` and ``speckled_facet_amplitudes``: (k, eps_r, spectrum,
        mss_upwind, mss_crosswind, wind_direction)."""
        return (self.k, self.eps_r, self.bragg_spectrum, self.mss_upwind,
                self.mss_crosswind, self.wind_direction)

    @property
    def subfacet(self) -> tuple[float, float, float]:
        """(mss_upwind, mss_crosswind, wind_direction) of the tilting band, for the
        tracing stage's sub-facet shadowing."""
        return (self.mss_upwind, self.mss_crosswind, self.wind_direction)


__all__ = ["SeaModel"]
