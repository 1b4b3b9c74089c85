"""``[propagation]`` section: the Earth under the radar.

``earth = "flat"`` (default) keeps the scene's plane z = 0 as the sea's mean surface
everywhere. ``earth = "spherical"`` draws the rays straight over a sphere of effective
radius k a (standard refraction: k = 4/3; Skolnik, *Introduction to Radar Systems*, 3rd
ed., 2001, chapter 8; Blake, *Radar Range-Performance Analysis*, 1986, chapter 5):
the scene's (x, y) of platforms and targets are distances along the surface from the
origin, z the height above it; targets beyond the radar horizon do not echo
(``seaecho.geometry.earth``, docs/scanning.md). ``multipath = "two-ray"`` multiplies the
echo of point targets and sea facets by the two-ray propagation factor of the sea
(``seaecho.radar.propagation``).
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from .base import Section


class PropagationConfig(Section):
    """The Earth's curvature and the atmosphere's refraction."""

    earth: Literal["flat", "spherical"] = Field(
        "flat",
        description="'flat' (the plane z = 0) or 'spherical' (an Earth of effective radius "
        "earth_radius_factor x 6371 km; platforms and targets beyond the horizon hidden)",
    )
    earth_radius_factor: float = Field(
        4.0 / 3.0, ge=0.5, le=100.0,
        description="effective Earth radius factor k [-] (4/3: standard refraction; "
        "spherical only)",
    )
    multipath: Literal["none", "two-ray"] = Field(
        "none",
        description="sea multipath of point targets and sea facets: 'none', or 'two-ray' "
        "(direct + sea-reflected wave: Fresnel reflection of sea water, rough-sea "
        "specular factor from the sea's rms height, divergence of the spherical Earth; "
        "flat or spherical Earth; ray-traced hulls get theirs from the trace)",
    )
    multipath_shadowing: bool = Field(
        True,
        description="two-ray only: the waves shadow the sea-reflected legs, so that only "
        "the crests lit from both legs reflect (Smith 1967's shadowing; the illuminated "
        "height PDF of Fabbro, Bourlier & Combes 2006): the mirror is raised to their "
        "mean height and the roughness is theirs; false: the mean sea as the mirror with "
        "Miller-Brown-Vegh roughness",
    )


__all__ = ["PropagationConfig"]
