"""The radar-wide sea at each pulse: the tiles the beam reaches, each in its own frame.

``[sea] coverage = "radar"`` lays a patchwork of tiles around a fixed monostatic radar
out to its window's end (:mod:`seaecho.geometry.patchwork`, eqs T1-T5; built by
:func:`seaecho.build.build_coverage`). At pulse p, :class:`CoverageSea`:

1. bounds the two-way gain over the boxes of the tiles whose azimuths meet the arcs of
   eq U3 below (:func:`seaecho.radar.coverage.two_way_bounds`, eqs C1-C2; the arcs hold
   every tile the bound keeps) and keeps the tiles whose bound reaches ``[radar]
   sea_gain_floor_db``: the beam's main lobe and the sidelobes above the floor;
2. computes a kept tile's facets with the single tile's whole pipeline
   (:meth:`seaecho.simulation.Simulation.sea_echo`: facets, ray-traced occlusion by the
   waves of the tile, two-scale facet model, speckle, radar equation), in the tile's own
   flat frame (eq T5): the radar's states and antenna axes are carried into that frame
   (:class:`TilePlatform`), so delays, gains and angles are those of the tile on the
   Earth (its drop and local vertical); the tile's own sea (its seed, ``"sea-tile"``
   stream) with the ships' wakes where its grid lies;
3. weights each facet by whether its tile owns it (eq T4: no facet counted twice),
   whether a static occluder hides it (eq T6 below), on a spherical Earth whether its
   centroid is above the radar's horizon (the straight ray of
   :meth:`~seaecho.geometry.earth.SphericalEarth.visible`: the horizon cuts tiles facet
   by facet), and whether the beams' bound in its own direction reaches the floor
   (:func:`point_bounds`, eq C1);
4. accumulates the tiles' echoes into the pulse's samples
   (:meth:`seaecho.radar.system.RadarSystem.receive` is linear in its echoes).

**A held sea (eqs U1-U3).** For a fixed radar and a sea held over a block of pulses
(``[radar] sea_update_pulses``, ``[scattering] sea_motion = "held"``) whose occluders
stand still, nothing of a facet's echo changes from pulse to pulse within the block but
the antennas' gains: the facets, their occlusion, the speckle draws of the block, the
delays, the port states (on FSA bases about the platform's vertical, not the scanning
antenna's axes) and the two-ray factors are the block's. Eq R1 is linear in
sqrt(G_t G_r), so a tile's pipeline runs once per block, at the block's first pulse, with
isotropic unit-gain antennas of the same ports (:func:`unit_gain_antenna`):

    a_f^(1) = a_f(G_t = G_r = 1)                                                     (U1)

per facet f the tile owns and sees (step 3 without the beam's bound), held with its
delay and the direction n_f from the transmitter to its bounce point in the simulation
frame (:class:`UnitEcho`); each pulse p of the block then takes

    a_f(p) = a_f^(1) sqrt(G_t(n_f; A_p) G_r(n_f; A_p))    where the bound of eq C1
             at n_f reaches the floor, 0 elsewhere                                    (U2)

(:func:`beam_gains`: eq A1 with the pulse's antenna axes A_p, in the radar equation's
working precision) and sums the kept tiles' facets in one receive. The facets of a tile
are held in the order of their azimuth, and a pulse reads only the azimuths where
|n . y_a| < u_max can hold, u_max the direction cosine beyond which the antenna's width
envelope is below the floor (one antenna transmitting and receiving on the same axes:
its square):

    |n . y_a| < u_max  =>  |cos(phi - phi_y)| < (u_max + s |y_z|) / (c rho_y)         (U3)

with n = (c cos phi, c sin phi, n_z), y_a = (rho_y cos phi_y, rho_y sin phi_y, y_z), s
the largest |n_z| and c the smallest horizontal norm of the tile's facets: two arcs of
azimuth around phi_y +- 90 deg (:meth:`UnitEcho.sector`), a superset of the facets eq U2
keeps. Against the tile pipeline at every pulse (the evolving sea's path, below), the
same physics: in float64 working precision the two agree to the accumulation's NUFFT
tolerance, in the default float32 to the rounding of the gains' direction cosines,
taken in the radar's frame instead of each tile's (tests). An evolving sea (its facets
move and their speckle evolves at every pulse) or a moving occluder takes steps 2-4 at
every pulse, each kept tile's simulation held between pulses.

**Occluders (T6).** The static occluders (``[[land]]``, ``[[objects]]``) are one
Mitsuba scene of the simulation frame, where the scene places them (the land on the
Earth, eq E4): each facet's segment to the antennas, from its centroid carried out of
the tile's frame (eq T5), is traced against it (:meth:`CoverageSea._hidden`), the tile's
own tracer holding only its waves (and moving objects, in the tile's frame).

Making the tiles of a held sea. The tiles a pulse needs and does not hold are made
together, in batches of at most :data:`BATCH_NODES` grid nodes of one level
(:meth:`CoverageSea.unit_echoes`): each tile's pipeline up to its facet model
(:meth:`seaecho.simulation.Simulation.sea_stage`), the facet model of the batch's facets
in one Dr.Jit kernel (:func:`batched_amplitudes`: eqs P1-P7 are per facet, so each tile
gets the numbers of its own evaluation), then each tile's radar equation. The tiles of a
level share one tracer, moved onto each tile's grid
(:meth:`seaecho.tracing.engine.FacetEngine.reuse_tracer`: the same occlusion as a new
one), and the platforms' states of a pulse (:class:`HeldStates`). The bytes are those of
a tile at a time (tests).

Memory. A held sea keeps the unit-gain echoes of the tiles the beam's bound keeps, at
most :data:`CACHE_BYTES` in all; an evolving sea keeps the simulations of at most
:data:`CACHE_NODES` grid nodes. A tile the beam leaves is dropped, one beyond the budget
is computed and dropped at once, and one batch of tiles (:data:`BATCH_NODES` nodes, or
one larger tile) goes through the pipeline at a time: a pulse's memory is the budget
plus that batch, whatever the window's range (the time grows with the tiles the beam
crosses). Which tiles are held
changes nothing: a tile's unit echo is a pure function of (scene, tile, block), its echo
at a pulse of (scene, tile, pulse), so pulses stay computable in any order and a Dask
run writes the serial bytes.

Truncation. A skipped tile's or facet's echo power is at most g_f times its power at
both beams' peaks (eq C3), so the skipped sea of a pulse is at most

    P_skipped(p) <= g_f sum_(skipped facets f) |a_f|^2 (unit gains)                  (C4)

over the facets of the skipped tiles and those left out of the kept ones.

Neglected: shadowing of a tile's facets by the waves of the tiles in front of it (each
tile is traced alone: the waves shadow along the beam within a tile); the tile's own
curvature (eq T5); moving ``[[objects]]`` are placed in each tile's frame without the
tile's tilt (an error of its angle rho / (k a) about the scene's origin).
"""

