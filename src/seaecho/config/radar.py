"""Radar sections of a scene file: platforms, antennas, waveform, receiver, targets.

Sections (TOML tables):

- ``[radar]``                 carrier, sampling, PRF, pulses, power, noise, channels, sea
  clutter on/off; ``[radar.waveform]`` the transmitted pulse.
- ``[transmitter]``           the transmitting platform (trajectory, attitude, optional
  Gauss-Markov perturbation ``[transmitter.perturbation]``) and its antenna
  ``[transmitter.antenna]``.
- ``[receiver]``              the same for the receiver; omit it for a monostatic radar
  (the receiver is then the transmitter's platform and antenna).
- ``[[targets]]``             point targets: position, velocity, RCS or a 2x2 scattering
  matrix.

Conventions (docs/conventions.md): SI inside, degrees and dB only in names ending
``_deg``/``_db``; world frame x east, y north, z up. A platform's body frame is x forward,
y left, z up; its attitude (yaw, pitch, roll) turns the body frame into the world frame
as R = Rz(yaw) Ry(-pitch) Rx(roll): yaw counter-clockwise from +x (east), pitch positive
nose up, roll positive right wing down.

Polarisation ports. An antenna has two orthogonal ports, named by its ``basis``:
``hv`` (ports H and V), ``slant`` (ports P = +45 deg and M = -45 deg) or ``circular``
(ports R and L, IEEE handedness). A channel ``"mn"`` is receive port m, transmit port n
(S_mn: m received, n transmitted), e.g. ``"HV"`` receives H and transmits V.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, field_validator, model_validator

from ..conventions import PORTS
from .base import Name, Section, short_repr

Vec3 = tuple[float, float, float]


PatternName = Literal["rectangular", "isotropic", "dipole", "hw_dipole", "tr38901"]
BasisName = Literal["hv", "slant", "circular"]
WeightingName = Literal["none", "hamming", "taylor"]

_POS = 1.0e8  # bound on coordinates [m]: beyond geostationary orbit
_VEL = 1.0e4  # bound on speeds [m/s]: beyond orbital speed
#: Longest run, (n_pulses - 1) / prf_hz [s] (116 days, as the range of start_time_s).
MAX_RUN_S = 1.0e7


class GaussMarkovConfig(Section):
    """First-order Gauss-Markov perturbation of a platform's path and attitude.

    Each axis x of the perturbation obeys dx/dt = -x / tau + w(t), with w white, so that x
    is stationary with standard deviation sigma and autocorrelation
    sigma^2 exp(-|dt| / tau) (Gelb, *Applied Optimal Estimation*, 1974, section 3.8).
    The draws come from the scene's seed (``[run].seed``), one stream per platform.
    """

    position_sigma_m: Vec3 = Field(
        (0.0, 0.0, 0.0),
        description="stationary standard deviation of the path error along world x, y, z [m]",
    )
    position_tau_s: float = Field(
        10.0, gt=0.0, le=1.0e6, description="correlation time of the path error [s]"
    )
    attitude_sigma_deg: Vec3 = Field(
        (0.0, 0.0, 0.0),
        description="stationary standard deviation of the (yaw, pitch, roll) error [deg]",
    )
    attitude_tau_s: float = Field(
        1.0, gt=0.0, le=1.0e6, description="correlation time of the attitude error [s]"
    )
    step_s: float = Field(
        1.0e-3, gt=0.0, le=10.0,
        description="time step on which the process is drawn (then interpolated) [s]",
    )

    @model_validator(mode="after")
    def _check(self) -> GaussMarkovConfig:
        for name in ("position_sigma_m", "attitude_sigma_deg"):
            values = getattr(self, name)
            if any(not (0.0 <= v <= 1.0e4) for v in values):
                raise ValueError(f"{name} = {list(values)}: each must be in [0, 1e4]")
        return self


#: Narrowest sector scan [deg] (a narrower one overflows the sweep count).
MIN_SECTOR_DEG = 0.01


class ScanConfig(Section):
    """How an antenna scans about its platform's vertical (body z) axis.

    Azimuths are in the scene's convention: counter-clockwise from the platform's body x
    axis (forward), as ``azimuth_deg``; a coastal site with ``yaw_deg = 90`` has body x
    pointing north. The antenna turns clockwise seen from above, as marine radars do
    (its azimuth decreases; its bearing clockwise from north increases); the platform's
    attitude (roll, pitch, yaw) turns the pedestal with it. ``depression_deg`` of the
    antenna tilts the beam.
    """

    mode: Literal["fixed", "rotating", "sector"] = Field(
        "fixed",
        description="'fixed' (no scan), 'rotating' (continuous clockwise rotation) or "
        "'sector' (clockwise from sector_deg[0] to sector_deg[1], then back)",
    )
    rate_rpm: float | None = Field(
        None, gt=0.0, le=600.0,
        description="rotation rate, revolutions per minute [rpm] (rotating, sector)",
    )
    start_deg: float | None = Field(
        None, ge=-360.0, le=360.0,
        description="boresight azimuth at t = 0, counter-clockwise from body x [deg] "
        "(rotating; default 0)",
    )
    sector_deg: tuple[float, float] | None = Field(
        None,
        description="sector (from, to), counter-clockwise from body x, each within +-360 "
        "[deg]: swept clockwise from 'from' to 'to' and back, starting at 'from' at t = 0 "
        "(sector)",
    )

    @model_validator(mode="after")
    def _check(self) -> ScanConfig:
        if self.mode == "fixed":
            if any(v is not None for v in (self.rate_rpm, self.start_deg, self.sector_deg)):
                raise ValueError("mode 'fixed' takes no rate_rpm, start_deg or sector_deg")
            return self
        if self.rate_rpm is None:
            raise ValueError(f"mode '{self.mode}' needs rate_rpm")
        if not 2.0 * math.pi * self.rate_rpm / 60.0 > 0.0:  # the run's rad/s (build.py)
            raise ValueError(f"rate_rpm = {self.rate_rpm!r}: 0 rad/s once converted (too "
                             "small for float64); allowed 0 < rate_rpm <= 600 rpm")
        if self.mode == "rotating" and self.sector_deg is not None:
            raise ValueError("sector_deg is only used with mode 'sector'")
        if self.mode == "sector":
            if self.sector_deg is None:
                raise ValueError("mode 'sector' needs sector_deg = [from, to]")
            if self.start_deg is not None:
                raise ValueError("mode 'sector' starts at sector_deg[0]; omit start_deg")
            if any(not abs(v) <= 360.0 for v in self.sector_deg):
                raise ValueError(f"sector_deg = {list(self.sector_deg)}: each must be "
                                 "within +-360 deg")
            width = (self.sector_deg[0] - self.sector_deg[1]) % 360.0
            if width == 0.0:
                raise ValueError(f"sector_deg = {list(self.sector_deg)}: an empty sector; "
                                 "use mode 'rotating' for a full turn")
            if width < MIN_SECTOR_DEG:
                raise ValueError(f"sector_deg = {list(self.sector_deg)}: a sector of "
                                 f"{width:.3g} deg; it must be at least {MIN_SECTOR_DEG} deg "
                                 "wide")
        return self

    @property
    def scanning(self) -> bool:
        """Whether the antenna scans."""
        return self.mode != "fixed"


class AntennaConfig(Section):
    """An antenna: pattern, size, polarisation ports, pointing, scan."""

    pattern: PatternName = Field(
        "rectangular",
        description="'rectangular' (uniformly illuminated aperture width x height, the "
        "paper's section V), 'isotropic', or Sionna RT's 'dipole', 'hw_dipole', 'tr38901'",
    )
    width_m: float | None = Field(
        None, gt=0.0, le=100.0,
        description="aperture width, along the antenna's horizontal axis [m] (rectangular)",
    )
    height_m: float | None = Field(
        None, gt=0.0, le=100.0,
        description="aperture height, along the antenna's vertical axis [m] (rectangular)",
    )
    basis: BasisName = Field(
        "hv",
        description="polarisation ports: 'hv' (H, V), 'slant' (P = +45 deg, M = -45 deg) "
        "or 'circular' (R, L)",
    )
    cross_polar_isolation_db: float | None = Field(
        None, ge=0.0, le=200.0,
        description="cross-polar isolation of each port [dB]; omit for ideal ports",
    )
    look_at_m: Vec3 | None = Field(
        None, description="point the boresight at this world point (x, y, z), each within "
        "+-1e8 [m]"
    )
    track_look_at: bool = Field(
        False,
        description="keep the boresight on look_at_m at every pulse (spotlight); default: "
        "aim at the first pulse ([radar] start_time_s) and stay fixed to the platform "
        "(stripmap)",
    )
    azimuth_deg: float | None = Field(
        None, ge=-360.0, le=360.0,
        description="boresight azimuth in the platform body frame, counter-clockwise from "
        "body x (forward) [deg]; with depression_deg, instead of look_at_m",
    )
    depression_deg: float | None = Field(
        None, ge=-90.0, le=90.0,
        description="boresight depression below the body horizontal plane [deg]",
    )
    illumination: Literal["uniform", "cosine", "taylor"] = Field(
        "uniform",
        description="aperture illumination along the width (rectangular): 'uniform' "
        "(first sidelobe -13.3 dB), 'cosine' (-23 dB) or 'taylor' (taylor_sidelobe_db); "
        "the height stays uniform",
    )
    taylor_sidelobe_db: float = Field(
        30.0, ge=13.3, le=60.0,
        description="Taylor illumination's design peak sidelobe level below the peak [dB]",
    )
    taylor_nbar: int = Field(
        4, ge=2, le=20, description="Taylor illumination's nbar (near sidelobes held) [-]"
    )
    scan: ScanConfig = Field(
        default_factory=ScanConfig,
        description="scanning [<platform>.antenna.scan]; default fixed",
    )

    @model_validator(mode="after")
    def _check(self) -> AntennaConfig:
        if self.pattern == "rectangular" and (self.width_m is None or self.height_m is None):
            raise ValueError("pattern 'rectangular' needs width_m and height_m")
        if self.illumination != "uniform" and self.pattern != "rectangular":
            raise ValueError(f"illumination '{self.illumination}' needs pattern "
                             "'rectangular'")
        if self.scan.scanning:
            # the conflicting pointing first: it names the field the user gave
            if (self.azimuth_deg is not None or self.look_at_m is not None
                    or self.track_look_at):
                raise ValueError("a scanning antenna is pointed by its scan and "
                                 "depression_deg: omit azimuth_deg, look_at_m and "
                                 "track_look_at")
            if self.depression_deg is None:
                raise ValueError("a scanning antenna needs depression_deg")
            return self
        by_angles = self.azimuth_deg is not None or self.depression_deg is not None
        if by_angles and (self.azimuth_deg is None or self.depression_deg is None):
            raise ValueError("give both azimuth_deg and depression_deg")
        if by_angles == (self.look_at_m is not None):
            raise ValueError("point the antenna by look_at_m or by azimuth_deg/depression_deg "
                             "(exactly one)")
        if self.track_look_at and self.look_at_m is None:
            raise ValueError("track_look_at needs look_at_m")
        if self.look_at_m is not None and not all(abs(c) <= _POS for c in self.look_at_m):
            raise ValueError(f"look_at_m = {list(self.look_at_m)}: each component must be "
                             f"within +-{_POS:g} m")
        return self

    @property
    def ports(self) -> tuple[str, str]:
        """The two port letters of this antenna's basis."""
        return PORTS[self.basis]


