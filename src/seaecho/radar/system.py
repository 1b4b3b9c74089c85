"""The assembled radar of a scene: platforms, antennas and pointing, waveform, window.

:class:`RadarSystem` is the radar stage's entry point. It is built from a
:class:`~seaecho.radar.model.RadarModel` (plain values; :func:`seaecho.build.build_radar`
makes the one of a scene) and works on plain arrays:
for pulse ``p`` and scatterers (positions, velocities, 2x2 scattering amplitudes in the
world FSA bases), :meth:`RadarSystem.scatterer_echo` gives the delays and per-channel
complex amplitudes of eq (R1) (``seaecho.radar.equation``), and
:meth:`RadarSystem.receive` sums them into the raw samples (eq E2,
``seaecho.radar.echo``) with optional thermal noise. Pulse p is emitted at
t_p = t_start + p / PRF. Nothing is carried from pulse to pulse.

Pointing. A look-at antenna is aimed at t_start from the nominal track and then stays
fixed to its platform (stripmap; the platform's attitude errors move the beam), unless
``track_look_at`` keeps it on the point at every pulse (spotlight). Antennas pointed by
angles are fixed in the body frame.

Approximations: stop-and-hop within one pulse (the delay is constant over the pulse;
the Doppler phase changes from pulse to pulse) and the receiver's attitude taken at the
emission time (the echo arrives microseconds later).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..backend import aligned
from ..constants import C0
from ..geometry.frames import tile_outline
from ..rng import generator
from .echo import DIRECT_TERMS, ReceiveWindow, accumulate, accumulate_cuda_sets
from .equation import noise_power, thermal_noise
from .model import RadarModel
from .platforms import PlatformState
from .pointing import Pointing

#: Default of ``RadarSystem.freeze`` (the scatterers' radar equation recorded and
#: replayed, :mod:`seaecho.radar.replay`): the environment variable
#: ``SEAECHO_FREEZE_ECHO`` ("1" on, "0" off), else None: on for both back ends (a
#: replay costs less than a trace on the CPU too: 0.3 against 0.7 ms for 3 scatterers,
#: 27 against 29 ms for 50 000; docs/performance.md, section 4).
FREEZE_ECHO: bool | None = ({"1": True, "0": False}.get(os.environ["SEAECHO_FREEZE_ECHO"])
                            if "SEAECHO_FREEZE_ECHO" in os.environ else None)


#: Pulse geometries :meth:`RadarSystem.geometry` keeps (the most recent ones).
GEOMETRIES_KEPT = 8


@dataclass(frozen=True)
class PulseGeometry:
    """Platform states and antenna axes at one pulse's emission time."""

    time: float
    tx: PlatformState
    rx: PlatformState
    tx_axes: NDArray[np.float64]
    rx_axes: NDArray[np.float64]


@dataclass(frozen=True)
class ScattererEcho:
    """Delays and amplitudes of a set of scatterers for one pulse (eq R1).

    Attributes
    ----------
    tau : (K,) total delay tau_t + tau_r [s] (float64)
    amplitudes : (C, K) complex amplitude per channel [sqrt(W)], carrier phase included;
        or a list of C (K,) complex arrays (the fused sea kernel)
    r_t, r_r : (K,) ranges [m], or None (the fused sea kernel, ``seaecho.radar.resident``,
        returns only what the accumulation needs)
    g_t, g_r : (K,) antenna power gains [-], or None (likewise)
    n_i, n_s : (K, 3) unit propagation directions [-], or None when not asked for
    """

    tau: NDArray[np.float64]
    amplitudes: NDArray[np.complex128] | list[NDArray[np.complex128]]
    r_t: NDArray[np.float64] | None
    r_r: NDArray[np.float64] | None
    g_t: NDArray[np.float64] | None
    g_r: NDArray[np.float64] | None
    n_i: NDArray[np.float64] | None
    n_s: NDArray[np.float64] | None


