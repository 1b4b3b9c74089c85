"""``[ship]`` section: the ship that makes the wake (and, later, the hull echo).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from ..constants import KNOT
from .base import Section

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


class ShipConfig(Section):
    """A ship sailing in a straight line at constant speed."""

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
    def speed(self) -> float:
        """Speed [m/s]."""
        return self.speed_m_s if self.speed_m_s is not None else self.speed_kn * KNOT


__all__ = ["MIN_BEAM_RATIO", "MIN_LENGTH_M", "MIN_WAVE_SPEED_M_S", "ShipConfig"]
