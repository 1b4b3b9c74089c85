"""``[image]`` section: SAR image formation (backprojection) after the raw data.

With an ``[image]`` section, ``seaecho run`` focuses the raw data it has just written into
``<output>_image.nc`` (and its figures); ``seaecho image RAW.nc`` reads the same section
from the file's scene and lets its command-line options override each field. The
processing (``seaecho.imaging``, ``docs/imaging.md``) is time-domain backprojection onto
a horizontal grid, calibrated in RCS and sigma0.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from .base import Section

WindowName = Literal["none", "hamming", "taylor"]


class ImageConfig(Section):
    """SAR focusing: grid, track, weighting, polarimetric products, speckle filter."""

    pixel_m: float | None = Field(
        None, gt=0.0, le=1.0e4,
        description="pixel size on the ground, both axes [m]; default a quarter of the "
        "slant-range resolution c / (2 B)",
    )
    extent_m: tuple[float, float, float, float] | None = Field(
        None,
        description="image area (x_min, x_max, y_min, y_max) in the scene frame [m]; default "
        "the sea tile (or the targets' bounding box plus 20 range resolutions without sea)",
    )
    height_m: float = Field(
        0.0, ge=-1.0e4, le=1.0e5, description="height of the image plane [m] (mean sea level 0)"
    )
    track: Literal["nominal", "true"] = Field(
        "nominal",
        description="platform track the processor uses: 'nominal' (its navigation solution, "
        "what a real processor knows) or 'true' (the perturbed track that made the echoes)",
    )
    azimuth_window: WindowName = Field(
        "none", description="weighting over the processed Doppler band: 'none', 'hamming', "
        "'taylor'"
    )
    range_weighting: WindowName | None = Field(
        None,
        description="matched-filter weighting; default: the range compression already in "
        "the file ([radar] range_weighting); otherwise the raw data are compressed again",
    )
    taylor_nbar: int = Field(5, ge=1, le=100, description="Taylor windows: nbar [-]")
    taylor_sidelobe_db: float = Field(
        35.0, gt=0.0, le=150.0, description="Taylor windows: peak sidelobe level below peak [dB]"
    )
    doppler_bandwidth_hz: float | None = Field(
        None, gt=0.0, le=1.0e9,
        description="processed Doppler bandwidth, centred on the beam's Doppler centroid at "
        "each pulse [Hz]; default the PRF (no azimuth ambiguity)",
    )
    upsample: int = Field(
        16, ge=1, le=256,
        description="range upsampling factor before linear interpolation [-] (16: at most "
        "0.03 dB interpolation loss)",
    )
    looks: tuple[int, int] = Field(
        (1, 1), description="multilook (azimuth y, range x) in pixels: intensities averaged "
        "over blocks, written on a coarser grid [-]"
    )
    speckle_filter: Literal["none", "boxcar", "refined-lee"] = Field(
        "none", description="speckle filter of the intensities: 'none', 'boxcar' or "
        "'refined-lee' (Lee et al. 1999)"
    )
    filter_size: int = Field(
        7, ge=3, le=101, description="speckle filter window (odd; refined Lee: 7) [pixels]"
    )
    dynamic_range_db: float = Field(
        50.0, gt=0.0, le=200.0, description="figures: dB range below the common maximum [dB]"
    )
    figures: bool = Field(True, description="write the PNG figures beside the image file")

    @model_validator(mode="after")
    def _check(self) -> ImageConfig:
        if self.extent_m is not None:
            x0, x1, y0, y1 = self.extent_m
            if not (x1 > x0 and y1 > y0):
                raise ValueError(f"extent_m = {list(self.extent_m)}: need x_min < x_max and "
                                 "y_min < y_max")
        if any(n < 1 or n > 1000 for n in self.looks):
            raise ValueError(f"looks = {list(self.looks)}: each must be in [1, 1000]")
        if self.filter_size % 2 == 0:
            raise ValueError(f"filter_size = {self.filter_size}: must be odd")
        if self.speckle_filter == "refined-lee" and self.filter_size < 5:
            raise ValueError(f"filter_size = {self.filter_size}: refined Lee needs >= 5")
        return self


__all__ = ["ImageConfig"]