from __future__ import annotations

import dataclasses
import time
from collections import OrderedDict
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .geometry.patchwork import BATCH_NODES, CACHE_BYTES, CACHE_NODES, TILE_MARGIN_M


def _model_key(model) -> tuple:
    """A facet model's fields, its arrays and tables by identity (a level's sea model
    makes a new :class:`~seaecho.scattering.facet.FacetModel` of the same ones each
    time)."""
    return tuple(v if isinstance(v, (bool, int, float, complex, str, type(None))) else id(v)
                 for v in (getattr(model, f.name) for f in dataclasses.fields(model)))


def batched_amplitudes(stages) -> list[NDArray[np.complex128]]:
    """:func:`seaecho.scattering.facet.speckled_facet_amplitudes` of each
    :class:`seaecho.simulation.SeaStage` of ``stages`` (N_s, 4) [m], those of one facet
    model, back end and set of inputs (damping, breaking zones, mechanisms) in one
    evaluation of their facets put end to end.

    Eqs P1-P7 are per facet (each facet's directions, area, draws, damping and breaking
    fraction), so the facets of several tiles through one kernel get the numbers each
    tile's own evaluation gives (test). Only the Dr.Jit back end is batched (a
    :class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable` spectrum; its kernel
    recomputes the facets' local frames, ``local`` is not read); numpy and the evolving
    speckle (its draws a callable) take one evaluation per stage.
    """
    from .scattering.facet import speckled_facet_amplitudes
    from .scattering.spectrum_table import BraggSpectrumTable

    out: list = [None] * len(stages)
    groups: dict[tuple, list[int]] = {}
    for j, st in enumerate(stages):
        kw, model = st.kwargs, st.args[4]
        draws = kw["draws"]
        if (callable(draws) or not isinstance(draws, dict)
                or not isinstance(model.spectrum, BraggSpectrumTable)):
            out[j] = speckled_facet_amplitudes(*st.args, **kw)
            continue
        key = (_model_key(model), kw["variant"], kw["precision"],
               kw["wake_damping"] is None, kw["breaking_fraction"] is None,
               tuple(sorted(draws)))
        groups.setdefault(key, []).append(j)
    for js in groups.values():
        first = stages[js[0]]
        cat = [np.concatenate([np.asarray(stages[j].args[a]).reshape(
            -1, *np.shape(first.args[a])[1:]) for j in js]) for a in range(4)]
        kw = dict(first.kwargs, local=None, draws={
            m: np.concatenate([stages[j].kwargs["draws"][m] for j in js])
            for m in first.kwargs["draws"]})
        for name in ("wake_damping", "breaking_fraction"):
            if first.kwargs[name] is not None:
                kw[name] = np.concatenate([np.asarray(stages[j].kwargs[name], dtype=float)
                                           for j in js])
        amp = speckled_facet_amplitudes(*cat, first.args[4], **kw)
        ends = np.cumsum([len(stages[j].args[3]) for j in js])
        for j, a in zip(js, np.split(amp, ends[:-1]), strict=True):
            out[j] = a
    return out


class TilePlatform:
    """A platform seen from a tile's frame (eq T5 of :mod:`seaecho.geometry.patchwork`):
    its states' positions, velocities and body-to-world rotations carried into the
    tile's frame; everything else is the platform's."""

    def __init__(self, platform, frame) -> None:
        self._platform = platform
        self.frame = frame

    def _carry(self, st):
        f = self.frame
        return dataclasses.replace(st, position=f.to_tile(st.position),
                                   velocity=f.vector_to_tile(st.velocity),
                                   rotation=f.matrix_to_tile(st.rotation))

    def state(self, t):
        """The platform's true state at ``t`` in the tile's frame."""
        return self._carry(self._platform.state(t))

    def nominal_state(self, t):
        """The platform's nominal state at ``t`` in the tile's frame."""
        return self._carry(self._platform.nominal_state(t))

    def __getattr__(self, name):
        return getattr(self._platform, name)