class PlatformConfig(Section):
    """A platform carrying an antenna: trajectory, attitude, perturbation."""

    motion: Literal["fixed", "linear", "waypoints"] = Field(
        "fixed",
        description="'fixed' (position_m), 'linear' (position_m at t = 0 + velocity_m_s t) "
        "or 'waypoints' (piecewise-linear through waypoint_positions_m)",
    )
    position_m: Vec3 | None = Field(
        None, description="position (x, y, z) at t = 0 [m] (fixed, linear)"
    )
    velocity_m_s: Vec3 = Field((0.0, 0.0, 0.0), description="velocity (linear) [m/s]")
    waypoint_times_s: tuple[float, ...] | None = Field(
        None, min_length=2, max_length=100_000,
        description="times of the waypoints, increasing [s] (waypoints)",
    )
    waypoint_positions_m: tuple[Vec3, ...] | None = Field(
        None, min_length=2, max_length=100_000,
        description="waypoint positions (x, y, z) [m], one per waypoint time",
    )
    yaw_deg: float | None = Field(
        None, ge=-360.0, le=360.0,
        description="heading of the body x axis, counter-clockwise from east [deg]; "
        "default: along the horizontal velocity (0 if at rest)",
    )
    pitch_deg: float = Field(0.0, ge=-90.0, le=90.0, description="pitch, nose up [deg]")
    roll_deg: float = Field(
        0.0, ge=-180.0, le=180.0, description="roll, right wing down [deg]"
    )
    perturbation: GaussMarkovConfig | None = Field(
        None, description="random path and attitude errors [<platform>.perturbation]"
    )
    antenna: AntennaConfig = Field(..., description="the antenna [<platform>.antenna]")

    @model_validator(mode="after")
    def _check(self) -> PlatformConfig:
        for name in ("position_m", "velocity_m_s"):
            v = getattr(self, name)
            bound = _POS if name == "position_m" else _VEL
            if v is not None and any(abs(c) > bound for c in v):
                raise ValueError(f"{name} = {list(v)}: each component must be within "
                                 f"+-{bound:g}")
        if self.motion in ("fixed", "linear"):
            if self.position_m is None:
                raise ValueError(f"motion '{self.motion}' needs position_m")
            if self.waypoint_times_s is not None or self.waypoint_positions_m is not None:
                raise ValueError("waypoints are only used with motion 'waypoints'")
            if self.motion == "fixed" and any(self.velocity_m_s):
                raise ValueError("motion 'fixed' cannot have a velocity; use 'linear'")
        else:
            t, p = self.waypoint_times_s, self.waypoint_positions_m
            if t is None or p is None:
                raise ValueError("motion 'waypoints' needs waypoint_times_s and "
                                 "waypoint_positions_m")
            if len(t) != len(p):
                raise ValueError(f"{len(t)} waypoint times but {len(p)} positions")
            if any(b <= a for a, b in zip(t, t[1:], strict=False)):
                raise ValueError(f"waypoint_times_s = {short_repr(t)}: must increase "
                                 "strictly")
            for i in range(len(t) - 1):
                v = [(b - a) / (t[i + 1] - t[i]) for a, b in zip(p[i], p[i + 1], strict=True)]
                if any(not abs(c) <= _VEL for c in v):
                    raise ValueError(
                        f"waypoints {i} and {i + 1} (t = {t[i]:g} and {t[i + 1]:g} s): "
                        f"velocity {short_repr(v)} m/s; each component must be within "
                        f"+-{_VEL:g} (as velocity_m_s)")
            if self.position_m is not None or any(self.velocity_m_s):
                raise ValueError("motion 'waypoints' takes no position_m/velocity_m_s")
        return self


