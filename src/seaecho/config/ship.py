"""``[ship]`` section, and ``[[ships]]``: the ships that make wakes (and hull echoes).

``[ship]`` is one ship; ``[[ships]]`` an array of them, each with a ``name``, on a
straight course (``heading_deg``, ``position_m``) or on waypoints (``waypoints_m``,
legs at constant speed joined by turns at ``turn_rate_deg_s`` or ``turn_radius_m``).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, model_validator

from ..constants import KNOT
from .base import Name, Section, short_repr

#: Minimum phase speed of capillary-gravity waves on clean water, (4 g sigma / rho)^(1/4)
#: = 0.23 m/s (H. Lamb, *Hydrodynamics*, 6th ed., 1932, art. 268): a hull slower than
#: this makes no steady wave pattern.
MIN_WAVE_SPEED_M_S = 0.23
#: Shortest hull [m]: 37 capillary lengths sqrt(sigma / (rho g)) = 2.7 mm, so that the
#: gravity-wave (thin-ship) theory of the wake applies.
MIN_LENGTH_M = 0.1
#: Most slender hull, B / L: below the slenderest real hulls (racing shells, ~0.03); a
#: beam of 5e-324 m made the turbulent wake's edge 0 / 0.
MIN_BEAM_RATIO = 0.01


#: Metacentric height over beam, GM / B, by default [-] (a modelling choice; docs/targets.md).
DEFAULT_GM_OVER_BEAM = 0.05

#: Fastest turn [deg/s]: small fast craft turn at up to ~10 deg/s; 30 bounds any hull.
MAX_TURN_RATE_DEG_S = 30.0


class ShipConfig(Section):
    """A ship sailing at constant speed: a straight course, or legs between waypoints."""

    name: Name = Field("", max_length=200,
                       description="a label for the ship (default ship0, ship1, ...)")

    length_m: float = Field(
        ..., ge=MIN_LENGTH_M, le=500.0,
        description="waterline length L [m]; from 0.1 m (thin-ship wave theory neglects "
        "surface tension: the hull must be much longer than the 2.7 mm capillary length)")
    beam_m: float = Field(..., gt=0.0, le=80.0, description="beam B [m]")
    draft_m: float = Field(..., gt=0.0, le=30.0, description="draft T [m]")
    speed_kn: float | None = Field(
        None, ge=0.0, le=60.0, description="speed through the water [kn]; or give speed_m_s"
    )
    speed_m_s: float | None = Field(
        None, ge=0.0, le=31.0, description="speed through the water [m/s]; or give speed_kn"
    )
    heading_deg: float = Field(
        0.0,
        ge=-360.0,
        le=360.0,
        description="course the ship sails towards, counter-clockwise from +x (east) [deg]",
    )
    position_m: tuple[float, float] = Field(
        (0.0, 0.0), description="(x, y) of the hull centre at time 0 [m]"
    )
    kelvin_wake: bool = Field(True, description="add the Kelvin wake (paper eq 16) to the sea")
    narrow_v: bool = Field(
        False,
        description="add the narrow-V wake: the Bragg-scale divergent waves of the hull raise "
        "the sub-facet Bragg spectrum in two arms of a few degrees about the track "
        "(docs/wake.md; needs [radar], whose Bragg vector it uses); off by default: their "
        "height is Michell's theory capped at the breaking steepness, a bound not checked "
        "against a measured arm brightness",
    )
    turbulent_wake_length_m: float | None = Field(
        None,
        ge=0.0,
        le=1.0e5,
        description="length of the turbulent (damped) wake strip behind the stern [m]; "
        "default 20 ship lengths",
    )
    wake_amplitude: Literal["kriebel-seelig", "michell"] = Field(
        "kriebel-seelig",
        description="Kelvin-wake heights: Michell's thin-ship theory scaled to the empirical "
        "maximum height of Kriebel & Seelig (2005), or as Michell's theory gives them",
    )
    wake_breaking_limit: bool = Field(
        True, description="cap the Kelvin wake's waves at the breaking steepness H/L = 0.1412"
    )
    turbulent_wake_film_contrast_db: float | None = Field(
        None, ge=-30.0, le=0.0,
        description="override of the Bragg contrast of the turbulent wake's surfactant film "
        "[dB]; default: the Marangoni damping of the film at the radar's Bragg wavenumber "
        "(Alpers & Huehnerfuss 1989, docs/wake.md)",
    )
    turbulent_wake_film_elasticity_mn_m: float = Field(
        10.0, ge=0.0, le=1000.0,
        description="dilational modulus of the turbulent wake's surfactant film [mN/m]; "
        "order of 10 mN/m for natural films (Alpers & Huehnerfuss 1988)",
    )
    waypoints_m: tuple[tuple[float, float], ...] | None = Field(
        None, min_length=2, max_length=1000,
        description="sail through these (x, y) points, each within +-1e7 [m], at the "
        "first at time 0, instead of heading_deg and position_m; legs at constant speed, "
        "corners rounded by turns of turn_rate_deg_s or turn_radius_m (docs/targets.md)",
    )
    turn_rate_deg_s: float | None = Field(
        None, gt=0.0, le=MAX_TURN_RATE_DEG_S,
        description="rate of turn at the waypoints [deg/s] (radius speed / rate); or give "
        "turn_radius_m",
    )
    turn_radius_m: float | None = Field(
        None, gt=0.0, le=1.0e5, description="radius of the turns at the waypoints [m]; or "
        "give turn_rate_deg_s",
    )
    hull_echo: bool = Field(
        False, description="add the hull's own echo (shooting and bouncing rays, sea "
        "multipath; docs/ship.md) with the [[objects]] scatterer defaults; on waypoints_m "
        "the hull follows the route and turns with it",
    )
    wave_motion: bool = Field(
        False, description="hull_echo: the hull heaves, pitches and rolls with the sea under "
        "its waterplane (quasi-static wave following; docs/targets.md); needs the sea "
        "([radar] sea_clutter = true)",
    )
    wave_response: Literal["dynamic", "quasi-static"] = Field(
        "dynamic", description="wave_motion: 'dynamic', heave, pitch and roll of a box "
        "hull L x B x T as damped oscillators at their natural periods driven by the "
        "random sea (docs/targets.md); 'quasi-static', the plane fitted to the held sea "
        "under the waterplane (no resonance, wakes included)")
    metacentric_height_m: float | None = Field(
        None, gt=0.0, le=20.0,
        description="wave_motion 'dynamic': transverse metacentric height GM [m], which "
        "sets the natural roll period 2 pi k_xx / sqrt(g GM) with k_xx = 0.35 beam_m; "
        "default 0.05 beam_m (a modelling choice: roll periods of ~5 s for a 10 m boat, "
        "~11 s for an 80 m ship)")
    hull_rays_per_wavelength: float | None = Field(
        None, ge=1.0, le=32.0,
        description="hull_echo: launch density of the shooting-and-bouncing rays [rays "
        "per wavelength along each axis]; default the [[objects]] default, 4 (the "
        "trace's cost goes with its square: docs/ship.md)")
    hull_mesh: str | None = Field(
        None, min_length=1, max_length=4096,
        description="hull_echo: mesh file (.ply, .obj, .stl; x forward, y to port, z up, "
        "waterline z = 0), relative to the scene file's folder; default the generic ship "
        "of seaecho.geometry.vessel scaled to length_m, beam_m, draft_m",
    )

    @model_validator(mode="after")
    def _route(self) -> ShipConfig:
        if self.hull_mesh is not None:
            if not self.hull_echo:
                raise ValueError("hull_mesh is only used with hull_echo = true")
            suffix = self.hull_mesh.rsplit(".", 1)[-1].lower() if "." in self.hull_mesh else ""
            if suffix not in ("ply", "obj", "stl"):
                raise ValueError(f"hull_mesh = {short_repr(self.hull_mesh)}: allowed "
                                 "extensions .ply, .obj, .stl")
        if not self.wave_motion and ("wave_response" in self.model_fields_set
                                     and self.wave_response != "dynamic"
                                     or self.metacentric_height_m is not None):
            raise ValueError("wave_response / metacentric_height_m are for wave_motion = "
                             "true")
        if self.hull_rays_per_wavelength is not None and not self.hull_echo:
            raise ValueError("hull_rays_per_wavelength is only used with hull_echo = true")
        if self.wave_motion and not self.hull_echo:
            raise ValueError("wave_motion moves the hull echo: it needs hull_echo = true")
        turn = self.turn_rate_deg_s is not None or self.turn_radius_m is not None
        if self.waypoints_m is None:
            if turn:
                raise ValueError("turn_rate_deg_s / turn_radius_m are for a ship on "
                                 "waypoints_m")
            return self
        # given with other values than the defaults (a scene written back in full, as a
        # run's scene_json, holds the defaults and reads back)
        given = {f for f in {"heading_deg", "position_m"} & self.model_fields_set
                 if getattr(self, f) != type(self).model_fields[f].default}
        if given:
            raise ValueError(f"waypoints_m sets the track: give no {' or '.join(sorted(given))}")
        if self.turn_rate_deg_s is not None and self.turn_radius_m is not None:
            raise ValueError("give turn_rate_deg_s or turn_radius_m, not both")
        w = self.waypoints_m
        if any(abs(c) > 1.0e7 for p in w for c in p):
            raise ValueError(f"waypoints_m = {short_repr(w)}: each coordinate must be within "
                             "+-1e7 m")
        if (self.speed_kn is None) == (self.speed_m_s is None):  # (before its validator)
            raise ValueError("give exactly one of speed_kn and speed_m_s")
        if self.speed == 0.0:
            raise ValueError("a ship on waypoints_m needs a speed > 0")
        legs = [math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(w, w[1:], strict=False)]
        if min(legs) == 0.0:
            i = legs.index(0.0)
            raise ValueError(f"waypoints_m: points {i} and {i + 1} coincide")
        heads = [math.atan2(b[1] - a[1], b[0] - a[0]) for a, b in zip(w, w[1:], strict=False)]
        turns = [abs(math.remainder(b - a, 2 * math.pi)) for a, b in
                 zip(heads, heads[1:], strict=False)]
        if any(t > 1e-12 for t in turns) and not turn:
            raise ValueError("waypoints_m turns: give turn_rate_deg_s or turn_radius_m")
        if any(t > math.pi - 1e-9 for t in turns):
            raise ValueError("waypoints_m: the track turns back on itself (180 deg); add an "
                             "intermediate waypoint")
        # the turns must fit on the legs (the corner cut R tan(|Delta| / 2) of
        # seaecho.wake.ship.Route, checked again there)
        r = self.turn_radius
        cut = [0.0] + [r * math.tan(0.5 * t) for t in turns] + [0.0]
        for i, n in enumerate(legs):
            if cut[i] + cut[i + 1] > n * (1.0 + 1e-12):
                raise ValueError(
                    f"waypoints_m: leg {i} is {n:.4g} m long but the turns at radius "
                    f"{r:.4g} m need {cut[i] + cut[i + 1]:.4g} m; a faster turn rate, a "
                    "smaller turn_radius_m or waypoints further apart")
        return self

    @property
    def turn_radius(self) -> float:
        """Radius of the turns [m]: turn_radius_m, or speed / turn rate (inf when none)."""
        if self.turn_radius_m is not None:
            return float(self.turn_radius_m)
        if self.turn_rate_deg_s is not None:
            return self.speed / math.radians(self.turn_rate_deg_s)
        return math.inf

    @model_validator(mode="after")
    def _one_speed(self) -> ShipConfig:
        if (self.speed_kn is None) == (self.speed_m_s is None):
            raise ValueError("give exactly one of speed_kn and speed_m_s")
        if 0.0 < self.speed < MIN_WAVE_SPEED_M_S:
            given = (f"speed_kn = {self.speed_kn:g}" if self.speed_kn is not None
                     else f"speed_m_s = {self.speed_m_s:g}")
            raise ValueError(
                f"{given}: slower than the slowest water wave, {MIN_WAVE_SPEED_M_S} m/s "
                "(capillary-gravity minimum, Lamb 1932 art. 268): the ship makes no steady "
                "wave wake; give 0 for a ship at rest")
        if self.beam_m >= self.length_m:
            raise ValueError(
                f"beam_m = {self.beam_m} must be smaller than length_m = {self.length_m}"
            )
        if self.beam_m < MIN_BEAM_RATIO * self.length_m:
            raise ValueError(
                f"beam_m = {self.beam_m:g}: below {MIN_BEAM_RATIO} x length_m = "
                f"{MIN_BEAM_RATIO * self.length_m:g} m; no hull is that slender (racing "
                "shells, the slenderest, have B / L of about 0.03)")
        return self

    @property
    def metacentric_height(self) -> float:
        """GM [m]: metacentric_height_m, default 0.05 beam_m."""
        if self.metacentric_height_m is not None:
            return float(self.metacentric_height_m)
        return DEFAULT_GM_OVER_BEAM * float(self.beam_m)

    @property
    def speed(self) -> float:
        """Speed [m/s]."""
        return self.speed_m_s if self.speed_m_s is not None else self.speed_kn * KNOT


__all__ = ["DEFAULT_GM_OVER_BEAM", "MAX_TURN_RATE_DEG_S", "MIN_BEAM_RATIO", "MIN_LENGTH_M",
           "MIN_WAVE_SPEED_M_S", "ShipConfig"]