class HeldStates:
    """A platform whose states at the last few scalar times are kept: the tiles of a
    pulse carry the same state into their frames (:class:`TilePlatform`), computed once
    (the same arrays, read only by the carrying)."""

    KEEP = 8

    def __init__(self, platform) -> None:
        self._platform = platform
        self._held: OrderedDict = OrderedDict()

    def _get(self, kind: str, t):
        if np.ndim(t) != 0:
            return getattr(self._platform, kind)(t)
        key = (kind, float(t))
        st = self._held.get(key)
        if st is None:
            st = getattr(self._platform, kind)(t)
            self._held[key] = st
            if len(self._held) > self.KEEP:
                self._held.popitem(last=False)
        return st

    def state(self, t):
        """The platform's true state at ``t`` [s]."""
        return self._get("state", t)

    def nominal_state(self, t):
        """The platform's nominal state at ``t`` [s]."""
        return self._get("nominal_state", t)

    def __getattr__(self, name):
        return getattr(self._platform, name)


def tile_radar(radar_model, frame, seed: int, unit_gain: bool = False):
    """The radar model seen from a tile's frame: its platforms carried by
    :class:`TilePlatform`, a look-at point moved into the frame, the tile's seed, no
    targets, noise or sea skip (the patchwork selects the tiles). ``unit_gain``: both
    antennas isotropic (G = 1 in every direction) with the same ports, basis and
    isolation (:func:`unit_gain_antenna`): the echoes of eq U1."""
    if unit_gain:
        radar_model = dataclasses.replace(
            radar_model, tx_antenna=unit_gain_antenna(radar_model.tx_antenna),
            rx_antenna=unit_gain_antenna(radar_model.rx_antenna))
    tx = TilePlatform(radar_model.tx, frame)
    rx = tx if radar_model.rx is radar_model.tx else TilePlatform(radar_model.rx, frame)

    def pointing(p):
        if p.look_at is None:
            return p
        return dataclasses.replace(p, look_at=frame.to_tile(p.look_at))

    return dataclasses.replace(
        radar_model, tx=tx, rx=rx, tx_pointing=pointing(radar_model.tx_pointing),
        rx_pointing=pointing(radar_model.rx_pointing), targets=None, thermal_noise=False,
        seed=int(seed), sea_gain_floor=None, earth=None)


def point_bounds(radar, geo, frame, points) -> NDArray[np.float64]:
    """The two-way bound of eq C1-C2 in the direction of each point (N, 3) of a tile's
    frame at the pulse of ``geo`` (the tile's geometry) [-]: the width envelope's at the
    point's direction cosine, the obliquity bounded by 1."""
    from .radar.coverage import width_envelope

    out = np.ones(len(points))
    for ant, pos, axes in ((radar.tx_antenna, geo.tx.position, geo.tx_axes),
                           (radar.rx_antenna, geo.rx.position, geo.rx_axes)):
        if ant.pattern != "rectangular":
            continue
        d = points - pos
        u = d @ axes[:, 1] / np.linalg.norm(d, axis=-1)
        out *= width_envelope(ant, ant.width * u / ant.wavelength) ** 2
    return out


def unit_gain_antenna(antenna):
    """``antenna`` with an isotropic pattern (G = 1 everywhere) and the same ports
    (basis, cross-polar isolation): eq R1 with it is the unit-gain echo of eq U1."""
    return dataclasses.replace(antenna, pattern="isotropic", width=None, height=None)


def incidence_directions(geo, positions, velocities) -> NDArray[np.float64]:
    """Unit vectors n_i from the transmitter to the bounce points of scatterers at
    ``positions`` moving at ``velocities`` (K, 3) [-]: those whose gain eq R1 takes
    (:func:`seaecho.radar.equation.flight`, eq R3, as :func:`seaecho.radar.kernels.
    echo_terms` evaluates it), in the frame of ``geo`` (a pulse's geometry)."""
    from .backend import NUMPY, Boundary
    from .constants import C0
    from .radar.equation import flight

    io = Boundary(NUMPY, len(positions))
    p_tx = NUMPY.vconst(geo.tx.position)
    tau_t, _, p_b = flight(NUMPY, p_tx, io.vec3(positions), io.vec3(velocities),
                           NUMPY.vconst(geo.rx.position), NUMPY.vconst(geo.rx.velocity))
    n = (p_b - p_tx) * (1.0 / (C0 * tau_t))
    return np.stack(np.broadcast_arrays(n.x, n.y, n.z), axis=-1)