class WaveformConfig(Section):
    """The transmitted pulse (complex baseband envelope)."""

    kind: Literal["lfm", "pulse"] = Field(
        "lfm", description="'lfm' (linear FM chirp) or 'pulse' (plain rectangular pulse)"
    )
    bandwidth_hz: float | None = Field(
        None, gt=0.0, le=1.0e10, description="chirp bandwidth B [Hz] (lfm)"
    )
    duration_s: float = Field(..., gt=0.0, le=1.0e-2, description="pulse duration T [s]")
    up_chirp: bool = Field(True, description="frequency increases over the pulse (lfm)")

    @model_validator(mode="after")
    def _check(self) -> WaveformConfig:
        if self.kind == "lfm" and self.bandwidth_hz is None:
            raise ValueError("kind 'lfm' needs bandwidth_hz")
        if self.kind == "pulse" and self.bandwidth_hz is not None:
            raise ValueError("kind 'pulse' has bandwidth 1/duration_s; omit bandwidth_hz")
        if self.kind == "lfm" and self.bandwidth_hz * self.duration_s < 1.0:
            raise ValueError(
                f"bandwidth_hz x duration_s = {self.bandwidth_hz * self.duration_s:.3g}: a "
                "linear FM pulse sweeps its bandwidth only if B T >= 1 (below, its spectrum "
                "is that of a plain pulse of width 1/T; Richards 2014, section 4.6); use "
                "kind = 'pulse' or a longer pulse")
        return self