@dataclass(frozen=True)
class DeviceEcho:
    """Delays and amplitudes of scatterers that stay in GPU memory (eq R1).

    :meth:`RadarSystem.receive` accumulates them on the device
    (:func:`seaecho.radar.echo.accumulate_cuda`); only the pulse's samples come back.

    Attributes
    ----------
    xp : seaecho.backend.DrJitNamespace
        The namespace (``drjit.cuda``) the arrays live in.
    tau : Dr.Jit Float64 (K,)
        Total delays [s], all inside the receive window.
    amplitudes : tuple of C Dr.Jit Float64 (2 K,)
        Complex amplitudes [sqrt(W)] per channel, interleaved (re, im): the memory of a
        complex (K,) array each.
    n_channels : int
        C.
    """

    xp: Any
    tau: Any
    amplitudes: Any
    n_channels: int
    #: host arrays the device arrays may alias (LLVM maps aligned numpy memory)
    host: Any = field(default=None, repr=False, compare=False)

    @classmethod
    def upload(cls, xp: Any, tau: NDArray, amplitudes) -> DeviceEcho:
        """Host delays (K,) [s] and C channels' complex amplitudes (K,) [sqrt(W)] as a
        device echo in ``xp`` (the inverse of :meth:`to_host`)."""
        host = [aligned(np.asarray(tau, dtype=np.float64), np.float64)]
        host += [aligned(np.ascontiguousarray(a, dtype=np.complex128).view(np.float64),
                         np.float64) for a in amplitudes]
        dev = [xp.Float(h) for h in host]
        return cls(xp, dev[0], tuple(dev[1:]), len(dev) - 1, host)

    def to_host(self) -> ScattererEcho:
        """The same echo as numpy arrays (a copy from the device)."""
        tau = np.array(self.xp.host(self.tau), dtype=np.float64)
        amp = np.stack([np.array(self.xp.host(a)).view(np.complex128)
                        for a in self.amplitudes])
        return ScattererEcho(tau, amp, None, None, None, None, None, None)


def canonical_channels(channels, rx_ports: tuple[str, str], tx_ports: tuple[str, str]
                       ) -> list[tuple[str, int, int]]:
    """Validate channel names and order them like HH, HV, VH, VV.

    Returns
    -------
    list of (name, receive port index, transmit port index)
    """
    out = []
    for name in channels:
        if len(name) != 2 or name[0] not in rx_ports or name[1] not in tx_ports:
            raise ValueError(f"channel {name!r}: must be a receive port of {rx_ports} "
                             f"followed by a transmit port of {tx_ports}")
        out.append((name, rx_ports.index(name[0]), tx_ports.index(name[1])))
    return sorted(out, key=lambda c: (c[1], c[2]))