def beam_gains(radar, geo, direction: NDArray[np.float64], floor: float,
               variant: str | None = None, precision: str | None = None
               ) -> NDArray[np.float64]:
    """sqrt(G_t G_r) of a pulse's antennas towards unit directions (K, 3) of the
    simulation frame, 0 where the beams' bound of eq C1 is below ``floor`` (eq U2) [-].

    Eq A1 (:func:`seaecho.radar.kernels.antenna_gain`, the radar equation's own gain) in
    ``precision`` (default the sea's working precision,
    :data:`seaecho.scattering.facet.PRECISION`, as the tile pipeline's radar equation
    takes it) on the Dr.Jit back end of ``variant``.

    Parameters
    ----------
    radar : seaecho.radar.system.RadarSystem
    geo : seaecho.radar.system.PulseGeometry
        The pulse's antenna axes.
    direction : ndarray (K, 3)
        n_i, from the transmitter; the receiver takes -n_s = n_i (a fixed monostatic
        radar) [-].
    floor : float
        g_f [-].
    """
    from .backend import Boundary, drjit_namespace
    from .radar.coverage import width_envelope
    from .radar.kernels import antenna_gain
    from .scattering.facet import PRECISION

    precision = PRECISION if precision is None else precision
    tx, rx = radar.tx_antenna, radar.rx_antenna
    bound = np.ones(len(direction))
    for ant, axes in ((tx, geo.tx_axes), (rx, geo.rx_axes)):
        if ant.pattern == "rectangular":  # eq C1 in each facet's direction
            u = direction @ axes[:, 1]
            bound *= width_envelope(ant, ant.width * u / ant.wavelength) ** 2
    out = np.zeros(len(direction))
    idx = np.flatnonzero(bound >= floor)
    if idx.size == 0:
        return out
    xp = drjit_namespace(variant)
    xs = xp if precision == "double" else xp.with_precision(precision)
    io = Boundary(xp, idx.size)
    d = xs.cast(io.vec3(direction[idx]))
    g_t = xp.cast(antenna_gain(xp, tx, d, geo.tx_axes, xs))
    same = rx is tx and np.array_equal(geo.rx_axes, geo.tx_axes)
    g_r = g_t if same else xp.cast(antenna_gain(xp, rx, d, geo.rx_axes, xs))
    (out[idx],) = io.numpy(xp.sqrt(g_t * g_r))
    return out


@dataclasses.dataclass(frozen=True)
class UnitEcho:
    """A tile's facets for one held block at unit antenna gains (eq U1).

    Attributes
    ----------
    block : int
        The block of held pulses ([radar] sea_update_pulses) it serves.
    tau : ndarray (K,)
        Delays [s] of the facets whose echo can reach the window.
    amplitudes : ndarray (C, K) complex
        Eq R1 at G_t = G_r = 1 [sqrt(W)]: everything of the pulse but the antennas'
        gains (occlusion, facet model, speckle, two-ray factor, range loss, carrier).
    direction : ndarray (K, 3)
        Unit vector from the transmitter to each facet's bounce point in the simulation
        frame [-] (:func:`incidence_directions`): where the gains of eq U2 are taken.
    """

    block: int
    tau: NDArray[np.float64]
    amplitudes: NDArray[np.complex128]
    direction: NDArray[np.float64]

    @classmethod
    def sorted(cls, block: int, tau, amplitudes, direction) -> UnitEcho:
        """The echo with its facets in the order of their azimuth atan2(n_y, n_x) in
        [-pi, pi] (:meth:`sector` slices it)."""
        order = np.argsort(np.arctan2(direction[:, 1], direction[:, 0]), kind="stable")
        return cls(int(block), np.ascontiguousarray(tau[order]),
                   np.ascontiguousarray(amplitudes[:, order]),
                   np.ascontiguousarray(direction[order]))

    @property
    def nbytes(self) -> int:
        """Memory held [bytes]."""
        return int(self.tau.nbytes + self.amplitudes.nbytes + self.direction.nbytes
                   + self.azimuth.nbytes)

    @property
    def azimuth(self) -> NDArray[np.float64]:
        """atan2(n_y, n_x) of the facets, nondecreasing [rad] (computed once)."""
        az = self.__dict__.get("_azimuth")
        if az is None:
            az = np.arctan2(self.direction[:, 1], self.direction[:, 0])
            object.__setattr__(self, "_azimuth", az)
        return az

    def sector(self, width_axis: NDArray[np.float64], u_max: float) -> NDArray[np.int64]:
        """Indices of the facets that may have |n . y| < ``u_max`` for the unit vector
        ``width_axis`` y [-]: a superset, contiguous in azimuth (the module docstring's
        eq U3), every facet when the bound does not narrow them."""
        n = len(self.tau)
        if n == 0 or u_max >= 1.0:
            return np.arange(n)
        # |n . y| = |c_h rho cos(phi - phi_y) + n_z y_z|, c_h = sqrt(1 - n_z^2)
        nz = np.abs(self.direction[:, 2])
        s_max = float(nz.max())
        c_min = float(np.sqrt(max(1.0 - s_max * s_max, 0.0)))
        rho = float(np.hypot(width_axis[0], width_axis[1]))
        if c_min * rho <= 0.0:
            return np.arange(n)
        q = (u_max + s_max * abs(float(width_axis[2]))) / (c_min * rho) + 1e-9
        if q >= 1.0:
            return np.arange(n)
        delta = float(np.arcsin(q))
        phi_y = float(np.arctan2(width_axis[1], width_axis[0]))
        az = self.azimuth
        parts = []
        for centre in (phi_y + 0.5 * np.pi, phi_y - 0.5 * np.pi):
            a = (centre - delta + np.pi) % (2.0 * np.pi) - np.pi
            b = (centre + delta + np.pi) % (2.0 * np.pi) - np.pi
            if a <= b:
                parts.append((np.searchsorted(az, a), np.searchsorted(az, b, "right")))
            else:  # across -pi / pi
                parts += [(0, np.searchsorted(az, b, "right")), (np.searchsorted(az, a), n)]
        merged: list[list[int]] = []  # at most three ranges, merged where they overlap
        for i, j in sorted((int(i), int(j)) for i, j in parts if j > i):
            if merged and i <= merged[-1][1]:
                merged[-1][1] = max(merged[-1][1], j)
            else:
                merged.append([i, j])
        if not merged:
            return np.zeros(0, dtype=np.int64)
        return np.concatenate([np.arange(i, j) for i, j in merged])