class RadarConfig(Section):
    """Carrier, sampling, pulses, power, receiver noise, channels, what to simulate."""

    carrier_frequency_hz: float = Field(
        ..., gt=1.0e6, le=1.0e12, description="carrier frequency f_c [Hz]"
    )
    sampling_rate_hz: float = Field(
        ..., gt=0.0, le=1.0e11, description="complex baseband sampling rate f_s [Hz]"
    )
    prf_hz: float = Field(..., gt=0.0, le=1.0e7, description="pulse repetition frequency [Hz]")
    n_pulses: int = Field(1, ge=1, le=10_000_000, description="number of pulses [-]")
    start_time_s: float = Field(
        0.0, ge=-1.0e7, le=1.0e7, description="emission time of pulse 0 [s]"
    )
    transmit_power_w: float = Field(
        1.0, gt=0.0, le=1.0e9, description="peak transmit power P_t [W]"
    )
    waveform: WaveformConfig = Field(..., description="the pulse [radar.waveform]")
    window_start_m: float | None = Field(
        None, ge=0.0, le=1.0e9,
        description="start of the receive window as range c*tau/2 (half the bistatic path "
        "length) [m]; omit (with window_end_m) to cover the tile and targets",
    )
    window_end_m: float | None = Field(
        None, gt=0.0, le=1.0e9, description="end of the receive window as range c*tau/2 [m]"
    )
    channels: tuple[str, ...] = Field(
        ("HH", "HV", "VH", "VV"), min_length=1, max_length=4,
        description="channels 'mn' (receive port m, transmit port n), e.g. HH, HV, VH, VV",
    )
    sea_clutter: bool = Field(True, description="simulate the sea's echo (off: targets only)")
    sea_update_pulses: int = Field(
        1, ge=1, le=10_000_000, description="recompute the sea surface every N pulses [-]"
    )
    sea_gain_floor_db: float | Literal["off"] = Field(
        -60.0,
        description="skip the sea's echo at a pulse where the two-way antenna gain, "
        "bounded over the whole tile, stays below this level relative to the beams' "
        "peaks [dB]: the skipped clutter power is at most this gain times the tile's "
        "clutter power at the peak (docs/scanning.md), in [-300, 0]; 'off' computes it "
        "at every pulse; the same floor skips a hull's echo ([[ships]] hull_echo, "
        "[[objects]] scatterer) at a pulse where the bound over the box of its "
        "scattering centres stays below it",
    )

    @field_validator("sea_gain_floor_db")
    @classmethod
    def _floor_in_range(cls, v: float | str) -> float | str:
        if v != "off" and not -300.0 <= v <= 0.0:
            raise ValueError(f"{v}: allowed a level in [-300, 0] dB or 'off'")
        return v
    accumulation_precision: Literal["double", "single"] = Field(
        "double",
        description="floating point of the echo accumulation's non-uniform FFT (eq E2): "
        "'double' (error ~5e-10 of each channel's echo) or 'single' (~1e-5, i.e. -98 dB, "
        "about half the CPU time; CPU only, a GPU run keeps double; docs/performance.md)",
    )
    thermal_noise: bool = Field(False, description="add receiver thermal noise k T0 F B")
    noise_figure_db: float = Field(3.0, ge=0.0, le=50.0, description="noise figure F [dB]")
    noise_bandwidth_hz: float | None = Field(
        None, gt=0.0, le=1.0e11,
        description="receiver noise bandwidth B_n [Hz]; default the sampling rate",
    )
    range_weighting: WeightingName = Field(
        "none", description="matched-filter weighting: 'none', 'hamming' or 'taylor'"
    )
    taylor_nbar: int = Field(5, ge=1, le=100, description="Taylor window nbar [-]")
    taylor_sidelobe_db: float = Field(
        35.0, gt=0.0, le=150.0, description="Taylor window peak sidelobe level below peak [dB]"
    )
    sigma_map_pulse: int = Field(
        0, ge=0, le=10_000_000, description="pulse whose per-facet sigma maps are saved [-]"
    )
    transmit_phase: Literal["coherent", "random"] = Field(
        "coherent",
        description="'coherent' (every pulse transmitted with phase 0) or 'random' (a "
        "magnetron: a new uniform phase per pulse, seeded; echoes do not add coherently "
        "from pulse to pulse)",
    )
    cpi_pulses: int | None = Field(
        None, ge=1, le=10_000_000,
        description="pulses per dwell (coherent processing interval): Swerling 1 and 3 "
        "targets draw a new RCS every dwell [-]; default all the pulses of the run",
    )

    @model_validator(mode="after")
    def _check(self) -> RadarConfig:
        if (self.window_start_m is None) != (self.window_end_m is None):
            raise ValueError("give both window_start_m and window_end_m, or neither")
        if self.window_start_m is not None and self.window_end_m <= self.window_start_m:
            raise ValueError(f"window_end_m = {self.window_end_m} must exceed "
                             f"window_start_m = {self.window_start_m}")
        if len(set(self.channels)) != len(self.channels):
            raise ValueError(f"channels = {list(self.channels)}: repeated channel")
        w = self.waveform
        bandwidth = w.bandwidth_hz if w.kind == "lfm" else 1.0 / w.duration_s
        if bandwidth > self.sampling_rate_hz:
            raise ValueError(f"waveform bandwidth {bandwidth:g} Hz exceeds sampling_rate_hz "
                             f"= {self.sampling_rate_hz:g} (complex sampling needs f_s >= B)")
        if w.duration_s >= 1.0 / self.prf_hz:
            raise ValueError(f"pulse duration {w.duration_s:g} s is not shorter than the "
                             f"pulse repetition interval {1.0 / self.prf_hz:g} s")
        span = (self.n_pulses - 1) / self.prf_hz
        if not span <= MAX_RUN_S:
            raise ValueError(f"n_pulses = {self.n_pulses} at prf_hz = {self.prf_hz:g}: the run "
                             f"would last {span:.3g} s; at most {MAX_RUN_S:g} s (as "
                             "start_time_s's range)")
        if self.sigma_map_pulse >= self.n_pulses:
            raise ValueError(f"sigma_map_pulse = {self.sigma_map_pulse} must be below "
                             f"n_pulses = {self.n_pulses}")
        return self

    @property
    def wavelength_m(self) -> float:
        """Carrier wavelength lambda = c0 / f_c [m]."""
        from ..constants import C0

        return C0 / self.carrier_frequency_hz


