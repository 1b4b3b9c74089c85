"""``[scattering]`` section: the per-facet sea scattering model and how the sea moves.

``model`` chooses the mechanisms of each facet: ``"blend"`` (the paper's Kirchhoff / small
perturbation blend, eqs 10-11) or ``"blend+breaking"`` (plus breaking zones,
Kudryavtsev et al. 2003, placed on the steepest crests of the resolved surface).
``unresolved_tilt`` averages the Bragg term over the slopes of the waves the grid does not
resolve (docs/scattering.md, eq P6), which makes sigma0 independent of the grid spacing.
``sea_motion`` says what happens between two updates of the surface geometry
(``[radar] sea_update_pulses``): ``"held"`` freezes the sea and its speckle (the paper's
section V-B), ``"evolving"`` moves the facets with the waves and evolves their speckle
(Bragg dispersion, orbital motion, finite lifetimes: docs/dynamics.md). ``"auto"`` (the
default) is ``"evolving"`` when the sea is renewed within the run (``sea_update_pulses <
n_pulses``, where a held sea would give clutter that is white from block to block) and
``"held"`` when one surface serves the whole run (the paper's SAR scenes hold it for the
aperture) or there is no sea clutter; :func:`seaecho.build.sea_motion` resolves it.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from .base import Section

ScatteringModelName = Literal["blend", "blend+breaking"]
SeaMotionName = Literal["auto", "held", "evolving"]


class ScatteringConfig(Section):
    """The per-facet scattering model and the motion of the sea between updates."""

    model: ScatteringModelName = Field(
        "blend+breaking",
        description="per-facet mechanisms: 'blend' (Kirchhoff/SPM blend, paper eqs 10-11) "
        "or 'blend+breaking' (plus breaking zones, Kudryavtsev et al. 2003)",
    )
    unresolved_tilt: bool = Field(
        True,
        description="average the Bragg term over the slopes of the unresolved waves "
        "(five-point quadrature): sigma0 independent of the grid spacing",
    )
    sea_motion: SeaMotionName = Field(
        "auto",
        description="between surface updates ([radar] sea_update_pulses): 'held' freezes "
        "the sea and its speckle (the paper), 'evolving' moves the facets with the waves "
        "and evolves the speckle (Bragg lines, orbital motion, finite coherence time); "
        "'auto': 'evolving' when the sea is renewed within the run (sea_update_pulses < "
        "n_pulses, which held would make white clutter), 'held' when one surface serves "
        "every pulse (the paper's SAR scenes)",
    )


__all__ = ["ScatteringConfig", "ScatteringModelName", "SeaMotionName"]
