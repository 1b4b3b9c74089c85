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


class ShipConfig(Section):
    """A ship sailing in a straight line at constant speed."""

    length_m: float = Field(..., gt=0.0, le=500.0, description="waterline length L [m]")
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
    turbulent_wake_film_contrast_db: float = Field(
        -3.0, ge=-30.0, le=0.0,
        description="persistent Bragg contrast of the turbulent wake's surfactant film [dB], a "
        "free parameter (no measured value is built in); the turbulence adds complete "
        "damping at the stern decaying as (1 + xi/B)^-3/5",
    )

    @model_validator(mode="after")
    def _one_speed(self) -> ShipConfig:
        if (self.speed_kn is None) == (self.speed_m_s is None):
            raise ValueError("give exactly one of speed_kn and speed_m_s")
        if self.beam_m >= self.length_m:
            raise ValueError(
                f"beam_m = {self.beam_m} must be smaller than length_m = {self.length_m}"
            )
        return self

    @property
    def speed(self) -> float:
        """Speed [m/s]."""
        return self.speed_m_s if self.speed_m_s is not None else self.speed_kn * KNOT


__all__ = ["ShipConfig"]
