"""What the radar stage needs, as plain values: :class:`RadarModel` and :class:`TargetSet`.

:func:`seaecho.build.build_radar` fills these from a scene's ``[radar]``,
``[transmitter]``, ``[receiver]`` and ``[[targets]]`` sections (degrees, dB and knots
converted there); :class:`seaecho.radar.system.RadarSystem` works on them and never
sees the scene.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..geometry.earth import SphericalEarth
from .antennas import Antenna
from .platforms import Platform
from .pointing import Pointing
from .propagation import TwoRay
from .waveform import Waveform


@dataclass(frozen=True)
class TargetSet:
    """Point targets moving at constant velocity.

    Attributes
    ----------
    positions : ndarray (K, 3)
        Positions at t = 0 [m].
    velocities : ndarray (K, 3)
        Velocities [m/s].
    scattering : ndarray (K, 2, 2) complex
        Scattering amplitudes s_mn [m] in (h, v) order, m received, n transmitted,
        ``|s_mn|^2`` the RCS [m^2] (docs/conventions.md).
    names : tuple of str
        Labels.
    swerling : ndarray (K,) int or None
        Swerling case of each target, 0 to 4 (:mod:`seaecho.targets.swerling`); None:
        all steady. ``scattering`` holds the mean: |s_mn|^2 the mean RCS.
    dwell_pulses : int
        Pulses per dwell: cases 1 and 3 draw one RCS per dwell.
    seed : int
        The scene's seed (the fluctuations' stream).
    """

    positions: NDArray[np.float64]
    velocities: NDArray[np.float64]
    scattering: NDArray[np.complex128]
    names: tuple[str, ...]
    swerling: NDArray[np.int64] | None = None
    dwell_pulses: int = 1
    seed: int = 0

    def __len__(self) -> int:
        return int(self.positions.shape[0])

    def rcs_factor(self, pulse) -> NDArray[np.float64]:
        """RCS over mean RCS of every target at ``pulse`` [-], shape ``pulse``'s + (K,)
        (eq T1 of :mod:`seaecho.targets.swerling`; 1 for steady targets)."""
        p = np.asarray(pulse, dtype=np.int64)
        if self.swerling is None or not np.any(self.swerling):
            return np.ones(p.shape + (len(self),))
        from ..targets.swerling import swerling_factor

        return swerling_factor(self.seed, self.swerling, p[..., None], self.dwell_pulses)

    def scattering_at(self, pulse: int) -> NDArray[np.complex128]:
        """Scattering amplitudes presented at ``pulse`` [m], (K, 2, 2): ``scattering``
        times sqrt of :meth:`rcs_factor` (the phases kept)."""
        if self.swerling is None or not np.any(self.swerling):
            return self.scattering
        return self.scattering * np.sqrt(self.rcs_factor(int(pulse)))[:, None, None]


@dataclass(frozen=True)
class RadarModel:
    """Plain-valued description of a radar: carrier, pulses, platforms, antennas, receiver.

    Attributes
    ----------
    carrier : float
        Carrier frequency f_c [Hz].
    sampling_rate : float
        Complex baseband sampling rate f_s [Hz].
    prf : float
        Pulse repetition frequency [Hz].
    n_pulses : int
        Number of pulses.
    start_time : float
        Emission time of pulse 0 [s].
    transmit_power : float
        Peak transmit power P_t [W].
    waveform : Waveform
        The transmitted pulse.
    tx, rx : Platform
        Transmitter and receiver platforms (the same object when monostatic).
    tx_antenna, rx_antenna : Antenna
        Antenna patterns and ports.
    tx_pointing, rx_pointing : Pointing
        How each antenna's axes follow its platform.
    channels : tuple of str
        Channels "mn" (receive port m, transmit port n).
    noise_figure_db : float
        Receiver noise figure F [dB].
    noise_bandwidth : float
        Receiver noise bandwidth B_n [Hz].
    thermal_noise : bool
        Add k T0 F B_n noise to every pulse.
    window_m : (float, float) or None
        Receive window as ranges c tau / 2 [m]; None: cover the tile and the targets.
    tile_size : (float, float) or None
        Sea tile extents (Lx, Ly) [m] the automatic window covers; None without sea.
    sea_clutter : bool
        Whether the sea echoes (sets the automatic window).
    targets : TargetSet or None
        Point targets.
    seed : int
        The scene's seed (noise stream).
    range_weighting : str
        Matched-filter weighting ('none', 'hamming', 'taylor').
    taylor_nbar : int
        Taylor window nbar.
    taylor_sidelobe_db : float
        Taylor window peak sidelobe level below the peak [dB].
    sea_update_pulses : int
        The sea surface is recomputed every N pulses.
    sigma_map_pulse : int
        Pulse whose sigma maps a run saves.
    accumulation_precision : str
        Floating point of the echo accumulation's NUFFT ('double' or 'single',
        :func:`seaecho.radar.echo.accumulate`).
    earth : SphericalEarth or None
        A spherical (effective-radius) Earth: platforms and targets are given in
        Earth-following coordinates and mapped to the tangent frame, targets beyond the
        horizon do not echo (:mod:`seaecho.geometry.earth`); None: flat Earth.
    transmit_phase : str
        'coherent' (every pulse leaves with phase 0) or 'random' (a magnetron: each
        pulse's phase uniform in [0, 2 pi) from the ``"transmit-phase"`` stream).
    sea_gain_floor : float or None
        Two-way gain relative to the beams' peaks [-] below which, bounded over the
        whole tile, a pulse skips the sea (:mod:`seaecho.radar.coverage`); None: never.
    multipath : TwoRay or None
        The sea's two-ray propagation factor applied to point targets and sea facets
        (:mod:`seaecho.radar.propagation`); None: free space.
    window_points : (K, 3) array or None
        Further points the automatic receive window covers, in the simulation frame [m]
        (the echoing land's outline at the sea level and at its height); None: none.
    """

    carrier: float
    sampling_rate: float
    prf: float
    n_pulses: int
    start_time: float
    transmit_power: float
    waveform: Waveform
    tx: Platform
    rx: Platform
    tx_antenna: Antenna
    rx_antenna: Antenna
    tx_pointing: Pointing
    rx_pointing: Pointing
    channels: tuple[str, ...]
    noise_figure_db: float
    noise_bandwidth: float
    thermal_noise: bool
    window_m: tuple[float, float] | None
    tile_size: tuple[float, float] | None
    sea_clutter: bool
    targets: TargetSet | None
    seed: int
    range_weighting: str = "none"
    taylor_nbar: int = 5
    taylor_sidelobe_db: float = 35.0
    sea_update_pulses: int = 1
    sigma_map_pulse: int = 0
    accumulation_precision: str = "double"
    earth: SphericalEarth | None = None
    transmit_phase: str = "coherent"
    sea_gain_floor: float | None = None
    multipath: TwoRay | None = None
    window_points: np.ndarray | None = None

    @property
    def monostatic(self) -> bool:
        """True when the receiver is the transmitter's platform and antenna."""
        return self.rx is self.tx

    @property
    def scan_period(self) -> float | None:
        """Scan period [s] of the scanning antenna, None when neither antenna scans.

        The transmitter's (one revolution, or a sector's back-and-forth,
        :attr:`seaecho.radar.pointing.Scan.period`), else the receiver's: the time over
        which a scanning radar revisits a target (scan-to-scan decorrelation of
        fluctuating targets).
        """
        for pointing in (self.tx_pointing, self.rx_pointing):
            if pointing.scan_period is not None:
                return pointing.scan_period
        return None

    @property
    def scanning(self) -> bool:
        """Whether an antenna scans."""
        return self.scan_period is not None


__all__ = ["RadarModel", "TargetSet"]
