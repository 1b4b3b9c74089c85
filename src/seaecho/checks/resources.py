"""Resources of a run: peak memory and an order of magnitude of the run time.

`seaecho check` prints :func:`estimate` for a scene; `seaecho run` prints it and refuses
(exit 2) a scene whose estimated peak exceeds the memory it may use, naming the fields
that drive the estimate, before anything large is allocated. The estimate is computed
from the scene alone (arithmetic, plus the nominal platform tracks for the receive
window): nothing in it allocates more than the scene's own description.

Model. The peak resident memory of ``seaecho run`` is

.. math::

    M = M_0 + (m_c + m_e) N_{cells} + m_f C N_{fft} + m_w C n_{chunk} N_s + m_p N_p
        + m_F N_p C N_s + m_g N_{gm} + m_t K                                     (M1)

with M_0 the process (Python, numpy, h5py, Dr.Jit; Mitsuba with sea clutter), N_cells the
sea grid's points (sea clutter on; m_e for an evolving sea only), C the channels, N_s the
samples of the receive window and N_fft its NUFFT period (``seaecho.radar.echo``), n_chunk
= min(16, N_p) pulses per write, N_p the pulses, N_gm the Gauss-Markov steps of the
perturbed platforms, K the point targets, and m_F the figures drawn from the whole raw and
compressed arrays (0 with ``--no-figures``: matplotlib's meshes cost 45 to 155 bytes per
value), which adds to the rest (the run loop's memory is not all returned to the system).

Or, if larger, M_0 + M_A: the normalisation of a rectangular aperture's pattern (eq A1
of ``seaecho.radar.antennas``, computed when the radar is built), bounded by
M_A = m_a n_theta^2 + 200 MiB with n_theta = 8 D / lambda + 96 (D the aperture's larger
side): a 100 m aperture at 1 THz would need petabytes, so the estimate refuses it. Its
time is that of the quadrature ``seaecho.radar.antennas.aperture_radiated_power`` makes
(``aperture_quadrature``: n_u Gauss-Legendre nodes in u times n_phi trapezoid nodes in
phi): t_l (2 n_u)^2 for the Gauss-Legendre rule (a symmetric tridiagonal eigenvalue
problem of order 2 n_u) plus t_q n_u n_phi for the sum, once per distinct aperture (the
normalisation is cached: a monostatic radar's receiver costs nothing more).

The coefficients are upper envelopes of the peak RSS measured by
``benchmarks/bench_resources.py`` (``ru_maxrss`` of the child process) on scenes that
vary one term at a time, from 4 096 to 1 048 576 sea grid points and up to 1.6 million
samples per pulse; the total is multiplied by :data:`SAFETY`. The accuracy on those
scenes is in docs/checks.md ("Resource estimate"); ``tests/test_resources.py`` runs a
small scene and checks that its measured peak is below the estimate.

Time (order of magnitude only, measured on one loaded 2-core machine): a start-up of a
few seconds plus a set-up per sea grid point (surface, wake, sigma maps), then per pulse
t_c N_cells + t_f C N_fft log2 N_fft + t_t K, then the figures per value drawn; each hull
trace t_r per launch-grid cell, launch (1, or 2 with sea multipath) and source (2
bistatic: the reciprocal mean of ``seaecho.tracing.sbr`` traces from T and from R).

A radar-wide sea (``[sea] coverage = "radar"``) counts the grid nodes of the tiles the
beam's bound keeps. Held (eqs U1-U3 of ``seaecho.coverage``), it costs per pulse
t_h per kept node (the gains and sum), plus each tile's unit echo made once per block
that meets it (eq M2 of :func:`coverage_cost`), and holds the unit echoes of one pulse's
tiles besides one batch of tiles in work; evolving, the tile pipeline of every kept
node at every pulse (t_c) and the tiles beyond the cache made again.

The memory a run may use is the smallest of the memory the system reports available
(``MemAvailable`` of ``/proc/meminfo``), the cgroup's limit less its usage, and the
``--max-memory-gb`` option or the ``SEAECHO_MAX_MEMORY_GB`` environment variable.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy.fft import next_fast_len

from ..config import SceneError
from ..constants import C0
from ..geometry.frames import tile_outline

MiB = 1024.0**2
GiB = 1024.0**3

# Coefficients of eq (M1) [bytes] (fitted, module docstring)
M0_TARGETS = 310 * MiB  #: process with the radar chain only (a clean install peaked at 319 MiB
#: on the 4-pulse calibration scene with figures, 2026-11: the API, guards and Dask imports)
M0_SEA = {"analytic": 310 * MiB, "raytraced": 310 * MiB}  #: with the sea stages
M_CELL = {"analytic": 2100.0, "raytraced": 2300.0}  #: per sea grid point
#: per sea grid point of an evolving sea (``[scattering] sea_motion``, "auto" resolved by
#: ``seaecho.build.sea_motion``): the speckle anchors of four families, the tilt nodes'
#: phases, the block's phase centres, velocities and accelerations; Simulation 1 (648^2
#: grid) peaked 0.42 GB higher evolving than held (docs/dynamics.md, Cost)
M_EVOLVING_CELL = 1000.0
M_FFT = 20.0  #: per channel and NUFFT bin (phasors, spectrum product, inverse FFT)
M_WRITE = 70.0  #: per channel, sample and buffered pulse (buffer, range compression)
M_PULSE = 1000.0  #: per pulse (tracks, times, per-pulse dataset variables)
M_FIGURE = 180.0  #: per pulse, channel and sample when figures are drawn
M_GM = 200.0  #: per Gauss-Markov step and perturbed platform
M_TARGET = 400.0  #: per point target
M_ANTENNA = 40.0  #: per n_theta^2 of a rectangular aperture's normalisation
M_ANTENNA_GRID = 200 * MiB  #: its integration grid (chunks of 2e6 directions)
M_SBR_RAY = 1200.0  #: per ray of a hull trace's batch (about 1 kB per ray)
M_SBR_CELL = 44.0  #: per cell of a hull trace's launch grid (coverage mask, indices, the
#: edge test's hits and the launch rays it keeps for the plain cells: the trace of
#: Simulation 1's boat peaked 43 MB higher with them, 2.1e6 cells)
M_CENTRE = 200.0  #: per scattering centre of a cached hull signature
M_PIXEL = 120.0  #: per image pixel (calibration maps, coverage, products' temporaries)
M_PIXEL_CHANNEL = 160.0  #: per image pixel and channel (accumulator, image, sigma0...)
M_UPSAMPLED = 40.0  #: per upsampled sample of the focusing's block of pulses
M_IMAGE_FIGURE = 60.0  #: per image pixel and figure panel drawn
IMAGE_PANELS = 12  #: figure panels of an image (``seaecho.plotting.image``)
#: per facet of a held radar-wide sea's unit echo (eq U1): its delay, direction and
#: azimuth (40 bytes of float64) and what making the tiles leaves in the allocators
#: (fitted: the 3 km revolution of ``benchmarks/bench_coverage.py --revolution 1000``
#: peaked at 598 MB with 0.6 million nodes kept), plus per channel its complex amplitude
M_UNIT_FACET = 150.0
M_UNIT_FACET_CHANNEL = 16.0
M_TRUTH_CELL = 100.0  #: per sea cell of a raw dataset read as the image's truth (sigma
#: map, elevations, wake mask, the Kelvin amplitude's filter)
#: Margin on the sum, so that the estimate stays above the measured peak.
SAFETY = 1.15

# Time coefficients [s] (order of magnitude)
T_START = {"targets": 4.0, "analytic": 5.0, "raytraced": 8.0}
T_CELL = {"analytic": 2.0e-6, "raytraced": 3.0e-6}  #: per sea grid point and pulse
T_CELL_SETUP = {"analytic": 1.0e-5, "raytraced": 1.5e-5}  #: per grid point, once (surface,
#: wake, the sigma-map pulse)
T_FFT = 4.0e-9
#: per tile of a radar-wide sea made (its surface, wake, facet engine and tracer): the
#: first pulse of scenes/sband_longrange.toml made 562 tiles in 69 s at a load of ~10
T_TILE = 0.1
#: A held radar-wide sea (eqs U1-U3 of ``seaecho.coverage``: each tile's unit echo made
#: once per block of held pulses that meets it, the gains and sum per pulse): a tile made
#: costs t_u + t_n n (n its grid nodes), a pulse t_h per node of the tiles it keeps.
#: Fitted to ``benchmarks/bench_coverage.py``'s coastal radar on two shared cores: its
#: tiles' relative costs (18, 36 and 92 ms of CPU per tile of 32^2, 64^2 and 128^2
#: nodes, load 8-9) scaled to the measured 3 km revolution (``--revolution 1000``: 2512
#: tiles made in 123 s of CPU, 34 ms per pulse besides, 0.48 million nodes kept; load
#: 6.8), and 53 ms per pulse with 0.72 million nodes kept at 12 km.
T_UNIT_TILE = 0.021
T_UNIT_NODE = 7.0e-6
T_HELD_NODE = 4.0e-8
T_TARGET = 2.0e-6
T_PULSE = 2.0e-2
T_FIGURE = 4.0e-6  #: per pulse, channel and sample drawn
T_LEGENDRE = 6.0e-8  #: per (2 n_u)^2 of the normalisation's Gauss-Legendre rule
T_QUADRATURE = 1.5e-7  #: per node n_u x n_phi of the normalisation's quadrature
T_RAY = 1.5e-6  #: per launch-grid cell, launch and source of a hull trace
T_BACKPROJECTION = 2.0e-8  #: per pixel, pulse and channel of the focusing

#: Environment variable that sets the memory limit [GB].
ENV_LIMIT = "SEAECHO_MAX_MEMORY_GB"
#: Sizes the estimate takes from the modules that own them (imported when first used:
#: the tracing and imaging modules cost a second of imports that ``seaecho check`` of a
#: scene without hulls or image does not need):
#: ``CHUNK`` most pulses per block of work when ``--block-pulses`` is not given
#: (``seaecho.io.run.block_size``: twice its target ``DEFAULT_BLOCK_PULSES``);
#: ``SIGNATURE_CACHE`` hull signatures a run keeps (``seaecho.tracing.hull_echo``);
#: ``SBR_BATCH`` rays per batch of a hull trace (``seaecho.tracing.sbr.SBROptions``);
#: ``IMAGE_BLOCK`` pulses per block of the focusing (``seaecho.imaging.focus.focus``'s
#: ``block_pulses``).
_OWNED = ("CHUNK", "SIGNATURE_CACHE", "SBR_BATCH", "IMAGE_BLOCK")


@functools.cache
def _owned(name: str) -> int:
    """The size ``name`` of :data:`_OWNED`, read from its module."""
    if name == "CHUNK":
        from ..io.run import DEFAULT_BLOCK_PULSES

        return 2 * DEFAULT_BLOCK_PULSES
    if name == "SIGNATURE_CACHE":
        from ..tracing.hull_echo import SIGNATURE_CACHE

        return SIGNATURE_CACHE
    if name == "SBR_BATCH":
        from ..tracing.sbr import SBROptions

        return SBROptions.batch
    if name == "IMAGE_BLOCK":
        import inspect

        from ..imaging.focus import focus

        return inspect.signature(focus).parameters["block_pulses"].default
    raise AttributeError(name)


def __getattr__(name: str) -> int:
    """``resources.CHUNK`` and the other sizes of :data:`_OWNED` (PEP 562)."""
    if name in _OWNED:
        return _owned(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


@dataclass(frozen=True)
class Estimate:
    """Estimated resources of a run.

    Attributes
    ----------
    peak_bytes : float
        Peak resident memory [bytes] (eq M1 times :data:`SAFETY`).
    time_s : float
        Order of magnitude of the run time [s].
    terms : dict
        Bytes of each term of eq (M1), with the fields that drive it as keys' values in
        ``drivers``.
    drivers : dict
        For each term, the scene fields that set it.
    n_samples, n_fft, n_pulses, channels, cells, pixels : int
        The sizes that enter the model (``pixels``: of the ``[image]``).
    hull_rays : float
        Launch-grid cells over every launch, source and trace of the hulls
        (:class:`HullSize`).
    """

    peak_bytes: float
    time_s: float
    terms: dict[str, float] = field(default_factory=dict)
    drivers: dict[str, str] = field(default_factory=dict)
    n_samples: int = 0
    n_fft: int = 0
    n_pulses: int = 0
    channels: int = 0
    cells: int = 0
    pixels: int = 0
    hull_rays: float = 0.0

    def largest_terms(self, n: int = 2) -> list[str]:
        """Names of the ``n`` largest terms (the process base left out; the antenna
        pattern's is transient, at the start, the others add up)."""
        named = [(v, k) for k, v in self.terms.items() if k != "process"]
        return [k for v, k in sorted(named, reverse=True)[:n] if v > 0]


# --------------------------------------------------------------------- nominal tracks
#: Perturbation bound in standard deviations (P(|x| > 8 sigma) = 1.2e-15 per sample).
PERTURBATION_SIGMAS = 8.0


@dataclass(frozen=True)
class Segment:
    """A piece of a nominal track: position c + v t for t in [t_a, t_b] [s]."""

    t_a: float
    t_b: float
    c: NDArray[np.float64]  #: position extrapolated to t = 0 [m]
    v: NDArray[np.float64]  #: velocity [m/s]


def nominal_segments(cfg) -> list[Segment]:
    """Segments of a ``[transmitter]`` / ``[receiver]`` section's nominal track.

    The first and last segments extend to -inf / +inf, as ``seaecho.radar.platforms``
    extrapolates them.
    """
    if cfg.motion in ("fixed", "linear"):
        v = np.array(cfg.velocity_m_s if cfg.motion == "linear" else (0.0, 0.0, 0.0))
        return [Segment(-np.inf, np.inf, np.array(cfg.position_m, dtype=float), v)]
    t = np.array(cfg.waypoint_times_s, dtype=float)
    p = np.array(cfg.waypoint_positions_m, dtype=float)
    out = []
    for i in range(t.size - 1):
        v = (p[i + 1] - p[i]) / (t[i + 1] - t[i])
        t_a = -np.inf if i == 0 else t[i]
        t_b = np.inf if i == t.size - 2 else t[i + 1]
        out.append(Segment(t_a, t_b, p[i] - v * t[i], v))
    return out


def perturbation_bound(cfg) -> float:
    """Bound on how far the true track strays from the nominal one [m] (8 sigma)."""
    if cfg.perturbation is None:
        return 0.0
    return PERTURBATION_SIGMAS * float(np.linalg.norm(cfg.perturbation.position_sigma_m))


# ----------------------------------------------------------------- receive window
def _nominal_position(cfg, t: float) -> np.ndarray:
    """Nominal position of a platform section at time t [m] (``platforms`` semantics)."""
    segs = nominal_segments(cfg)
    seg = next((s for s in segs if s.t_a <= t <= s.t_b), segs[-1])
    return seg.c + seg.v * t


def window_size(scene) -> tuple[int, int, int]:
    """(samples per pulse N_s, NUFFT period N_fft, pulse samples N_p) of a run.

    The same arithmetic as ``ReceiveWindow.from_ranges`` and ``RadarSystem.auto_window``
    (parity-tested), on the nominal tracks; a perturbed track widens the window by its
    8-sigma bound on each side, so the estimate stays an upper bound.
    """
    from ..radar.echo import GUARD

    r = scene.radar
    w = r.waveform
    fs = r.sampling_rate_hz
    n_pulse = max(int(np.ceil(w.duration_s * fs - 1e-9)), 1)
    bandwidth = w.bandwidth_hz if w.kind == "lfm" else 1.0 / w.duration_s
    if r.window_start_m is not None:
        start, end = r.window_start_m, r.window_end_m
    else:
        lx, ly = scene.sea.size_m
        points = tile_outline(lx, ly)
        rx_cfg = scene.receiver or scene.transmitter
        slack = 0.5 * (perturbation_bound(scene.transmitter) + perturbation_bound(rx_cfg))
        from ..build import build_earth, land_window_points

        earth = build_earth(scene)  # a spherical Earth: platforms and targets on it
        land = land_window_points(scene)
        on_earth = (lambda q: q) if earth is None else earth.position
        ranges = []
        for pulse in (0, r.n_pulses - 1):
            t = r.start_time_s + pulse / r.prf_hz
            pt = on_earth(_nominal_position(scene.transmitter, t))
            pr = on_earth(_nominal_position(rx_cfg, t))
            pts = [points] if r.sea_clutter else []
            pts += [on_earth(np.array(g.position_m) + t * np.array(g.velocity_m_s))
                    for g in scene.targets]
            if land is not None:  # the echoing land's outline (build.land_window_points)
                pts.append(on_earth(land))
            if not pts:
                continue
            p = np.vstack(pts)
            ranges.append(0.5 * (np.linalg.norm(p - pt, axis=-1)
                                 + np.linalg.norm(p - pr, axis=-1)))
        if not ranges:
            return 1, int(next_fast_len(1 + n_pulse + 2 * GUARD)), n_pulse
        rr = np.concatenate(ranges)
        margin = (0.05 * np.hypot(lx, ly) * r.sea_clutter + 4 * C0 / (2 * bandwidth) + 5.0
                  + slack)
        start, end = max(rr.min() - margin, 0.0), rr.max() + margin
    n_samples = math.ceil((2.0 * (end - start) / C0 + w.duration_s) * fs) + 1
    # next_fast_len is exact but slow for huge sizes; a power of two bounds it
    total = n_samples + n_pulse + 2 * GUARD
    n_fft = int(next_fast_len(total)) if total < 2**40 else 2 ** math.ceil(math.log2(total))
    return n_samples, n_fft, n_pulse


# --------------------------------------------------------------------------- model
def gauss_markov_steps(scene) -> float:
    """Gauss-Markov steps drawn for the perturbed platforms (``draw_perturbation``); a
    float, which may be infinite (a step of 5e-324 s)."""
    r = scene.radar
    span = (r.n_pulses - 1) / r.prf_hz + 1.0e-3
    steps = 0.0
    for cfg in (scene.transmitter, scene.receiver):
        if cfg is not None and cfg.perturbation is not None:
            steps += math.ceil(span / cfg.perturbation.step_s) + 2.0 if math.isfinite(
                span / cfg.perturbation.step_s) else math.inf
    return steps


def antenna_nodes(scene) -> list[tuple[str, int]]:
    """(section, n_theta) of each rectangular antenna's pattern normalisation."""
    lam = C0 / scene.radar.carrier_frequency_hz
    out = []
    for name in ("transmitter", "receiver"):
        cfg = getattr(scene, name)
        if cfg is None:
            cfg = scene.transmitter  # monostatic: the receiver is built from it again
        a = cfg.antenna
        if a.pattern == "rectangular":
            out.append((name, int(8 * max(a.width_m, a.height_m) / lam) + 96))
    return out


def antenna_quadratures(scene) -> list[tuple[int, int]]:
    """Quadrature nodes ``(n_u, n_phi)`` of each distinct rectangular aperture's pattern
    normalisation (``seaecho.radar.antennas.aperture_quadrature``; the normalisation is
    cached, so an aperture met twice, such as a monostatic radar's, counts once)."""
    from ..radar.antennas import aperture_quadrature

    lam = C0 / scene.radar.carrier_frequency_hz
    sizes = []
    for name in ("transmitter", "receiver"):
        cfg = getattr(scene, name) or scene.transmitter
        a = cfg.antenna
        if a.pattern == "rectangular" and (a.width_m, a.height_m) not in sizes:
            sizes.append((a.width_m, a.height_m))
    return [aperture_quadrature(w, h, lam) for w, h in sizes]


def nominal_positions(cfg, t: NDArray) -> NDArray[np.float64]:
    """Nominal positions of a platform section at times ``t`` (P,) [m], shape (P, 3)."""
    t = np.asarray(t, dtype=float)
    out = np.empty(t.shape + (3,))
    segs = nominal_segments(cfg)
    for k, seg in enumerate(segs):
        m = (t >= seg.t_a) & ((t < seg.t_b) | (k == len(segs) - 1))
        out[m] = seg.c + np.multiply.outer(t[m], seg.v)
    return out


@dataclass(frozen=True)
class HullSize:
    """Sizes of one hull's SBR traces (``[[objects]]`` with ``scatterer = true``).

    Attributes
    ----------
    name : str
    radius : float
        Bounding radius of its meshes about their origin [m].
    grid : float
        Launch-grid cells per launch, (2 radius / delta)^2 with delta = lambda / n the
        ray spacing: the rectangle that holds the hull's projection, at most.
    launches : int
        Launches per trace and source: 1, or 2 with sea multipath (from T and from its
        image).
    traces : int
        Traces over the run (``seaecho.targets.centres.refresh_schedule`` on the nominal
        tracks).
    centres : float
        Bound on the scattering centres of one trace: 4 path kinds x (2 radius / cell)^2.
    sources : int
        Sources the rays leave from: 2 when bistatic (the reciprocal mean, eq X2 of
        ``seaecho.tracing.sbr``, traces from T and from R), 1 monostatic.
    """

    name: str
    radius: float
    grid: float
    launches: int
    traces: int
    centres: float
    sources: int = 1


def hull_sizes(scene, base_dir=".") -> list[HullSize]:
    """:class:`HullSize` of each scatterer object whose files load (the others are
    reported by ``seaecho.checks.preflight.object_problems``)."""
    if not any(o.scatterer for o in scene.objects):
        return []
    from ..targets.centres import refresh_schedule
    from ..tracing.scene import load_object

    r = scene.radar
    lam = C0 / r.carrier_frequency_hz
    t = r.start_time_s + np.arange(r.n_pulses) / r.prf_hz
    tx = nominal_positions(scene.transmitter, t)
    rx = nominal_positions(scene.receiver or scene.transmitter, t)
    out = []
    for cfg in scene.objects:
        if not cfg.scatterer:
            continue
        try:
            shapes = load_object(cfg, base_dir=str(base_dir), ship=scene.ship)
        except (ValueError, OSError):
            continue
        o = shapes[0]
        radius = max(float(np.linalg.norm(s.world_vertices(0.0) - o.position, axis=-1).max())
                     for s in shapes)
        c = o.position + np.multiply.outer(t, o.velocity)
        with np.errstate(invalid="ignore", divide="ignore"):
            ut = (tx - c) / np.linalg.norm(tx - c, axis=-1, keepdims=True)
            ur = (rx - c) / np.linalg.norm(rx - c, axis=-1, keepdims=True)
        try:
            traces = len(refresh_schedule(ut, ur, t, np.deg2rad(cfg.signature_refresh_deg),
                                          cfg.signature_refresh_s))
        except ValueError:
            traces = r.n_pulses
        delta = lam / cfg.rays_per_wavelength
        out.append(HullSize(cfg.name, radius, (2.0 * radius / delta) ** 2,
                            2 if cfg.sea_multipath else 1, traces,
                            4.0 * (2.0 * radius / cfg.signature_cell_m) ** 2,
                            1 if np.array_equal(tx, rx) else 2))
    return out


def image_shape(scene) -> tuple[int, int]:
    """(ny, nx) pixels of the ``[image]`` grid ((0, 0) without one, or without an extent):
    its extent, or the default the focusing takes (the sea tile, else the targets' box
    plus 20 range resolutions), over the pixel size (default a quarter of the slant-range
    resolution c / (2 B)); the arithmetic of ``seaecho.imaging.focus.ImageGrid``."""
    cfg = scene.image
    if cfg is None:
        return 0, 0
    r = scene.radar
    w = r.waveform
    bandwidth = w.bandwidth_hz if w.kind == "lfm" else 1.0 / w.duration_s
    pixel = cfg.pixel_m if cfg.pixel_m is not None else C0 / (8.0 * bandwidth)
    if cfg.extent_m is not None:
        x0, x1, y0, y1 = cfg.extent_m
    elif r.sea_clutter:
        lx, ly = scene.sea.size_m
        x0, x1, y0, y1 = -0.5 * lx, 0.5 * lx, -0.5 * ly, 0.5 * ly
    elif scene.targets:
        p = np.array([g.position_m for g in scene.targets], dtype=float)
        m = 20.0 * C0 / (2.0 * bandwidth)
        x0, x1 = p[:, 0].min() - m, p[:, 0].max() + m
        y0, y1 = p[:, 1].min() - m, p[:, 1].max() + m
    else:
        return 0, 0  # no extent to focus on: seaecho.checks.preflight.image_problems
    return pixel_count(y1 - y0, pixel), pixel_count(x1 - x0, pixel)


def pixel_count(length: float, pixel: float) -> int:
    """Pixels of size ``pixel`` [m] along ``length`` [m], as ``ImageGrid.from_extent``
    rounds them (at least 1); an infinite count (a 5e-324 m pixel) is capped at 1e15."""
    with np.errstate(over="ignore"):
        n = np.float64(length) / pixel
    return max(1, int(round(n))) if n < 1.0e15 else 10**15


def image_term(pixels: int, channels: int, n_pulses: int, n_samples: int, upsample: int,
               panels: int, n_fft: int | None = None) -> float:
    """Bytes of the focusing (eq M1's image term): the pixels' maps and products, one
    block of upsampled pulses (at most :data:`IMAGE_BLOCK`, or the ``n_pulses``, of
    ``next_fast_len(n_samples)`` samples; capped by ``n_fft`` where given) and the
    figure panels."""
    up = _owned("IMAGE_BLOCK") * channels * upsample * next_fast_len(max(n_samples, 1))
    up = min(up, n_pulses * channels * upsample * (n_fft or next_fast_len(max(n_samples, 1))))
    return (M_PIXEL * pixels + M_PIXEL_CHANNEL * channels * pixels + M_UPSAMPLED * up
            + M_IMAGE_FIGURE * panels * pixels)


def image_pixels(scene) -> int:
    """Pixels of the ``[image]`` grid (:func:`image_shape`), 0 without one."""
    ny, nx = image_shape(scene)
    return ny * nx


def estimate(scene, figures: bool = True, *, workers: int | None = None,
             block: int | None = None, base_dir=".") -> Estimate:
    """Peak memory and run time of ``seaecho run`` for a scene (eq M1).

    Parameters
    ----------
    scene : seaecho.config.Scene
        With [radar] and [transmitter].
    figures : bool
        The run draws its figures (``seaecho run`` without ``--no-figures``).
    workers : int, optional
        ``--workers N``: a local cluster of N worker processes, each holding the
        simulation and a block of pulses (no figures, no image), besides this process.
    block : int, optional
        ``--block-pulses``: pulses per block (default at most :data:`CHUNK`).
    base_dir : path
        Folder of the scene file (the hulls' meshes are read to size their traces).

    A scene with ``[[receivers]]`` is estimated as the sum of its receivers' bistatic
    runs (:func:`multistatic_estimate`).
    """
    if getattr(scene, "receivers", ()):
        return multistatic_estimate(scene, figures, workers=workers, block=block,
                                    base_dir=base_dir)
    from ..build import sea_motion

    r = scene.radar
    sea = r.sea_clutter
    mode = scene.tracing.mode
    ny, nx = scene.sea.shape
    cells = nx * ny if sea else 0
    held = cells  # the sea's cells held in memory
    tiles_first = tiles_remade = 0.0  # tiles made at the first pulse and at every pulse
    unit = None  # a held radar-wide sea's unit echoes (CoverageCost)
    if sea and scene.sea.coverage == "radar":  # the tiles of each pulse (seaecho.coverage)
        if coverage_is_held(scene):
            unit = coverage_cost(scene)
            cells, held = unit.nodes_per_pulse, unit.nodes_in_work
        else:
            cells, held, tiles_first, tiles_remade = coverage_cells(scene)
    n_s, n_fft, _ = window_size(scene)
    c = len(r.channels)
    n_p = r.n_pulses
    chunk = min(block or _owned("CHUNK"), n_p)
    k = len(scene.targets)
    gm = gauss_markov_steps(scene)
    hulls = hull_sizes(scene, base_dir)
    pixels = image_pixels(scene)
    raytracing = sea and mode == "raytraced" or bool(hulls)
    terms = {
        "process": (M0_SEA["raytraced" if raytracing else mode] if sea or hulls
                    else M0_TARGETS),
        "sea grid": M_CELL[mode] * held,
        "evolving sea": M_EVOLVING_CELL * held if sea and sea_motion(scene) == "evolving"
        else 0.0,
        "receive window": M_FFT * c * n_fft + M_WRITE * c * chunk * n_s,
        "pulses": M_PULSE * n_p,
        "figures": M_FIGURE * n_p * c * n_s if figures else 0.0,
        "perturbation": M_GM * gm,
        "targets": M_TARGET * k,
        "hull traces": (max((M_SBR_RAY * min(_owned("SBR_BATCH"), h.grid) + M_SBR_CELL * h.grid
                             for h in hulls), default=0.0)
                        + sum(M_CENTRE * h.centres * min(h.traces, _owned("SIGNATURE_CACHE"))
                              for h in hulls)),
    }
    if unit is not None:
        terms["unit echoes"] = unit.held_facets * (M_UNIT_FACET + M_UNIT_FACET_CHANNEL * c)
    worker = sum(terms.values()) - terms["figures"]
    if workers:
        terms["workers"] = workers * worker
    if pixels:
        panels = IMAGE_PANELS if scene.image.figures and figures else 0
        terms["image"] = image_term(pixels, c, n_p, n_s, scene.image.upsample, panels,
                                    n_fft)
    window_fields = ("[radar].sampling_rate_hz, [radar.waveform].bandwidth_hz and "
                     "duration_s, the window (window_start_m/window_end_m, or the tile "
                     "and targets it covers), [radar].channels")
    drivers = {
        "process": "(fixed)",
        "sea grid": "[sea].nx, [sea].ny ([radar].sea_clutter)",
        "evolving sea": "[scattering].sea_motion ('auto': evolving when "
                        "[radar].sea_update_pulses < n_pulses), [sea].nx, [sea].ny",
        "receive window": window_fields + " (and --block-pulses)",
        "pulses": "[radar].n_pulses",
        "figures": "[radar].n_pulses x the receive window (use --no-figures)",
        "perturbation": "[transmitter/receiver.perturbation].step_s, [radar].n_pulses "
                        "and prf_hz",
        "targets": "[[targets]]",
        "hull traces": "[[objects]] scatterer: the mesh's size against the ray spacing "
                       "lambda / rays_per_wavelength, signature_cell_m, and the traces "
                       "signature_refresh_deg / signature_refresh_s make",
        "workers": "--workers (each worker holds the simulation and a block of pulses)",
        "image": "[image].pixel_m and extent_m (pixels), [radar].channels, "
                 "[image].upsample, figures",
        "unit echoes": "[sea] size_x_m, nx (the tiles' facets), the window's range and "
                       "the antenna's width (the tiles a pulse keeps), [radar].channels",
    }
    nodes = antenna_nodes(scene)
    n_theta = max((n for _, n in nodes), default=0)
    antenna = M_ANTENNA * n_theta**2 + (M_ANTENNA_GRID if n_theta >= 1000 else 0.0)
    terms["antenna pattern"] = antenna
    drivers["antenna pattern"] = ("[transmitter/receiver.antenna].width_m and height_m "
                                  "against the wavelength ([radar].carrier_frequency_hz)")
    stages = sum(v for k, v in terms.items() if k != "antenna pattern")
    peak = SAFETY * max(stages, terms["process"] + antenna)
    per_pulse = T_PULSE + T_TARGET * k + T_FFT * c * n_fft * math.log2(max(n_fft, 2))
    if unit is not None:  # the gains and sum of eq U2
        per_pulse += T_HELD_NODE * cells
    elif sea:
        per_pulse += T_CELL[mode] * cells + T_TILE * tiles_remade
    per_pulse += sum(T_TARGET * h.centres for h in hulls)
    start = T_START[mode] + T_CELL_SETUP[mode] * held if sea else T_START["targets"]
    start += T_TILE * tiles_first
    rays = sum(h.grid * h.launches * h.sources * h.traces for h in hulls)
    pulses = n_p * per_pulse + T_RAY * rays
    if unit is not None:  # the tiles' unit echoes, once per block that meets them
        start += unit.first_s
        pulses += unit.making_s
    if workers:
        pulses /= workers
    time_s = start + pulses + (T_FIGURE * n_p * c * n_s if figures else 0.0) + sum(
        T_LEGENDRE * (2 * n_u) ** 2 + T_QUADRATURE * n_u * n_phi
        for n_u, n_phi in antenna_quadratures(scene))
    time_s += T_BACKPROJECTION * pixels * n_p * c
    return Estimate(peak, time_s, terms, drivers, n_s, n_fft, n_p, c, cells, pixels, rays)


def coverage_cells(scene, samples: int = 16) -> tuple[int, int, float, float]:
    """A radar-wide sea's (``[sea] coverage = "radar"``) grid nodes computed per pulse
    (the mean over ``samples`` pulses spread over the run of the tiles the beam's bound
    keeps, :class:`seaecho.coverage.CoverageSea`), held at most (the budget
    :data:`~seaecho.coverage.CACHE_NODES`, or the nodes of the pulse that keeps most,
    plus one tile in work) [-], the tiles made at the first pulse and those made again
    at every pulse (the mean fraction of the kept tiles beyond the budget; the tiles the
    turning beam meets anew are left out) [-]."""
    from ..build import build_radar, coverage_layout, sea_spectrum
    from ..geometry.patchwork import CACHE_NODES, TILE_MARGIN_M
    from ..radar.coverage import two_way_bounds
    from ..radar.system import RadarSystem

    model = build_radar(scene)
    pw = coverage_layout(scene, model, sea_spectrum(scene))
    radar = RadarSystem(model)
    boxes = pw.boxes(TILE_MARGIN_M)
    nodes = np.array([np.prod(lv.shape) for lv in pw.levels])[pw.level]
    counts, most, tiles, remade = [], 0, [], []
    for p in np.unique(np.linspace(0, model.n_pulses - 1, samples).astype(int)):
        keep = two_way_bounds(radar, int(p), boxes) >= model.sea_gain_floor
        n = int(nodes[keep].sum())
        counts.append(n)
        most = max(most, n)
        tiles.append(int(keep.sum()))
        remade.append(keep.sum() * max(n - CACHE_NODES, 0) / max(n, 1))
    return (int(np.mean(counts)), min(CACHE_NODES, most) + int(nodes.max()),
            float(tiles[0]), float(np.mean(remade)))


def coverage_is_held(scene) -> bool:
    """Whether a ``coverage = "radar"`` scene takes the held sea's unit echoes (eqs
    U1-U3 of :mod:`seaecho.coverage`): its sea held within each block
    (``[scattering] sea_motion``, "auto" resolved by ``seaecho.build.sea_motion``) and
    no moving ``[[objects]]`` (a velocity, or following the ship)."""
    from ..build import sea_motion

    moving = any(np.any(np.asarray(o.velocity_m_s, dtype=float) != 0.0) or o.follow_ship
                 for o in scene.objects)
    return sea_motion(scene) == "held" and not moving


@dataclass(frozen=True)
class CoverageCost:
    """The sizes of a held radar-wide sea (:func:`coverage_cost`).

    Attributes
    ----------
    nodes_per_pulse : int
        Grid nodes of the tiles the beam's bound keeps, mean over the sampled pulses [-].
    nodes_in_work : int
        Grid nodes through the tile pipeline at once (a batch of one level,
        ``seaecho.coverage.BATCH_NODES``, or one larger tile) [-].
    held_facets : float
        Facets of the unit echoes held (two per node of the pulse that keeps most,
        within ``seaecho.coverage.CACHE_BYTES``) [-].
    first_s : float
        CPU time of the tiles made at the first pulse [s].
    making_s : float
        CPU time of the tiles made over the rest of the run [s].
    tiles_made : float
        Tiles made over the run [-].
    """

    nodes_per_pulse: int
    nodes_in_work: int
    held_facets: float
    first_s: float
    making_s: float
    tiles_made: float


def coverage_cost(scene, samples: int = 16, max_steps: int = 256) -> CoverageCost:
    """The nodes, held facets and tile-making time of a held radar-wide sea (eqs U1-U3
    of :mod:`seaecho.coverage`).

    A tile's unit echo is made at the first pulse of each block of held pulses
    (``[radar] sea_update_pulses``) whose beam's bound keeps it (eq C2). The beam of a
    block sweeps the azimuths between its first and its last pulse, so the tiles it
    makes are those it keeps at one pulse plus those whose azimuth interval the sweep
    crosses; the patchwork is a full annulus around the radar, so these are the share
    sweep / 2 pi of all its tiles (weighted by each tile's cost, t_u + t_n n): per block

        t_b = sum_(kept at a pulse) c_i + min(sweep_b / (2 pi), 1) sum_(all) c_i       (M2)

    with the kept tiles' mean over ``samples`` pulses spread over the run (the first
    pulse's alone at the first block, already counted in ``first_s``) and sweep_b the
    azimuth the transmitting antenna's boresight turns through over the block, summed
    over at most ``max_steps`` steps of the run. A fixed antenna makes the tiles it keeps
    once per block; a revolution of B blocks about B times the kept tiles plus all the
    tiles once.
    """
    from ..build import build_radar, coverage_layout, sea_spectrum
    from ..geometry.patchwork import BATCH_NODES, CACHE_BYTES, TILE_MARGIN_M
    from ..radar.coverage import two_way_bounds
    from ..radar.system import RadarSystem

    model = build_radar(scene)
    pw = coverage_layout(scene, model, sea_spectrum(scene))
    radar = RadarSystem(model)
    boxes = pw.boxes(TILE_MARGIN_M)
    nodes = np.array([np.prod(lv.shape) for lv in pw.levels])[pw.level]
    cost = T_UNIT_TILE + T_UNIT_NODE * nodes
    n_p, block = model.n_pulses, int(model.sea_update_pulses)
    counts, kept_cost, first = [], [], None
    for p in np.unique(np.linspace(0, n_p - 1, samples).astype(int)):
        keep = two_way_bounds(radar, int(p), boxes) >= model.sea_gain_floor
        counts.append(int(nodes[keep].sum()))
        kept_cost.append(float(cost[keep].sum()))
        if first is None:
            first = (float(cost[keep].sum()), int(keep.sum()))
    # the boresight's azimuth over the run, in at most max_steps steps
    steps = np.unique(np.linspace(0, n_p - 1, min(n_p, max_steps + 1)).astype(int))
    axis = np.array([radar.geometry(int(p)).tx_axes[:, 0] for p in steps])
    turn = np.abs(np.angle(np.exp(1j * np.diff(np.arctan2(axis[:, 1], axis[:, 0])))))
    sweep = np.zeros(-(-n_p // block))
    np.add.at(sweep, steps[1:] // block, turn)
    share = np.minimum(sweep / (2.0 * np.pi), 1.0)
    mean_kept = float(np.mean(kept_cost))
    making = (len(sweep) - 1) * mean_kept + float(share.sum()) * float(cost.sum())
    tiles = first[1] + (len(sweep) - 1) * mean_kept / max(first[0], 1e-300) * first[1] \
        + float(share.sum()) * len(nodes)
    most = max(counts)
    per_facet = M_UNIT_FACET + M_UNIT_FACET_CHANNEL * len(scene.radar.channels)
    return CoverageCost(int(np.mean(counts)), int(max(min(BATCH_NODES, most), nodes.max())),
                        min(2.0 * most, CACHE_BYTES / per_facet), first[0], making,
                        float(tiles))


# --------------------------------------------------------------------------- limits
def _read(path: str) -> str | None:
    try:
        return Path(path).read_text().strip()
    except OSError:
        return None


def available_memory() -> tuple[float | None, str]:
    """(bytes, source) this process may still use, from the system and its cgroup;
    (None, reason) where neither can be read."""
    found: list[tuple[float, str]] = []
    meminfo = _read("/proc/meminfo")
    if meminfo:
        for line in meminfo.splitlines():
            if line.startswith("MemAvailable:"):
                found.append((float(line.split()[1]) * 1024.0, "available memory"))
    limit, usage = _read("/sys/fs/cgroup/memory.max"), _read("/sys/fs/cgroup/memory.current")
    if limit is None:  # cgroup v1
        limit = _read("/sys/fs/cgroup/memory/memory.limit_in_bytes")
        usage = _read("/sys/fs/cgroup/memory/memory.usage_in_bytes")
    if limit and limit != "max" and limit.isdigit() and int(limit) < 2**60:
        free = float(limit) - float(usage or 0)
        found.append((max(free, 0.0), "the cgroup's memory limit"))
    if not found:
        return None, "available memory unknown on this system"
    return min(found)


def memory_limit(max_memory_gb: float | None = None) -> tuple[float | None, str]:
    """(bytes, source) a run may use: ``max_memory_gb`` [GB, 1e9 bytes], else
    ``SEAECHO_MAX_MEMORY_GB``, capped by :func:`available_memory`."""
    avail, source = available_memory()
    asked, asked_source = None, ""
    if max_memory_gb is not None:
        asked, asked_source = max_memory_gb * 1e9, "--max-memory-gb"
    elif os.environ.get(ENV_LIMIT):
        text = os.environ[ENV_LIMIT]
        try:
            asked = float(text) * 1e9
        except ValueError:
            raise SceneError(f"{ENV_LIMIT} = {text!r}: must be a number of GB") from None
        if not (asked > 0 and math.isfinite(asked)):
            raise SceneError(f"{ENV_LIMIT} = {text!r}: must be a positive number of GB")
        asked_source = ENV_LIMIT
    if asked is not None and (avail is None or asked <= avail):
        return asked, asked_source
    return avail, source


def format_bytes(n: float) -> str:
    if not math.isfinite(n):
        return "unbounded"
    if n >= 1000 * GiB:
        return f"{n / GiB:,.0f} GiB"
    return f"{n / GiB:.3g} GiB" if n >= 0.5 * GiB else f"{n / MiB:.3g} MiB"


def format_time(t: float) -> str:
    if not math.isfinite(t):
        return "unbounded"
    if t < 60:
        return f"~{t:.2g} s"
    if t < 3600:
        return f"~{t / 60:.2g} min"
    if t < 86400 * 2:
        return f"~{t / 3600:.2g} h"
    return f"~{t / 86400:.2g} days"


#: Terms of eq (M1) that a multistatic run holds once for all receivers (docs/multistatic.md).
_SHARED = ("process", "sea grid")


def multistatic_estimate(scene, figures: bool = True, **kw) -> Estimate:
    """:func:`estimate` of a scene with ``[[receivers]]``: each receiver's bistatic run
    (:func:`seaecho.build.receiver_scene`) estimated, the terms held once (the process,
    the sea grid) taken once and the others summed; the run time is the sum of the
    receivers' (an upper bound: the sea synthesis and the transmitter's trace, counted
    once per receiver there, are shared)."""
    from ..build import receiver_scene

    ests = [estimate(receiver_scene(scene, i), figures, **kw)
            for i in range(len(scene.receivers))]
    first = ests[0]
    terms = {k: (max(e.terms.get(k, 0.0) for e in ests) if k in _SHARED
                 else sum(e.terms.get(k, 0.0) for e in ests)) for k in first.terms}
    stages = sum(v for k, v in terms.items() if k != "antenna pattern")
    peak = SAFETY * max(stages, terms["process"] + terms.get("antenna pattern", 0.0))
    return dataclasses.replace(
        first, peak_bytes=peak, time_s=sum(e.time_s for e in ests), terms=terms,
        channels=sum(e.channels for e in ests), hull_rays=sum(e.hull_rays for e in ests),
        pixels=sum(e.pixels for e in ests))


def describe(est: Estimate, limit: float | None, source: str) -> str:
    """One line: estimated peak memory (against the limit) and run time."""
    text = f"estimated peak memory {format_bytes(est.peak_bytes)}"
    if limit is not None:
        text += f" (limit {format_bytes(limit)}, {source})"
    text += (f", run time {format_time(est.time_s)} ({est.n_pulses} pulses x {est.channels}"
             f" channels x {est.n_samples} samples")
    if est.cells:
        text += f", {est.cells} sea grid points"
    if est.hull_rays:
        text += f", {est.hull_rays:.3g} hull rays"
    if est.pixels:
        text += f", {est.pixels} image pixels"
    return text + ")"


def check_memory(scene, source: str, max_memory_gb: float | None = None,
                 figures: bool = True, **kw) -> tuple[Estimate, str]:
    """The estimate and its one-line description; :class:`SceneError` if it cannot fit.

    The message names the largest terms of eq (M1) and the fields that drive them.
    Keywords go to :func:`estimate` (``workers``, ``block``, ``base_dir``).
    """
    est = estimate(scene, figures=figures, **kw)
    limit, where = memory_limit(max_memory_gb)
    line = describe(est, limit, where)
    _refuse_over_limit(est, limit, f"{source}: the run does not fit in memory: {line}",
                       "Reduce them")
    return est, line


def _refuse_over_limit(est: Estimate, limit: float | None, what: str, advice: str) -> None:
    """:class:`SceneError` naming the largest terms and their fields if ``est`` is not
    finite or exceeds ``limit`` [B]; ``what`` opens the message, ``advice`` says what to
    change before the limit's own advice."""
    if math.isfinite(est.peak_bytes) and (limit is None or est.peak_bytes <= limit):
        return
    reasons = "; ".join(f"{name} {format_bytes(SAFETY * est.terms[name])} (set by "
                        f"{est.drivers[name]})" for name in est.largest_terms())
    raise SceneError(f"{what}. Largest terms: {reasons}. {advice}, or raise the limit with "
                     f"--max-memory-gb or {ENV_LIMIT} if more memory is free")


def worker_bytes(est: Estimate, threads: int = 1) -> float:
    """Peak memory of one Dask worker [bytes] running a scene of estimate ``est`` with
    ``threads`` threads: the process and, per thread, a simulation and a block of pulses
    (each thread builds and keeps its own, ``seaecho.distributed.worker_simulation``),
    or the start-up's antenna-pattern transient if larger; times :data:`SAFETY`."""
    process = est.terms.get("process", 0.0)
    own = sum(v for k, v in est.terms.items() if k not in _NOT_ON_A_WORKER)
    return SAFETY * max(process + max(threads, 1) * own,
                        process + est.terms.get("antenna pattern", 0.0))


#: Terms of eq (M1) that are this process's, not a worker's.
_NOT_ON_A_WORKER = ("process", "figures", "workers", "image", "antenna pattern")


def check_workers_memory(scene, workers: dict, source: str, *, block: int | None = None,
                         base_dir=".", fraction: float | None = None) -> Estimate:
    """Refuse a run whose per-worker part does not fit in a Dask worker's memory limit.

    Parameters
    ----------
    scene : seaecho.config.Scene
    workers : dict
        The scheduler's worker information (``Client.scheduler_info()["workers"]``):
        address -> {"memory_limit": bytes (0 or None: no limit), "nthreads": int, ...}.
    source : str
        What to start the message with (the scene file).
    block, base_dir
        As for :func:`estimate`.
    fraction : float, optional
        Share of a worker's limit the run may use: default Dask's pause threshold
        (``distributed.worker.memory.pause``, 0.8: a worker above it stops taking tasks,
        and the run would wait for ever), or its terminate threshold (0.95) if pausing
        is off.

    Returns
    -------
    Estimate
        The run's estimate (:func:`estimate` without figures).

    Raises
    ------
    SceneError
        Naming the workers whose limit is too small, the per-worker estimate, its
        largest terms and the fields that drive them.
    """
    if fraction is None:
        fraction = _dask_memory_fraction()
    est = estimate(scene, figures=False, block=block, base_dir=base_dir)
    short = []
    for address, info in sorted(workers.items()):
        limit = float(info.get("memory_limit") or 0.0)
        threads = int(info.get("nthreads") or 1)
        need = worker_bytes(est, threads)
        if limit > 0 and need > fraction * limit:
            short.append((address, limit, threads, need))
    if short:
        address, limit, threads, need = short[0]
        named = {k: v for k, v in est.terms.items() if k not in _NOT_ON_A_WORKER}
        top = sorted(((v, k) for k, v in named.items() if v > 0), reverse=True)[:2]
        reasons = "; ".join(f"{k} {format_bytes(SAFETY * threads * v)} (set by "
                            f"{est.drivers[k]})" for v, k in top)
        others = f" and {len(short) - 1} more" if len(short) > 1 else ""
        raise SceneError(
            f"{source}: the run does not fit in the Dask workers' memory: worker {address}"
            f"{others} (of {len(workers)}) has a memory limit of {format_bytes(limit)}, and "
            f"a worker may use {fraction:g} of it (Dask pauses a worker above that); each "
            f"of its {threads} threads holds a simulation and a block of pulses: estimated "
            f"{format_bytes(need)} per worker. Largest terms: {reasons}. Give the workers "
            "more memory (dask worker --memory-limit) or fewer threads, use "
            "--block-pulses, or reduce those fields")
    return est


def _dask_memory_fraction() -> float:
    """Dask's pause threshold of a worker's memory (else terminate, else 1)."""
    try:
        import dask

        import distributed  # noqa: F401 - loads the distributed.* defaults

        for key in ("pause", "terminate"):
            value = dask.config.get(f"distributed.worker.memory.{key}", False)
            if value:
                return float(value)
    except ImportError:  # pragma: no cover - dask is a dependency
        pass
    return 1.0


def focus_shape(raw, cfg) -> tuple[int, int]:
    """(ny, nx) pixels ``seaecho image`` makes of the raw dataset ``raw`` with ``cfg``:
    its extent (default the raw's sea tile or targets' box) over its pixel (default a
    quarter of the range resolution), as ``ImageGrid.from_extent`` counts them."""
    from ..imaging.focus import default_extent

    a = raw.attrs
    bandwidth = float(a.get("waveform_bandwidth_hz", a.get("sampling_rate_hz", 1.0)))
    pixel = cfg.pixel_m if cfg.pixel_m is not None else C0 / (8.0 * bandwidth)
    extent = cfg.extent_m if cfg.extent_m is not None else default_extent(raw, bandwidth)
    x0, x1, y0, y1 = (float(v) for v in extent)
    return pixel_count(y1 - y0, pixel), pixel_count(x1 - x0, pixel)


def image_estimate(raw, cfg, figures: bool = True) -> Estimate:
    """Peak memory and time of ``seaecho image`` focusing the raw dataset ``raw`` with
    ``cfg`` (an ``ImageConfig``): the process base, the raw's per-pulse arrays, its truth
    and the image term of eq (M1), from the dataset's sizes and attributes only.

    Parameters
    ----------
    raw : xarray.Dataset
        The raw dataset, opened lazily (nothing is read but its attributes and the
        coordinates the default extent needs).
    cfg : seaecho.config.image.ImageConfig
    figures : bool
        The command draws the image's figures (and ``cfg.figures``).
    """
    n_p = int(raw.sizes.get("pulse", 0))
    n_s = int(raw.sizes.get("fast_time", 0))
    c = int(raw.sizes.get("channel", 0))
    ny, nx = focus_shape(raw, cfg)
    pixels = ny * nx
    cells = int(raw.sizes.get("y_cell", 0)) * int(raw.sizes.get("x_cell", 0))
    panels = IMAGE_PANELS if cfg.figures and figures else 0
    terms = {"process": M0_TARGETS, "pulses": M_PULSE * n_p,
             "truth": M_TRUTH_CELL * cells,
             "image": image_term(pixels, c, n_p, n_s, cfg.upsample, panels)}
    drivers = {"process": "(fixed)", "pulses": "the raw dataset's pulses",
               "truth": "the raw dataset's sea grid",
               "image": "[image].pixel_m and extent_m (--pixel-m, --extent: the pixels), "
                        "the raw dataset's channels, [image].upsample, figures "
                        "(--no-figures)"}
    time_s = T_START["targets"] + T_BACKPROJECTION * pixels * n_p * c
    return Estimate(SAFETY * sum(terms.values()), time_s, terms, drivers, n_s, 0, n_p, c,
                    cells, pixels)


def check_image_memory(raw, cfg, source: str, max_memory_gb: float | None = None,
                       figures: bool = True) -> tuple[Estimate, str]:
    """:func:`image_estimate` and its one-line description; :class:`SceneError` naming
    the fields if the focusing cannot fit in the memory it may use (:func:`memory_limit`),
    as :func:`check_memory` does for a run."""
    from ..imaging.focus import MAX_PIXELS

    try:
        est = image_estimate(raw, cfg, figures)
    except ValueError as exc:  # no extent to default to
        raise SceneError(f"{source}: {exc}") from None
    if est.pixels > MAX_PIXELS:  # the focusing's own limit (ImageGrid.from_extent)
        raise SceneError(
            f"{source}: [image].pixel_m = {cfg.pixel_m!r}, extent_m = {cfg.extent_m!r}: "
            f"{est.pixels} pixels, more than {MAX_PIXELS}; use a larger pixel or a "
            "smaller extent (--pixel-m, --extent)")
    ny, nx = focus_shape(raw, cfg)
    if ny < 2 or nx < 2:  # as seaecho.checks.preflight.image_problems: the measures need 2 x 2
        raise SceneError(
            f"{source}: [image].pixel_m = {cfg.pixel_m!r}, extent_m = {cfg.extent_m!r}: "
            f"an image of {ny} x {nx} pixels; it needs at least 2 x 2 (a smaller pixel or "
            "a larger extent: --pixel-m, --extent)")
    limit, where = memory_limit(max_memory_gb)
    line = describe(est, limit, where)
    _refuse_over_limit(est, limit, f"{source}: the image does not fit in memory: "
                       f"[image].pixel_m = {cfg.pixel_m!r}, extent_m = {cfg.extent_m!r}: "
                       f"{line}", "Use larger pixels or a smaller extent")
    return est, line


__all__ = [
    "ENV_LIMIT",
    "SAFETY",
    "Estimate",
    "available_memory",
    "check_image_memory",
    "check_memory",
    "check_workers_memory",
    "describe",
    "estimate",
    "focus_shape",
    "antenna_nodes",
    "antenna_quadratures",
    "gauss_markov_steps",
    "hull_sizes",
    "image_estimate",
    "image_pixels",
    "image_term",
    "image_shape",
    "nominal_positions",
    "nominal_segments",
    "perturbation_bound",
    "pixel_count",
    "memory_limit",
    "window_size",
    "worker_bytes",
]
