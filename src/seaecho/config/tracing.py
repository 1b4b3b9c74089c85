"""``[tracing]`` section (facet mode, Mitsuba variant, refresh) and ``[[objects]]`` entries.

``[tracing]`` chooses how facets are seen from the transmitter and the receiver:
``mode = "raytraced"`` (Sionna RT / Mitsuba shadow rays against the sea and the objects) or
``"analytic"`` (normals from analytic slopes, Smith's statistical shadowing or none).

``[[objects]]`` adds geometry that occludes the sea in ray-traced mode: a mesh file
(PLY/OBJ/STL, through trimesh) or a Mitsuba/Sionna XML scene, placed by position,
orientation and velocity, with a radio material (an ITU name or a custom permittivity).
Paths are relative to the scene file's folder. With ``scatterer = true`` the object also
echoes (shooting and bouncing rays with physical optics, sea multipath; docs/ship.md).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Name, Section, short_repr

#: Shortest refresh interval [s]: the shortest pulse repetition interval, 1 / 1e7 Hz.
MIN_REFRESH_S = 1.0e-7
#: Mitsuba variants seaecho can trace with (polarised, differentiable, mono-spectral).
VariantName = Literal["llvm_ad_mono_polarized", "cuda_ad_mono_polarized"]
#: ITU-R P.2040 materials known to Sionna RT (``sionna.rt.ITURadioMaterial``).
ItuMaterial = Literal[
    "concrete", "brick", "plasterboard", "wood", "glass", "ceiling_board", "chipboard",
    "plywood", "marble", "floorboard", "metal", "very_dry_ground", "medium_dry_ground",
    "wet_ground",
]


class TracingConfig(Section):
    """How facets are seen from the transmitter and the receiver."""

    mode: Literal["raytraced", "analytic"] = Field(
        "raytraced",
        description="'raytraced' (shadow rays on Sionna RT / Mitsuba against sea and objects)"
        " or 'analytic' (normals from analytic slopes, no ray tracing)",
    )
    variant: VariantName = Field(
        "llvm_ad_mono_polarized",
        description="Mitsuba variant: 'llvm_ad_mono_polarized' (CPU) or "
        "'cuda_ad_mono_polarized' (needs a CUDA GPU)",
    )
    shadowing: Literal["smith", "none"] = Field(
        "smith",
        description="analytic mode only: weight facets by Smith's statistical shadowing "
        "(Smith 1967; bistatic: Bourlier et al. 2002) or by the facing test alone",
    )
    subfacet_shadowing: bool = Field(
        False,
        description="both modes: multiply visibility by Smith's bistatic shadowing of the "
        "unresolved slopes, 1 / (1 + Lambda_i + Lambda_s) at the local angles (Sancer 1969;"
        " Bourlier et al. 2002), sub-grid slopes of the band up to k/3",
    )
    periodic_apron: bool = Field(
        False,
        description="raytraced mode: also trace each facet's shadow rays against the sea "
        "tile's periodic copies in front of it (the FFT sea is periodic: its continuation),"
        " as far as the highest wave can shadow (z_max / tan(grazing)); without it the "
        "facets near the tile's edge towards the radar have no waves in front of them "
        "(low grazing angles: docs/scanning.md)",
    )
    refresh_interval_s: float = Field(
        0.0, ge=0.0, le=3600.0,
        description="visibility (BVH rebuild + shadow rays) is computed on the surface at "
        "t_ref = floor(t / interval) * interval and reused until the next multiple; "
        "0 = every time step [s]; otherwise at least 1e-7 s, the shortest pulse repetition "
        "interval (a shorter interval refreshes at every pulse, as 0 does)",
    )

    @model_validator(mode="after")
    def _refresh(self) -> TracingConfig:
        if 0.0 < self.refresh_interval_s < MIN_REFRESH_S:
            raise ValueError(
                f"refresh_interval_s = {self.refresh_interval_s:g}: give 0 (every pulse) or "
                f"at least {MIN_REFRESH_S:g} s, the shortest pulse repetition interval "
                "([radar].prf_hz <= 1e7); t / interval overflowed")
        return self


#: A coordinate within 1000 km of the origin [m].
_Coord = Annotated[float, Field(ge=-1.0e6, le=1.0e6)]
#: An angle in degrees within one turn either way [deg].
_Angle = Annotated[float, Field(ge=-360.0, le=360.0)]
#: A velocity component up to 1 km/s [m/s].
_Speed = Annotated[float, Field(ge=-1.0e3, le=1.0e3)]


class ObjectConfig(Section):
    """A mesh or Mitsuba/Sionna XML scene placed in the scene (ship hull, breakwater, ...)."""

    name: str = Field(..., min_length=1, max_length=100, pattern=r"^[A-Za-z0-9_-]+$",
                      description="unique object name (letters, digits, _ -)")
    file: Name = Field(..., min_length=1, max_length=1000,
                      description="mesh (.ply, .obj, .stl) or Mitsuba/Sionna scene (.xml), "
                      "relative to the scene file's folder")
    position_m: tuple[_Coord, _Coord, _Coord] = Field(
        (0.0, 0.0, 0.0),
        description="(x, y, z) of the object's origin at time 0, each within +-1e6 [m]")
    orientation_deg: tuple[_Angle, _Angle, _Angle] = Field(
        (0.0, 0.0, 0.0),
        description="rotation (yaw about z, pitch about y, roll about x), applied to the "
        "file's coordinates in the order roll, pitch, yaw (Sionna's convention), each "
        "within +-360 [deg]",
    )
    velocity_m_s: tuple[_Speed, _Speed, _Speed] = Field(
        (0.0, 0.0, 0.0), description="constant velocity of the object, each component "
        "within +-1000 [m/s]")
    scale: float = Field(1.0, gt=0.0, le=1.0e4, description="scale applied to the file [-]")
    follow_ship: bool = Field(
        False,
        description="place the object on the [ship]: position (x, y) and velocity from its "
        "track, yaw from its heading (added to orientation_deg[0])",
    )
    material: ItuMaterial | None = Field(
        None, description="ITU-R P.2040 material name (default 'metal' for meshes; for XML "
        "the file's own materials are kept unless this is given)")
    relative_permittivity: float | None = Field(
        None, ge=1.0, le=1.0e3, description="custom relative permittivity eps' [-] "
        "(instead of an ITU material)")
    conductivity_s_m: float | None = Field(
        None, ge=0.0, le=1.0e8, description="custom conductivity [S/m] (with "
        "relative_permittivity)")
    # The object's own echo (docs/ship.md): shooting and bouncing rays + physical optics
    scatterer: bool = Field(False, description="add the object's own echo (SBR + physical "
                            "optics, with sea multipath) to the sea's, in every pulse")
    max_bounces: int = Field(3, ge=1, le=10, description="scatterer: hits followed per ray "
                             "(3: plates, dihedrals, trihedrals) [-]")
    rays_per_wavelength: float = Field(4.0, ge=1.0, le=32.0, description="scatterer: launch "
                                       "rays per wavelength along each axis (4: 16 per "
                                       "lambda^2) [-]")
    signature_refresh_deg: float = Field(1.0, gt=0.0, le=90.0, description="scatterer: trace "
                                         "again when the direction to the transmitter or "
                                         "receiver has turned by this much; between traces "
                                         "the centres move rigidly [deg]")
    signature_refresh_s: float = Field(0.0, ge=0.0, le=3600.0, description="scatterer: also "
                                       "trace again after this time (0 = by aspect only) [s]")
    signature_cell_m: float = Field(0.1, gt=0.0, le=10.0, description="scatterer: side of "
                                    "the cells ray contributions are summed in (scattering "
                                    "centres) [m]")
    sea_multipath: bool = Field(True, description="scatterer: add the paths that bounce on "
                                "the mean sea (Fresnel x rough-sea factor, image method)")

    @model_validator(mode="after")
    def _material(self) -> ObjectConfig:
        custom = self.relative_permittivity is not None or self.conductivity_s_m is not None
        if custom and self.material is not None:
            raise ValueError("give either material (ITU name) or relative_permittivity/"
                             "conductivity_s_m, not both")
        if self.conductivity_s_m is not None and self.relative_permittivity is None:
            raise ValueError("conductivity_s_m needs relative_permittivity")
        own = {"max_bounces", "rays_per_wavelength", "signature_refresh_deg",
               "signature_refresh_s", "signature_cell_m", "sea_multipath"}
        # given with other values than the defaults (a scene written back in full, as a
        # run's scene_json, holds the defaults and reads back)
        given = {f for f in own & self.model_fields_set
                 if getattr(self, f) != type(self).model_fields[f].default}
        if not self.scatterer and given:
            raise ValueError(f"{', '.join(sorted(given))}: only with scatterer = true")
        suffix = self.file.rsplit(".", 1)[-1].lower() if "." in self.file else ""
        if suffix not in ("ply", "obj", "stl", "xml"):
            raise ValueError(f"file = {short_repr(self.file)}: allowed extensions .ply, .obj, "
                             ".stl, .xml")
        return self

    @property
    def moving(self) -> bool:
        """True if the object moves (own velocity or following the ship)."""
        return self.follow_ship or any(v != 0.0 for v in self.velocity_m_s)


__all__ = ["MIN_REFRESH_S", "ItuMaterial", "ObjectConfig", "TracingConfig", "VariantName"]