#: Mean RCS [m^2] of the named targets of the IMO radar performance standard, at X band
#: (9.2-9.5 GHz in the standard, 8-12 GHz here) and S band (2.9-3.1 GHz, 2-4 GHz here),
#: the Swerling case a preset takes unless given, and the target's height above the sea
#: [m] in the standard's table. Source: IMO resolution MSC.192(79) (adopted 6 December
#: 2004), Annex, section 5.3.1.1, table 2 "Minimum detection ranges in clutter-free
#: conditions" (antenna 15 m above the sea; detection in 8 of 10 scans at a false-alarm
#: probability of 1e-4), whose rows are, target (note): height [m], X / S band range
#: [NM]: small vessel with a radar reflector meeting the IMO performance standards (1):
#: 4.0, 5.0 / 3.7; navigation buoy with corner reflector (2): 3.5, 4.9 / 3.6; typical
#: navigation buoy (3): 3.5, 4.6 / 3.0; small vessel of length 10 m with no radar
#: reflector (4): 2.0, 3.4 / 3.0 (checked against the published text, MSC 79/23/Add.2,
#: annex 34, page 6). The RCS of note 1 is the reflector's "stated performance level" of
#: resolution MSC.164(78), annex, para 3.1: at least 7.5 m^2 (X) and 0.5 m^2 (S) mounted
#: at least 4 m above the water (checked). The RCS of notes 2-4 (10 / 1.0, 5.0 / 0.5 and
#: 2.5 / 1.4 m^2, the 10 m boat "taken as a complex target") are the notes' values as
#: an earlier revision quoted them; the copies of the resolution searched here did not
#: reproduce the notes' text, so they are not checked against it (docs/targets.md).
#: Swerling cases: a modelling choice (docs/targets.md): the many-scatterer boat case 1,
#: a buoy (one dominant reflector plus small ones) case 3. There is no swimmer: no
#: published RCS of a person in the water was found (a standing man: 0.5 to 1.2 m^2 at
#: 9.4 GHz, Schultz, Burgener & King, Proc. IRE 46(2), 476-481, 1958, is not a
#: swimmer's).
TARGET_PRESETS: dict[str, dict] = {
    "small-boat": {"x_band_m2": 2.5, "s_band_m2": 1.4, "swerling": 1, "height_m": 2.0},
    "small-boat-reflector": {"x_band_m2": 7.5, "s_band_m2": 0.5, "swerling": 1,
                             "height_m": 4.0},
    "navigation-buoy": {"x_band_m2": 5.0, "s_band_m2": 0.5, "swerling": 3, "height_m": 3.5},
    "navigation-buoy-reflector": {"x_band_m2": 10.0, "s_band_m2": 1.0, "swerling": 3,
                                  "height_m": 3.5},
}
#: Carrier bands of the presets [Hz] (IEEE Std 521-2002 letter bands).
PRESET_BANDS: dict[str, tuple[float, float]] = {"x_band_m2": (8.0e9, 12.0e9),
                                                "s_band_m2": (2.0e9, 4.0e9)}