class RadarSystem:
    """Platforms, antennas, waveform and receive window of a radar (see module docstring)."""

    def __init__(self, model: RadarModel, window: ReceiveWindow | None = None,
                 backend: str = "drjit") -> None:
        """Build the radar of a :class:`~seaecho.radar.model.RadarModel`.

        Parameters
        ----------
        model : RadarModel
            The radar (``seaecho.build.build_radar(scene)``).
        window : ReceiveWindow or None
            Overrides the model's window (default: its ``window_m``, or the automatic one
            covering the tile and the targets, :meth:`auto_window`).
        backend : {'drjit', 'numpy'}
            Per-scatterer kernel: fused Dr.Jit (float64, fast) or the numpy reference.
        """
        if backend not in ("drjit", "numpy"):
            raise ValueError(f"backend = {backend!r}: allowed 'drjit', 'numpy'")
        if not isinstance(model, RadarModel):
            raise TypeError(f"RadarSystem needs a RadarModel (seaecho.build.build_radar), "
                            f"got {type(model).__name__}")
        self.backend = backend
        self.model = model
        self.seed = model.seed
        self.carrier = model.carrier
        self.wavelength = C0 / model.carrier
        self.prf = model.prf
        self.start_time = model.start_time
        self.n_pulses = model.n_pulses
        self.transmit_power = model.transmit_power
        self.waveform = model.waveform
        self.monostatic = model.monostatic
        self.tx, self.rx = model.tx, model.rx
        self.tx_antenna, self.rx_antenna = model.tx_antenna, model.rx_antenna
        self.tx_pointing, self.rx_pointing = model.tx_pointing, model.rx_pointing
        self.channels = canonical_channels(model.channels, self.rx_antenna.ports,
                                           self.tx_antenna.ports)
        self.noise_power = noise_power(model.noise_figure_db, model.noise_bandwidth)
        if window is None:
            if model.window_m is not None:
                window = ReceiveWindow.from_ranges(*model.window_m, model.sampling_rate,
                                                   self.waveform.duration)
            else:
                window = self.auto_window()
        self.window = window
        self.n_fft = window.n_fft(self.waveform.n_samples)
        self._spectrum = self.waveform.spectrum(self.n_fft)
        #: replay the recorded radar-equation kernel of :meth:`scatterer_echo`
        #: (``drjit.freeze``, :mod:`seaecho.radar.replay`) instead of tracing it at each
        #: call; None: :data:`FREEZE_ECHO`, and where that is None, on (both back ends)
        self.freeze: bool | None = None
        self._replay: dict[str, Any] = {}
        #: keep a replayed echo asked for ``on_device`` (a hull's centres) in the device's
        #: memory, as a :class:`DeviceEcho` for the pulse's one transform
        #: (:func:`~seaecho.radar.echo.accumulate_cuda_sets`): None: on ``drjit.cuda``
        #: only; True: on any Dr.Jit namespace (the CPU tests of the GPU's branch)
        self.device_echoes: bool | None = None
        #: kept pulse geometries: key -> (geometry, the platforms and pointings it is of)
        self._geometries: dict[tuple, tuple[PulseGeometry, tuple]] = {}

    def __getstate__(self) -> dict:
        state = dict(self.__dict__)
        state["_replay"] = {}  # recordings stay in their process (they do not pickle)
        state["_geometries"] = {}
        return state

    def frozen(self, xp: Any) -> bool:
        """Whether :meth:`scatterer_echo` replays its recorded kernel on namespace ``xp``
        (:attr:`freeze`); makes the recorder on first use."""
        on = self.freeze
        if on is None:
            on = True if FREEZE_ECHO is None else FREEZE_ECHO
        if not on:
            return False
        if xp.name not in self._replay:
            from .replay import FrozenEchoTerms

            self._replay[xp.name] = FrozenEchoTerms(xp, self)
        return self._replay[xp.name].error is None

    # ------------------------------------------------------------------------ basics
    @property
    def scan_period(self) -> float | None:
        """Scan period [s] of a scanning antenna (a revolution, or a sector's
        back-and-forth), None when no antenna scans (:attr:`RadarModel.scan_period`)."""
        return self.model.scan_period

    @property
    def channel_names(self) -> list[str]:
        """Channel names in axis order, e.g. ['HH', 'HV', 'VH', 'VV']."""
        return [c[0] for c in self.channels]

    def emission_time(self, pulse: ArrayLike) -> NDArray[np.float64]:
        """Emission time of pulse(s) t_p = t_start + p / PRF [s]."""
        return self.start_time + np.asarray(pulse, dtype=float) / self.prf

    def geometry(self, pulse: int) -> PulseGeometry:
        """Platform states and antenna axes at the emission of ``pulse``.

        The last few pulses' geometries are kept (a pulse asks for its own two to three
        times: its echoes, the sea's gain bound, the hulls' beam test), up to
        :data:`GEOMETRIES_KEPT` before they are dropped together: the same object, whose
        arrays must not be written."""
        parts = (self.tx, self.rx, self.tx_pointing, self.rx_pointing)
        key = (int(pulse), self.start_time, self.prf) + tuple(map(id, parts))
        hit = self._geometries.get(key)
        if hit is not None:
            return hit[0]
        t = float(self.emission_time(pulse))
        tx, rx = self.tx.state(t), self.rx.state(t)
        geo = PulseGeometry(t, tx, rx, self.tx_pointing.axes(tx, t),
                            self.rx_pointing.axes(rx, t))
        kept = self._geometries
        if len(kept) >= GEOMETRIES_KEPT:  # a new dict (other threads may be reading)
            self._geometries = kept = {}
        # the entry holds the objects it was computed from: while it is kept, their ids
        # cannot be taken by a platform or pointing assigned later (a stale geometry)
        kept[key] = (geo, parts)
        return geo

    def target_positions(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
        """Positions [m] of the model's targets at time t [s] in the simulation frame
        (mapped to the tangent frame on a spherical Earth, eq E4) and whether each is
        above both platforms' horizon (all True on a flat Earth)."""
        targets = self.model.targets
        p = targets.positions + t * targets.velocities
        earth = self.model.earth
        if earth is None:
            return p, np.ones(len(p), dtype=bool)
        p = earth.position(p)
        seen = (earth.visible(self.tx.state(t).position, p)
                & earth.visible(self.rx.state(t).position, p))
        return p, seen

    def auto_window(self, margin_m: float | None = None) -> ReceiveWindow:
        """Receive window covering the sea tile (and its waves), the targets and the
        model's ``window_points`` (the land).

        Ranges (r_t + r_r)/2 are evaluated on the tile's boundary and centre at z = 0 and
        at every target, at the first and last pulse; the window adds ``margin_m``
        (default: 5 % of the tile diagonal + 4 range resolutions + 5 m) on both sides.
        """
        start, end = self.auto_window_m(margin_m)
        return ReceiveWindow.from_ranges(start, end, self.model.sampling_rate,
                                         self.waveform.duration)

    def auto_window_m(self, margin_m: float | None = None) -> tuple[float, float]:
        """Ranges (start, end) c tau / 2 [m] of :meth:`auto_window`."""
        m = self.model
        lx, ly = m.tile_size if m.tile_size is not None else (0.0, 0.0)
        clutter = m.sea_clutter and m.tile_size is not None
        points = tile_outline(lx, ly)
        ranges = []
        for pulse in (0, self.n_pulses - 1):
            t = float(self.emission_time(pulse))
            pt = self.tx.state(t).position
            pr = self.rx.state(t).position
            pts = [points] if clutter else []
            if m.targets is not None and len(m.targets):
                pts.append(self.target_positions(t)[0])
            if m.window_points is not None:  # the land's outline
                pts.append(m.window_points)
            if not pts:
                continue
            p = np.vstack(pts)
            ranges.append(0.5 * (np.linalg.norm(p - pt, axis=-1)
                                 + np.linalg.norm(p - pr, axis=-1)))
        if not ranges:
            raise ValueError("nothing to receive: sea_clutter is off and there are no "
                             "targets; give window_start_m/window_end_m")
        r = np.concatenate(ranges)
        if margin_m is None:
            margin_m = (0.05 * np.hypot(lx, ly) * clutter
                        + 4 * C0 / (2 * self.waveform.bandwidth) + 5.0)
        return float(max(r.min() - margin_m, 0.0)), float(r.max() + margin_m)

    # ------------------------------------------------------------------ scatterers
    def scatterer_echo(self, geometry: PulseGeometry, positions: ArrayLike,
                       velocities: ArrayLike, s: ArrayLike, directions: bool = False, *,
                       variant: str | None = None, precision: str = "double",
                       multipath: bool = False, on_device: bool = False
                       ) -> ScattererEcho | DeviceEcho:
        """Delays and per-channel amplitudes of scatterers, eqs (R1) and (R3).

        Evaluates :func:`seaecho.radar.kernels.echo_terms` as one fused Dr.Jit kernel
        when ``self.backend`` is ``"drjit"`` (default) and with numpy
        (:meth:`scatterer_echo_numpy`) when it is ``"numpy"``: the same formulas, the
        same numbers within rounding (tests).

        Parameters
        ----------
        geometry : PulseGeometry
            From :meth:`geometry`.
        positions : array_like (K, 3)
            Scatterer positions at the emission time [m].
        velocities : array_like (K, 3)
            Scatterer velocities [m/s].
        s : array_like (K, 2, 2) complex
            Scattering amplitudes [m] in (h, v) order on the world FSA bases of n_i and
            n_s (``seaecho.geometry.frames.polarisation_basis`` with normal +z).
        directions : bool
            Also return the unit directions n_i, n_s (the Dr.Jit path leaves them None
            otherwise, to save memory traffic; the numpy path always returns them).
        variant : str, optional
            Mitsuba variant of the Dr.Jit kernel: ``"llvm_ad_mono_polarized"`` (CPU,
            default) or ``"cuda_ad_mono_polarized"`` (GPU).
        precision : {"double", "single"}
            Working precision of the antenna gains, port states and polarimetric factor
            in the Dr.Jit kernel (``kernels.echo_terms``, ``scattering``): the sea's
            reference path passes ``seaecho.scattering.facet.PRECISION``, as its fused
            kernel does; delays, directions, carrier phase and the amplitude's magnitude
            are float64 in either.
        multipath : bool
            Multiply the scattering amplitudes by the sea's two-ray propagation factors,
            S' = diag(F_r) S diag(F_t) (:meth:`seaecho.radar.propagation.TwoRay.apply`,
            eq P1), when the model has them (``[propagation] multipath``): point targets
            and sea facets ask for it, ray-traced hulls (whose trace follows the sea's
            reflections) do not.
        on_device : bool
            The echo may stay in the device's memory (a hull's centres): where
            :attr:`device_echoes` allows it, the replayed kernel's delays and amplitudes
            are returned as a :class:`DeviceEcho` (:meth:`device_echo`) when the set is
            large enough for the NUFFT; otherwise, and where the kernel is traced, a
            :class:`ScattererEcho` as always.

        Returns
        -------
        ScattererEcho or DeviceEcho
        """
        if self.backend == "numpy" or np.size(positions) == 0:
            return self.scatterer_echo_numpy(geometry, positions, velocities, s,
                                             multipath=multipath)
        from ..backend import drjit_namespace
        from .kernels import scatterer_echo

        p = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
        v = np.asarray(velocities, dtype=np.float64).reshape(-1, 3)
        s = np.asarray(s, dtype=np.complex128)
        if s.shape != (p.shape[0], 2, 2):  # (a view would hide a hull's resident amplitudes)
            s = s.reshape(-1, 2, 2)
        s = self.propagated(geometry, p, s, multipath)
        xp = drjit_namespace(variant)
        r = None
        if self.frozen(xp):  # the recorded kernel replayed (radar.replay)
            device = on_device and not directions and self.keeps_on_device(xp, p.shape[0])
            r = self._replay[xp.name](geometry, p, v, s, directions, precision,
                                      device=device)
            if device and r is not None:
                return self.device_echo(xp, r["tau"], r["amplitudes"], r["keep"])
        if r is None:
            xs = None if precision == "double" else xp.with_precision(precision)
            r = scatterer_echo(xp, self, geometry, p, v, s, directions, scattering=xs)
        return ScattererEcho(r["tau"], r["amplitudes"], r["r_t"], r["r_r"], r["g_t"],
                             r["g_r"], r.get("n_i"), r.get("n_s"))

    def keeps_on_device(self, xp: Any, n: int) -> bool:
        """Whether an echo of ``n`` scatterers asked for ``on_device`` stays on namespace
        ``xp``'s device (:attr:`device_echoes`; only a set that :meth:`receive` would
        give the NUFFT, not the direct sum)."""
        on = self.device_echoes
        if on is None:
            on = xp.name == "cuda"
        return bool(on) and not xp.is_numpy and n * self._spectrum.size > DIRECT_TERMS

    def device_echo(self, xp: Any, tau: Any, amplitudes: list, keep: Any = None
                    ) -> DeviceEcho:
        """A :class:`DeviceEcho` of Dr.Jit delays (K,) [s] and C complex amplitudes (K,)
        [sqrt(W)]: each channel interleaved (re, im) into one (2 K,) array on the device,
        zero for the scatterers whose echo misses the receive window (those
        :meth:`receive` cuts from a host echo: a zero amplitude adds nothing to eq E2's
        sum, and the device's accumulation folds every delay into the window). Nothing
        is read back; ``keep`` holds host buffers the arrays may alias."""
        lo, hi = self.window.bounds(self.waveform.n_samples)
        inside = (tau > lo) & (tau < hi)
        idx = xp.arange(xp.width(tau))
        zero = xp.Float(0.0)
        out = []
        for a in amplitudes:
            buf = xp.empty(2 * xp.width(tau))
            xp.scatter(buf, xp.pair(xp.dr.select(inside, xp.Float(a.real), zero),
                                    xp.dr.select(inside, xp.Float(a.imag), zero)), idx)
            out.append(buf)
        return DeviceEcho(xp, tau, tuple(out), len(out), keep)

    def propagated(self, geometry: PulseGeometry, positions: NDArray[np.float64],
                   s: NDArray[np.complex128], multipath: bool) -> NDArray[np.complex128]:
        """Scattering amplitudes (K, 2, 2) [m] times the sea's two-ray factors of the
        transmit and receive legs (eq P1 of :mod:`seaecho.radar.propagation`) when
        ``multipath`` is asked for and the model has them; ``s`` itself otherwise."""
        two_ray = self.model.multipath
        if not multipath or two_ray is None or len(s) == 0:
            return s
        return two_ray.apply(s, positions, geometry.tx.position, geometry.rx.position,
                             self.monostatic)

    def scatterer_echo_numpy(self, geometry: PulseGeometry, positions: ArrayLike,
                             velocities: ArrayLike, s: ArrayLike, *,
                             multipath: bool = False) -> ScattererEcho:
        """Numpy evaluation of :meth:`scatterer_echo` (same parameters and result)."""
        from ..backend import NUMPY
        from .kernels import scatterer_echo

        p = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
        v = np.asarray(velocities, dtype=np.float64).reshape(-1, 3)
        s = self.propagated(geometry, p, np.asarray(s, dtype=np.complex128).reshape(-1, 2, 2),
                            multipath)
        r = scatterer_echo(NUMPY, self, geometry, p, v, s, directions=True)
        return ScattererEcho(r["tau"], r["amplitudes"], r["r_t"], r["r_r"], r["g_t"],
                             r["g_r"], r["n_i"], r["n_s"])

    # --------------------------------------------------------------------- receive
    def receive(self, pulse: int, echoes: list[ScattererEcho], noise: bool | None = None,
                out: NDArray[np.complex128] | None = None) -> NDArray[np.complex128]:
        """Raw samples of one pulse: the sum of the echoes (eq E2) plus thermal noise.

        Parameters
        ----------
        pulse : int
            Pulse index (selects the noise stream).
        echoes : list of ScattererEcho or DeviceEcho
            Scatterer sets (sea facets, targets) of this pulse, each accumulated by
            :func:`~seaecho.radar.echo.accumulate` (a few targets: the direct sum; the
            sea: the NUFFT) or, on a GPU, :func:`~seaecho.radar.echo.accumulate_cuda`.
        noise : bool or None
            Add k T0 F B noise; default the model's ``thermal_noise``.
        out : ndarray (C, n_samples) complex, optional
            Written in place.

        Returns
        -------
        ndarray (C, n_samples) complex [sqrt(W)]
        """
        n_ch = len(self.channels)
        if out is None:
            out = np.zeros((n_ch, self.window.n_samples), dtype=np.complex128)
        else:
            out[...] = 0.0
        # A pulse whose sea is on a GPU accumulates there the host scatterer sets that
        # would take the NUFFT (a hull's centres): uploaded, cufinufft on the same plan
        # (all of them in one transform: accumulate_cuda_sets)
        device = next((e.xp for e in echoes if isinstance(e, DeviceEcho)), None)
        on_device: list[DeviceEcho] = []
        for e in echoes:  # a handful of scatterer sets (sea, targets), each one vectorised
            if isinstance(e, DeviceEcho):  # already cut to the window, on the GPU
                on_device.append(e)
                continue
            if self.window.keeps_all(e.tau, self.waveform.n_samples):  # no copies
                tau, amp = e.tau, e.amplitudes
            else:
                keep = self.window.keep(e.tau, self.waveform.n_samples)
                if isinstance(e.amplitudes, np.ndarray):
                    tau, amp = e.tau[keep], e.amplitudes[:, keep]
                else:
                    tau, amp = e.tau[keep], [a[keep] for a in e.amplitudes]
            if device is not None and tau.size * self._spectrum.size > DIRECT_TERMS:
                on_device.append(DeviceEcho.upload(device, tau, amp))
            elif tau.size:
                out += accumulate(tau, amp, self._spectrum, self.window,
                                  precision=self.model.accumulation_precision)
        if on_device:
            out += accumulate_cuda_sets(device, [(e.tau, e.amplitudes) for e in on_device],
                                        self._spectrum, self.window)
        if self.model.transmit_phase == "random":  # a magnetron: a new phase per pulse
            out *= np.exp(1j * self.transmit_phase(pulse))
        if self.model.thermal_noise if noise is None else noise:
            out += thermal_noise(out.shape, self.noise_power,
                                 generator(self.seed, "noise", pulse))
        return out

    def transmit_phase(self, pulse: int) -> float:
        """Transmitted phase of ``pulse`` [rad]: 0 for a coherent radar; for a random
        one (a magnetron, whose oscillation starts from noise at every pulse) uniform in
        [0, 2 pi) from the ``"transmit-phase"`` stream, pulse index (Skolnik 2001,
        section 3.5: a magnetron's phase is random from pulse to pulse)."""
        if self.model.transmit_phase != "random":
            return 0.0
        return float(generator(self.seed, "transmit-phase", pulse).uniform(0.0, 2.0 * np.pi))

    def target_echo(self, geometry: PulseGeometry, *, variant: str | None = None,
                    pulse: int | None = None, hidden: ArrayLike | None = None
                    ) -> ScattererEcho | None:
        """Echo of the model's point targets at one pulse (None if there are none, or
        all are beyond the horizon of a spherical Earth or ``hidden``), with the sea's
        two-ray factors when the model has them (``[propagation] multipath``); ``variant`` as
        :meth:`scatterer_echo`; ``pulse`` (default: the pulse emitted at
        ``geometry.time``) selects the fluctuating targets' draws
        (:meth:`~seaecho.radar.model.TargetSet.scattering_at`); ``hidden`` (T,) bool:
        targets hidden otherwise (behind the land or a wave crest:
        ``Simulation.targets_hidden``)."""
        targets = self.model.targets
        if targets is None or not len(targets):
            return None
        p, seen = self.target_positions(geometry.time)
        if hidden is not None:
            seen = seen & ~np.asarray(hidden, dtype=bool)
        if not seen.any():
            return None
        if pulse is None:
            pulse = int(np.rint((geometry.time - self.start_time) * self.prf))
        scattering = targets.scattering_at(pulse)
        v = targets.velocities
        if self.model.earth is not None:  # velocities turned by the local tilt
            v = np.einsum("...ij,...j->...i", self.model.earth.tilt(
                targets.positions + geometry.time * v), v)
        if seen.all():
            return self.scatterer_echo(geometry, p, v, scattering, variant=variant,
                                       multipath=True)
        return self.scatterer_echo(geometry, p[seen], v[seen], scattering[seen],
                                   variant=variant, multipath=True)


__all__ = [
    "DeviceEcho",
    "Pointing",
    "PulseGeometry",
    "RadarSystem",
    "ScattererEcho",
    "canonical_channels",
]