class CoverageSea:
    """The sea echo of a radar-wide sea, pulse by pulse (module docstring).

    Parameters
    ----------
    models : seaecho.build.SimulationModels
        The scene's models, with ``coverage`` (:class:`seaecho.build.CoverageModel`).
    radar : seaecho.radar.system.RadarSystem
        The scene's radar (its window, transmit phase and tile selection).
    factory : callable
        ``factory(models, facet_weight)`` -> a simulation of one tile's models
        (:meth:`seaecho.simulation.Simulation.from_models`).
    cache_nodes : int
        Grid nodes of the tiles held between pulses (the evolving sea's path).
    cache_bytes : int
        Memory of the unit-gain echoes held between pulses (the held sea's path) [bytes].
    """

    def __init__(self, models, radar, factory: Callable, cache_nodes: int = CACHE_NODES,
                 cache_bytes: int = CACHE_BYTES) -> None:
        self.models = models
        self.model = models.coverage
        self.patchwork = self.model.patchwork
        self.radar = radar
        self.floor = models.radar.sea_gain_floor
        self.block = int(models.radar.sea_update_pulses)
        self._factory = factory
        self.cache_nodes = int(cache_nodes)
        self.cache_bytes = int(cache_bytes)
        #: grid nodes of the tiles of one level made together (:meth:`unit_echoes`)
        self.batch_nodes = BATCH_NODES
        self._nodes = np.array([np.prod(lv.shape) for lv in self.patchwork.levels]
                               )[self.patchwork.level]
        self._boxes = self.patchwork.boxes(TILE_MARGIN_M)
        self._tiles: OrderedDict[int, object] = OrderedDict()
        self._units: OrderedDict[int, UnitEcho] = OrderedDict()
        self._arcs: tuple | None = None  # the boxes' azimuths (_candidates)
        #: eqs U1-U2 (a tile's facets once per block, the gains per pulse): a held sea
        #: whose occluders all stand still; an evolving sea takes the tile pipeline at
        #: every pulse (its facets move and their speckle evolves)
        self.cached = (models.sea_model.dynamics is None and not any(
            getattr(o, "moving", False) for _, tr in self.model.levels for o in tr.objects))
        # tiles reaching beyond 0.99 of the horizon to the sea level (eq E2): only their
        # facets are tested against the Earth
        self._beyond = np.zeros(len(self.patchwork), dtype=bool)
        earth = models.radar.earth
        if earth is not None:
            from .geometry.earth import horizon_range

            h = float(models.radar.tx.nominal_state(models.radar.start_time).position[2])
            o = np.asarray(self.patchwork.centre)
            spans = np.array([self.patchwork.span(i) for i in range(len(self))])
            far = np.hypot(np.maximum(abs(spans[:, 0] - o[0]), abs(spans[:, 1] - o[0])),
                           np.maximum(abs(spans[:, 2] - o[1]), abs(spans[:, 3] - o[1])))
            self._beyond = far + TILE_MARGIN_M >= 0.99 * float(horizon_range(
                max(h, 0.0), 0.0, earth.radius))
        # The static occluders ([[land]], [[objects]]) in one scene of the simulation
        # frame, traced from every tile's facets (eq T6), instead of a scene per tile
        tracing = self.model.levels[0][1]
        self._static = tuple(o for o in tracing.objects if not getattr(o, "moving", False))
        self._occluders = None
        # what the tiles share: the platforms' states of a pulse (HeldStates) and, for
        # the held sea's unit echoes, one tracer per level moved from tile to tile
        tx = HeldStates(models.radar.tx)
        rx = tx if models.radar.rx is models.radar.tx else HeldStates(models.radar.rx)
        self._held_radar = dataclasses.replace(models.radar, tx=tx, rx=rx)
        self._tracers: dict[int, object] = {}
        #: tiles computed so far (new simulations made), for the benchmarks [-]
        self.tiles_made = 0
        #: facets whose echo the last pulse summed (eq U2, the held sea's path) [-]
        self.facets_echoed = 0
        #: CPU time spent making tiles' unit-gain echoes (eq U1), for the benchmarks [s]
        self.making_cpu_s = 0.0

    def __len__(self) -> int:
        return len(self.patchwork)

    def gain_bounds(self, pulse: int) -> NDArray[np.float64]:
        """Two-way gain bound over each tile's box at ``pulse`` (eq C2), (T,) [-]."""
        from .radar.coverage import two_way_bounds

        return two_way_bounds(self.radar, pulse, self._boxes)

    def selected(self, pulse: int) -> NDArray[np.int64]:
        """Tiles computed at ``pulse``: bound at or above the floor, in the patchwork's
        order [-]. The bound is evaluated on the tiles whose azimuths meet the arcs of
        eq U3 (:meth:`_candidates`, a superset of those it keeps): the same tiles."""
        from .radar.coverage import two_way_bounds

        cand = self._candidates(pulse)
        return cand[two_way_bounds(self.radar, pulse, self._boxes[cand]) >= self.floor]

    def _candidates(self, pulse: int) -> NDArray[np.int64]:
        """The tiles whose boxes' directions from the (fixed) antenna may have
        |n . y_a| < u_max (eq U3 with each box's azimuth interval and its largest
        |n_z|), for each antenna; every tile where the arcs do not narrow [-]."""
        if self._arcs is None:  # each box's azimuth interval and elevation bound, once
            o = self.radar.geometry(0).tx.position
            d = self._boxes - o
            az = np.arctan2(d[..., 1], d[..., 0])
            centre = np.arctan2(d[..., 1].mean(axis=1), d[..., 0].mean(axis=1))
            rel = (az - centre[:, None] + np.pi) % (2.0 * np.pi) - np.pi
            lo, hi = rel.min(axis=1), rel.max(axis=1)
            mid, half = centre + 0.5 * (lo + hi), 0.5 * (hi - lo)
            # the plan distance to the corners' rectangle bounds the box's from below
            gx = np.maximum(np.maximum(d[..., 0].min(axis=1), -d[..., 0].max(axis=1)), 0.0)
            gy = np.maximum(np.maximum(d[..., 1].min(axis=1), -d[..., 1].max(axis=1)), 0.0)
            g = np.hypot(gx, gy)
            dz = np.abs(d[..., 2]).max(axis=1)
            s_max = dz / np.maximum(np.hypot(g, dz), 1e-300)
            wide = (g == 0.0) | (half >= 0.5 * np.pi)  # around the antenna: always
            self._arcs = (mid, half, s_max, np.sqrt(np.maximum(1.0 - s_max ** 2, 0.0)),
                          wide)
        mid, half, s_max, c_min, wide = self._arcs
        geo = self.radar.geometry(pulse)
        same = (self.radar.rx_antenna == self.radar.tx_antenna
                and np.array_equal(geo.rx_axes, geo.tx_axes))
        keep = np.ones(len(mid), dtype=bool)
        for y, u_max in zip((geo.tx_axes[:, 1], geo.rx_axes[:, 1]), self._u_max(same),
                            strict=True):
            if u_max >= 1.0:
                continue
            rho = float(np.hypot(y[0], y[1]))
            with np.errstate(divide="ignore"):
                q = (u_max + s_max * abs(float(y[2]))) / (c_min * rho) + 1e-9
            delta = np.arcsin(np.minimum(q, 1.0))
            phi_y = float(np.arctan2(y[1], y[0]))
            near = q >= 1.0
            for centre in (phi_y + 0.5 * np.pi, phi_y - 0.5 * np.pi):
                gap = np.abs((mid - centre + np.pi) % (2.0 * np.pi) - np.pi)
                near |= gap <= half + delta + 1e-9
            keep &= near | wide
            if same:
                break
        return np.flatnonzero(keep)

    def _tile_models(self, i: int, unit_gain: bool = False):
        """The models of tile ``i``'s simulation: the radar in the tile's frame (unit
        gains for eq U1), the tile's sea, its level's sea model and tracing, no hulls,
        land echoes or patchwork (the scene's simulation has them)."""
        pw = self.patchwork
        sea_model, tracing = self.model.levels[int(pw.level[i])]
        if self._static:  # traced in the simulation frame (eq T6, _weight)
            tracing = dataclasses.replace(tracing, objects=tuple(
                o for o in tracing.objects if getattr(o, "moving", False)))
        radar = tile_radar(self._held_radar, pw.frame(i), pw.seed(i, self.model.seed),
                           unit_gain=unit_gain)
        return dataclasses.replace(self.models, radar=radar, sea=self.model.sea(i),
                                   sea_model=sea_model, tracing=tracing, hulls=None,
                                   land=None, coverage=None)

    def _weight(self, i: int, beam: bool) -> Callable:
        """Tile ``i``'s facet weight: ownership (eq T4), the horizon (eq E2, the tiles
        near it) and, with ``beam``, the beams' bound in each facet's direction (eq C1:
        the tile pipeline of every pulse; eq U2 applies it per pulse instead)."""
        pw = self.patchwork
        frame = pw.frame(i)
        owned = np.repeat(pw.cell_owned(i).reshape(-1), 2).astype(np.float64)
        earth = self.models.radar.earth if self._beyond[i] else None
        floor, radar = self.floor, self.radar
        cell = min(pw.levels[int(pw.level[i])].spacing)

        def facet_weight(sim, state, geo) -> NDArray[np.float64]:
            c, _, normal, _ = sim.engine.geometry(state)
            # eq C1 at each facet (the beams' bound in its direction): below the floor,
            # its echo is left out as the tiles' (eq C4)
            w = owned * (point_bounds(radar, geo, frame, c) >= floor) if beam else owned
            if self._static:  # eq T6: the static occluders, in the simulation frame
                on = np.flatnonzero(w > 0)
                cw, nw = frame.to_world(c[on]), normal[on] @ frame.rotation.T
                hidden = np.zeros(on.size, dtype=bool)
                for pos in {tuple(geo.tx.position), tuple(geo.rx.position)}:
                    hidden |= self._hidden(cw, nw, frame.to_world(np.array(pos)), cell,
                                           sim.engine.tracer.variant)
                w = w.copy()
                w[on[hidden]] = 0.0
            if earth is None:
                return w
            # eq T5: the facets and the antennas in the simulation frame; the straight
            # ray from each antenna to the facet, or to the sea level under a trough,
            # must clear the sphere (the tile's plane is the sphere at its centre)
            c = frame.to_world(np.concatenate([c[:, :2], np.maximum(c[:, 2:], 0.0)], axis=1))
            seen = (earth.visible(frame.to_world(geo.tx.position), c)
                    & earth.visible(frame.to_world(geo.rx.position), c))
            return w * seen

        return facet_weight

    def _hidden(self, points, normals, position, cell_m: float, variant: str
                ) -> NDArray[np.bool_]:
        """Whether the segments from facets (centroids ``points``, unit ``normals``, (N, 3)
        of the simulation frame) to ``position`` hit a static occluder (eq T6), starting
        off the facet along its normal as the tile's tracer's rays do
        (:meth:`seaecho.tracing.tracer.FacetTracer.occluded`, ``cell_m`` the grid's
        spacing [m]) [-]."""
        from .backend import Boundary, drjit_namespace
        from .tracing.scene import ObjectScene, shadow_test

        if len(points) == 0:
            return np.zeros(0, dtype=bool)
        if self._occluders is None:
            self._occluders = ObjectScene(list(self._static), variant=variant)
        xp = drjit_namespace(variant)
        eps = max(1e-3 * cell_m, 8.0 * np.finfo(np.float32).eps
                  * float(np.max(np.abs(points))))
        io = Boundary(xp, len(points))
        origin = io.vec3(points) + io.vec3(normals) * xp.const(eps)
        d = xp.vconst(position) - origin
        r = xp.sqrt(xp.dot(d, d))
        d = d / r
        blocked = xp.Bool(shadow_test([self._occluders.mi_scene], origin, d,
                                      r * (1.0 - 1e-6), variant=variant))
        return np.asarray(xp.host(blocked), dtype=bool).copy()

    def tile(self, i: int):
        """The simulation of tile ``i`` (held, or made): the tile pipeline of every
        pulse (module docstring, step 2)."""
        i = int(i)
        if i in self._tiles:
            self._tiles.move_to_end(i)
            return self._tiles[i]
        sim = self._factory(self._tile_models(i), self._weight(i, beam=True))
        self.tiles_made += 1
        held = sum(int(self._nodes[k]) for k in self._tiles)
        if held + int(self._nodes[i]) <= self.cache_nodes:  # else used once and dropped
            self._tiles[i] = sim
        return sim

    def unit_echo(self, i: int, block: int) -> UnitEcho:
        """Tile ``i``'s facets at unit gains for ``block`` (eq U1; held, or made at the
        block's first pulse: a pure function of (scene, tile, block))."""
        i, block = int(i), int(block)
        held = self._units.get(i)
        if held is not None and held.block == block:
            self._units.move_to_end(i)
            return held
        return self.unit_echoes([i], block)[0]

    def unit_echoes(self, tiles, block: int) -> list[UnitEcho]:
        """:meth:`unit_echo` of each of ``tiles`` for ``block``: those not held are made
        in batches of at most :data:`BATCH_NODES` grid nodes of one level, whose facet
        model runs as one kernel (:func:`batched_amplitudes`: the same numbers as a
        tile at a time)."""
        block = int(block)
        out: dict[int, UnitEcho] = {}
        todo: dict[int, list[int]] = {}
        for i in map(int, tiles):
            held = self._units.get(i)
            if held is not None and held.block == block:
                self._units.move_to_end(i)
                out[i] = held
            else:
                todo.setdefault(int(self.patchwork.level[i]), []).append(i)
        for level, group in sorted(todo.items()):
            per = max(1, self.batch_nodes // int(self._nodes[group[0]]))
            for k in range(0, len(group), per):
                out.update(self._make_units(group[k:k + per], level, block))
        return [out[int(i)] for i in tiles]

    def _make_units(self, tiles: list[int], level: int, block: int) -> dict[int, UnitEcho]:
        """The unit echoes (eq U1) of ``tiles`` (of one ``level``) for ``block``: each
        tile's pipeline up to the facet model (:meth:`seaecho.simulation.Simulation.
        sea_stage`), the facet model of them all at once, then each tile's radar
        equation; held within :attr:`cache_bytes`."""
        start = time.process_time()
        first = block * self.block
        made = []
        for i in tiles:
            self._units.pop(i, None)
            sim = self._factory(self._tile_models(i, unit_gain=True),
                                self._weight(i, beam=False))
            self.tiles_made += 1
            self._share_tracer(sim, level, first)
            geo = sim.radar.geometry(first)
            made.append((i, sim, geo, sim.sea_stage(first, geo)))
        staged = [stage for *_, stage in made if not hasattr(stage, "echo")]
        amps = iter(batched_amplitudes(staged))
        out = {}
        for i, sim, geo, stage in made:
            sea = stage if hasattr(stage, "echo") else sim.sea_finish(stage, next(amps))
            echo, facets = sea.echo, sea.facets
            if echo.tau.size != facets.visibility.size:  # the culled facets, one echo each
                raise RuntimeError("unit_echo: the tile's echoes and facets do not match")
            keep = self.radar.window.keep(echo.tau, self.radar.waveform.n_samples)
            n = incidence_directions(geo, facets.centroid[keep], facets.velocity[keep])
            unit = UnitEcho.sorted(block, echo.tau[keep],
                                   np.asarray(echo.amplitudes)[:, keep],
                                   n @ self.patchwork.frame(i).rotation.T)
            held = sum(u.nbytes for u in self._units.values())
            if held + unit.nbytes <= self.cache_bytes:  # else used once and dropped
                self._units[i] = unit
            out[i] = unit
        self._release()
        self.making_cpu_s += time.process_time() - start
        return out

    def _share_tracer(self, sim, level: int, pulse: int) -> None:
        """Give the tile simulation ``sim`` (a unit echo's, made at ``pulse``) the tracer
        of its level, moved onto its grid, or keep the one it builds as the level's: one
        Mitsuba scene per level instead of one per tile, the same occlusion
        (:meth:`seaecho.tracing.engine.FacetEngine.reuse_tracer`). The tiles' tracers
        hold only the sea (the static occluders are traced in the simulation frame)."""
        engine = getattr(sim, "engine", None)
        if engine is None or engine.mode != "raytraced" or engine.objects:
            return
        state = sim.surface_state(pulse)
        held = self._tracers.get(level)
        if held is None:
            self._tracers[level] = engine._get_tracer(state)
        else:
            engine.reuse_tracer(held, state)

    def gains(self, pulse: int, direction: NDArray[np.float64], geo=None
              ) -> NDArray[np.float64]:
        """:func:`beam_gains` of ``pulse`` (its geometry ``geo`` if already made) [-]."""
        geo = self.radar.geometry(pulse) if geo is None else geo
        return beam_gains(self.radar, geo, direction, self.floor, self.models.variant)

    def _u_max(self, same: bool = False) -> tuple[float, float]:
        """(tx, rx): the |u| = |n . y| beyond which an antenna's envelope factor of eq C1
        is below the floor, so the beams' bound is too (1 where it never is) [-];
        ``same``: one antenna on the same axes transmits and receives, its factor
        squared is the bound (below sqrt(g_f) then)."""
        from .radar.coverage import ENVELOPE_STEPS, width_envelope

        floor = np.sqrt(self.floor) if same else self.floor
        out = []
        for ant in (self.radar.tx_antenna, self.radar.rx_antenna):
            if ant.pattern != "rectangular":
                out.append(1.0)
                continue
            t_max = ant.width / ant.wavelength
            t = np.arange(int(np.ceil(t_max * ENVELOPE_STEPS)) + 2) / ENVELOPE_STEPS
            below = np.flatnonzero(width_envelope(ant, t) ** 2 < floor)
            # the envelope is constant on each step and nonincreasing: |t| >= t[below[0]]
            out.append(1.0 if below.size == 0 else
                       min(float(t[below[0]]) / t_max, 1.0))
        return out[0], out[1]

    def raw(self, pulse: int) -> NDArray[np.complex128] | None:
        """The sea's samples of ``pulse``, (channels, samples) [sqrt(W)], the transmit
        phase included and no noise; None when no tile reaches the floor."""
        keep = self.selected(pulse)
        kept = set(keep.tolist())
        for held in (self._tiles, self._units):  # the tiles the beam left
            for i in list(held):
                if i not in kept:
                    del held[i]
        if self.cached:
            out = self._raw_cached(pulse, keep)
            self._release()
            return out
        out = None
        for i in keep:  # a tile at a time: its facets are vectorised
            echo = self.tile(i).sea_echo(pulse).echo
            r = self.radar.receive(pulse, [echo], noise=False)
            out = r if out is None else out + r
        return out

    def _release(self) -> None:
        """Return Dr.Jit's cache of freed buffers to the system after a batch of tiles
        and after a pulse: the tiles and the pulse's sectors leave buffers of ever new
        sizes, which the cache would otherwise keep for the rest of the run."""
        from .backend import drjit_namespace

        try:
            xp = drjit_namespace(self.models.variant)
        except (ImportError, ValueError):  # no Dr.Jit: nothing held
            return
        xp.dr.flush_malloc_cache()

    def _raw_cached(self, pulse: int, keep: NDArray[np.int64]
                    ) -> NDArray[np.complex128] | None:
        """Eq U2: the kept tiles' unit-gain facets of the pulse's block times the
        pulse's gains, summed in one receive (eq E2 is linear in the echoes)."""
        from .radar.system import ScattererEcho

        if keep.size == 0:
            return None
        block = pulse // self.block
        geo = self.radar.geometry(pulse)
        same = (self.radar.rx_antenna == self.radar.tx_antenna
                and np.array_equal(geo.rx_axes, geo.tx_axes))
        u_max = self._u_max(same)
        parts = []
        # each tile's facets in the beam's sector (eq U3); the tiles not held are made
        # together (unit_echoes)
        for u in self.unit_echoes(keep, block):
            idx = u.sector(geo.tx_axes[:, 1], u_max[0])
            if u_max[1] < u_max[0]:  # the receiver's narrower sector
                idx = np.intersect1d(idx, u.sector(geo.rx_axes[:, 1], u_max[1]))
            if idx.size:
                parts.append((u, idx))
        self.facets_echoed = 0
        if not parts:
            return self.radar.receive(pulse, [], noise=False)
        direction = np.concatenate([u.direction[idx] for u, idx in parts])
        w = self.gains(pulse, direction, geo)
        on = np.flatnonzero(w > 0.0)
        self.facets_echoed = int(on.size)
        tau = np.concatenate([u.tau[idx] for u, idx in parts])[on]
        amp = np.concatenate([u.amplitudes[:, idx] for u, idx in parts], axis=1)[:, on] * w[on]
        echo = ScattererEcho(tau, amp, None, None, None, None, None, None)
        return self.radar.receive(pulse, [echo], noise=False)

    def facet_count(self, pulse: int) -> int:
        """Facets computed at ``pulse`` (all facets of the selected tiles) [-]."""
        levels = self.patchwork.levels
        n = [levels[int(j)].shape for j in self.patchwork.level[self.selected(pulse)]]
        return int(sum(2 * (ny - 1) * (nx - 1) for ny, nx in n))


__all__ = ["BATCH_NODES", "CACHE_BYTES", "CACHE_NODES", "TILE_MARGIN_M", "CoverageSea",
           "HeldStates", "TilePlatform", "UnitEcho", "batched_amplitudes", "beam_gains",
           "incidence_directions", "point_bounds", "tile_radar", "unit_gain_antenna"]