PresetName = Literal["small-boat", "small-boat-reflector", "navigation-buoy",
                     "navigation-buoy-reflector"]


def preset_rcs_m2(preset: str, carrier_hz: float) -> float:
    """Mean RCS [m^2] of a :data:`TARGET_PRESETS` entry at a carrier [Hz] (X or S band).

    Raises
    ------
    ValueError
        The carrier is in neither band.
    """
    for key, (lo, hi) in PRESET_BANDS.items():
        if lo <= carrier_hz <= hi:
            return float(TARGET_PRESETS[preset][key])
    raise ValueError(f"preset = '{preset}': its RCS is published for X band (8-12 GHz) "
                     f"and S band (2-4 GHz) only; the carrier is {carrier_hz / 1e9:g} GHz: "
                     "give rcs_m2 instead")


class TargetConfig(Section):
    """A point target: position, velocity and its RCS or 2x2 scattering matrix.

    The scattering amplitudes s_mn are in metres, |s_mn|^2 = sigma_mn [m^2], in the
    forward-scattering-alignment bases of docs/conventions.md (m received, n transmitted),
    given as (real, imaginary) pairs. With ``swerling`` 1 to 4 they are the mean: the
    target presents sqrt(F) s_mn, F drawn per dwell or per pulse (docs/targets.md).
    """

    name: Name = Field("", max_length=200, description="a label for the target")
    position_m: Vec3 = Field(..., description="position (x, y, z) at t = 0 [m]")
    velocity_m_s: Vec3 = Field((0.0, 0.0, 0.0), description="constant velocity [m/s]")
    rcs_m2: float | None = Field(
        None, ge=0.0, le=1.0e9,
        description="RCS sigma [m^2] of a co-polar target (s_hh = s_vv = sqrt(sigma), "
        "s_hv = s_vh = 0); or give s_hh, s_hv, s_vh, s_vv",
    )
    s_hh: tuple[float, float] | None = Field(None, description="s_hh (re, im) [m]")
    s_hv: tuple[float, float] | None = Field(None, description="s_hv (re, im) [m]")
    s_vh: tuple[float, float] | None = Field(None, description="s_vh (re, im) [m]")
    s_vv: tuple[float, float] | None = Field(None, description="s_vv (re, im) [m]")
    swerling: Literal[0, 1, 2, 3, 4] | None = Field(
        None,
        description="fluctuation (Swerling 1954): 0 steady; 1, 3 a new RCS every dwell "
        "([radar] cpi_pulses), 2, 4 every pulse; 1, 2 exponential power (chi-square 2 "
        "degrees of freedom), 3, 4 chi-square 4; rcs_m2 (or |s_mn|^2) is the mean; "
        "default 0, or the preset's",
    )
    preset: PresetName | None = Field(
        None,
        description="a published mean RCS at the radar's X or S band carrier instead of "
        "rcs_m2 (IMO MSC.192(79) table 2): 'small-boat' (10 m, no reflector), "
        "'small-boat-reflector', 'navigation-buoy', 'navigation-buoy-reflector' "
        "(docs/targets.md)",
    )

    @model_validator(mode="after")
    def _check(self) -> TargetConfig:
        given = [getattr(self, n) is not None for n in ("s_hh", "s_hv", "s_vh", "s_vv")]
        if self.preset is not None and (self.rcs_m2 is not None or any(given)):
            raise ValueError(f"preset = '{self.preset}' sets the RCS: give no rcs_m2 or "
                             "s_hh, s_hv, s_vh, s_vv with it")
        if self.preset is None and (self.rcs_m2 is None) == (not any(given)):
            raise ValueError("give either rcs_m2, a preset, or the scattering matrix s_hh, "
                             "s_hv, s_vh, s_vv (missing ones are 0)")
        for name in ("position_m", "velocity_m_s"):
            v = getattr(self, name)
            bound = _POS if name == "position_m" else _VEL
            if any(abs(c) > bound for c in v):
                raise ValueError(f"{name} = {list(v)}: each component must be within "
                                 f"+-{bound:g}")
        for name in ("s_hh", "s_hv", "s_vh", "s_vv"):
            v = getattr(self, name)
            if v is not None and any(abs(c) > 1.0e5 for c in v):
                raise ValueError(f"{name} = {list(v)}: each part must be within +-1e5 m")
        return self

    @property
    def swerling_case(self) -> int:
        """The Swerling case: ``swerling``, else the preset's, else 0."""
        if self.swerling is not None:
            return int(self.swerling)
        return int(TARGET_PRESETS[self.preset]["swerling"]) if self.preset else 0

    def scattering_matrix(self, carrier_hz: float | None = None):
        """The 2x2 complex scattering amplitude [m] in (h, v) order: [[s_hh, s_hv], [s_vh, s_vv]].

        ``M[m, n]``: m received, n transmitted, both ordered (h, v) as in
        ``seaecho.geometry.frames``, so ``M.reshape(4)`` lists HH, HV, VH, VV. A preset
        needs the carrier [Hz] (:func:`preset_rcs_m2`).
        """
        import numpy as np

        if self.preset is not None:
            if carrier_hz is None:
                raise ValueError(f"preset = '{self.preset}': needs the radar's carrier")
            a = np.sqrt(preset_rcs_m2(self.preset, carrier_hz))
            return np.array([[a, 0.0], [0.0, a]], dtype=complex)
        if self.rcs_m2 is not None:
            a = np.sqrt(self.rcs_m2)
            return np.array([[a, 0.0], [0.0, a]], dtype=complex)

        def c(v):
            return 0.0 if v is None else complex(v[0], v[1])

        return np.array([[c(self.s_hh), c(self.s_hv)], [c(self.s_vh), c(self.s_vv)]])


__all__ = [
    "PORTS",
    "AntennaConfig",
    "GaussMarkovConfig",
    "PlatformConfig",
    "RadarConfig",
    "PRESET_BANDS",
    "TARGET_PRESETS",
    "TargetConfig",
    "WaveformConfig",
    "preset_rcs_m2",
]
