"""``[[land]]`` entries: a coastline that hides what lies behind it and echoes.

Each entry is a piece of land: the polygon of its shore in the scene's (x, y) plane, a
height profile (the ground rising from the shore to a plateau, eq G1 of
``seaecho.geometry.land``) and its clutter: the constant-gamma model sigma0 = gamma
sin(psi) with gamma by terrain (Barton 1985) or given, and Weibull amplitudes of shape
a_w (Billingsley 2002). The land occludes the sea, the targets and the hulls behind it
(ray traced, with ``[tracing] mode = "raytraced"``) and echoes through the radar
equation like the sea's facets (docs/land.md).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Section

#: Terrains with a published gamma (``seaecho.scattering.land.GAMMA_DB``).
Terrain = Literal["mountains", "urban", "wooded-hills", "rolling-hills", "farmland", "desert",
                  "flatland"]
#: A shore vertex within 1000 km of the origin [m].
_Coord = Annotated[float, Field(ge=-1.0e6, le=1.0e6)]


class LandConfig(Section):
    """A piece of land: shore polygon, height profile, clutter."""

    name: str = Field(..., min_length=1, max_length=100, pattern=r"^[A-Za-z0-9_-]+$",
                      description="unique name of the land (letters, digits, _ -)")
    outline_m: tuple[tuple[_Coord, _Coord], ...] = Field(
        ..., min_length=3, max_length=10_000,
        description="the shore: polygon vertices (x, y), 3 to 10000, either winding, not "
        "closed explicitly; on a spherical Earth distances along the surface [m]")
    height_m: float = Field(..., gt=0.0, le=9000.0,
                            description="plateau height above the sea level [m]")
    shore_width_m: float = Field(
        0.0, ge=0.0, le=1.0e5,
        description="distance inland over which the ground rises linearly from the sea "
        "level to height_m; below resolution_m (e.g. 0): a cliff one facet wide [m]")
    resolution_m: float = Field(
        10.0, ge=0.5, le=1000.0,
        description="facet size of the land's mesh; about a range cell, so that a cell's "
        "amplitude follows the Weibull law [m]")
    terrain: Terrain | None = Field(
        None, description="gamma from Barton (1985) at 10 GHz, scaled as f^(1/2): "
        "'mountains', 'urban' (-5 dB), 'wooded-hills' (-10), 'rolling-hills' (-12), "
        "'farmland', 'desert' (-15), 'flatland' (-20); or give gamma_db")
    gamma_db: float | None = Field(
        None, ge=-60.0, le=10.0,
        description="gamma of the constant-gamma law sigma0 = gamma sin(psi) at the "
        "radar's carrier, instead of terrain [dB]")
    weibull_shape: float = Field(
        2.0, ge=1.0, le=10.0,
        description="Billingsley's Weibull shape a_w of the clutter amplitudes (1: "
        "Rayleigh; Billingsley's interim model: 2.0-5.4 by terrain and depression "
        "angle) [-]")
    echo: bool = Field(True, description="the land echoes (false: it only occludes)")

    @model_validator(mode="after")
    def _gamma(self) -> LandConfig:
        if (self.terrain is None) == (self.gamma_db is None):
            raise ValueError("give either terrain or gamma_db (one of them)")
        pts = self.outline_m
        twice_area = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                         in zip(pts, pts[1:] + pts[:1], strict=True))
        if not abs(twice_area) > 0.0:
            raise ValueError(f"outline_m: the polygon of {len(pts)} vertices has no area")
        return self


__all__ = ["LandConfig", "Terrain"]
