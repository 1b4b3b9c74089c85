"""``[sea]`` section: sea state, wave spectrum, tile and grid, sea water.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from .base import Section

SpectrumName = Literal["pierson-moskowitz", "jonswap", "elfouhaily", "romeiser",
                       "kudryavtsev"]
SpreadingName = Literal["longuet-higgins", "elfouhaily", "romeiser"]

#: Lowest wind [m/s]: the lower limit of Beaufort force 1 ("light air, ripples with the
#: appearance of scales"); below it, force 0, the sea is "like a mirror" (the Beaufort
#: wind force scale as the World Meteorological Organization tabulates it). The spectra
#: have no meaning there (k_p = g Omega^2 / U^2 diverges as U -> 0).
MIN_WIND_M_S = 0.3
#: Smallest tile [m]: a water wave of wavelength lambda decays at the viscous rate
#: 2 nu k^2 (Lamb 1932, art. 348), 1 / s at 1 cm but 80 / s at 1 mm: a tile under 1 cm holds
#: no lasting wave (5e-324 m divided by zero, 1e-300 m gave a NaN surface).
MIN_TILE_M = 0.01


class SeaConfig(Section):
    """The wind-driven sea: spectrum, tile, grid and water properties."""

    spectrum: SpectrumName = Field(
        "kudryavtsev",
        description="omnidirectional wave spectrum (paper eqs 4-5): 'pierson-moskowitz', "
        "'jonswap' (fetch-limited), 'elfouhaily' (unified, with capillary waves), "
        "'romeiser' (Romeiser, Alpers & Wismann 1997: short waves fitted to L- to Ka-band "
        "scatterometer data) or 'kudryavtsev' (Kudryavtsev et al. 2003: short waves from "
        "the energy balance of wind input, dissipation and parasitic capillaries, "
        "Elfouhaily's long waves; docs/ocean.md). Default 'kudryavtsev': at X band (sea "
        "states 2-5, 5-30 deg grazing) its HH and VV stay within 3.4 dB and its VV/HH within "
        "2.9 dB of Nathanson's table and the GIT and NRL models, where 'elfouhaily' puts VV "
        "2.7-6.4 dB and VV/HH 2.8-7.2 dB above them (docs/scattering.md, \"Choice of the "
        "default\")",
    )
    spreading: SpreadingName = Field(
        "longuet-higgins",
        description="directional spreading function: 'longuet-higgins' cos^2s(psi/2) "
        "(paper eq 6), 'elfouhaily' (Elfouhaily et al. 1997) or 'romeiser' (Romeiser et "
        "al. 1997, Gaussian about the wind)",
    )
    spreading_s: float = Field(
        1.0,
        gt=0.0,
        le=100.0,
        description="Longuet-Higgins spreading exponent s [-] (paper eq 6 uses s = 1)",
    )
    wind_speed_m_s: float = Field(
        ...,
        ge=MIN_WIND_M_S,
        le=40.0,
        description="wind speed U19.5 at 19.5 m above the sea [m/s] (paper eq 5); from "
        "0.3 m/s, Beaufort force 1 (below, the sea is calm and no wind-sea spectrum applies)",
    )
    wind_direction_deg: float = Field(
        0.0,
        ge=-360.0,
        le=360.0,
        description="direction the wind blows towards, counter-clockwise from +x (east) [deg]",
    )
    fetch_m: float | None = Field(
        None,
        gt=0.0,
        le=1.0e8,
        description="fetch [m]; required by 'jonswap'; omit for a fully developed sea "
        "with 'elfouhaily' or 'kudryavtsev' (Elfouhaily's long waves)",
    )
    depth_m: float | None = Field(
        None,
        gt=0.0,
        le=1.0e5,
        description="water depth for the dispersion relation (paper eq 15) [m]; omit for "
        "deep water",
    )
    size_x_m: float = Field(
        ..., ge=MIN_TILE_M, le=1.0e5,
        description="tile extent along x (east) [m]; from 1 cm (shorter water waves are "
        "damped by viscosity within a fraction of a second)",
    )
    size_y_m: float | None = Field(
        None, ge=MIN_TILE_M, le=1.0e5,
        description="tile extent along y (north) [m]; default size_x_m",
    )
    nx: int = Field(..., ge=4, le=16384, description="grid points along x [-] (even)")
    ny: int | None = Field(None, ge=4, le=16384, description="grid points along y [-]; default nx")
    temperature_c: float = Field(
        20.0, ge=-2.0, le=40.0, description="sea surface temperature [degC]"
    )
    salinity_psu: float = Field(35.0, ge=0.0, le=45.0, description="salinity [psu]")
    current_m_s: tuple[float, float] = Field(
        (0.0, 0.0),
        description="uniform surface current [U_x, U_y] in the scene frame (x east, y "
        "north) [m/s], each component from -5 to 5 m/s (the strongest tidal streams); it "
        "carries the waves (omega_0(K) + K.U, docs/dynamics.md) and the scatterers "
        "(Doppler q.U); [0, 0]: still water",
    )
    wind_drift: Literal["auto", "none", "3pct", "wu"] = Field(
        "auto",
        description="surface drift added to current_m_s, along the wind: '3pct' (the "
        "total surface drift, wind-induced current plus Stokes drift, 3 % of U10: AMS "
        "Glossary of Meteorology; Wu 1975), 'wu' (0.53 u* with u* of Wu's 1982 drag law: "
        "the wind-induced part only, about 2.0 % of U10 at 10 m/s; the coefficient is "
        "unsourced), 'none', or 'auto' (the default: '3pct' where the sea evolves between "
        "pulses, [scattering] sea_motion resolving to 'evolving', and the scene allows a "
        "current; 'none' otherwise: a held sea has no Doppler to carry it)",
    )
    coverage: Literal["tile", "radar"] = Field(
        "tile",
        description="where the sea is: 'tile' (one tile of size_x_m x size_y_m around "
        "the origin) or 'radar' (everywhere the range window of a fixed monostatic radar "
        "reaches: a patchwork of tiles whose facets grow with range, each its own "
        "realisation, evaluated only where the beam reaches at each pulse; size_x_m / nx "
        "is the finest facet; docs/scanning.md)",
    )

    @model_validator(mode="after")
    def _check(self) -> SeaConfig:
        for name in ("nx", "ny"):
            n = getattr(self, name)
            if n is not None and n % 2:
                raise ValueError(f"{name} = {n}: must be even (FFT grid with a Nyquist bin)")
        for i, u in enumerate(self.current_m_s):
            if not -5.0 <= u <= 5.0:
                raise ValueError(f"current_m_s[{i}] = {u:g} m/s: allowed -5 .. 5 m/s")
        if self.coverage == "radar" and (any(self.current_m_s)
                                         or self.wind_drift not in ("none", "auto")):
            raise ValueError(f"current_m_s = {list(self.current_m_s)}, wind_drift = "
                             f"{self.wind_drift!r} with coverage = 'radar': not implemented "
                             "yet (a current needs [0, 0] and 'none' or 'auto' there)")
        if self.spectrum == "jonswap" and self.fetch_m is None:
            raise ValueError("fetch_m is required when spectrum = 'jonswap' (fetch-limited sea)")
        return self

    @property
    def shape(self) -> tuple[int, int]:
        """Grid nodes (ny, nx) in array order, the shape of every gridded field."""
        return self.ny if self.ny is not None else self.nx, self.nx

    @property
    def size_m(self) -> tuple[float, float]:
        """(Lx, Ly) tile extents [m]."""
        return self.size_x_m, self.size_y_m if self.size_y_m is not None else self.size_x_m


__all__ = ["MIN_TILE_M", "MIN_WIND_M_S", "SeaConfig", "SpectrumName", "SpreadingName"]
