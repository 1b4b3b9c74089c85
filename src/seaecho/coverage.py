"""The radar-wide sea at each pulse: the tiles the beam reaches, each in its own frame.

``[sea] coverage = "radar"`` lays a patchwork of tiles around a fixed monostatic radar
out to its window's end (:mod:`seaecho.geometry.patchwork`, eqs T1-T5; built by
:func:`seaecho.build.build_coverage`). At pulse p, :class:`CoverageSea`:

1. bounds the two-way gain over every tile's box at once
   (:func:`seaecho.radar.coverage.two_way_bounds`, eqs C1-C2) and keeps the tiles whose
   bound reaches ``[radar] sea_gain_floor_db``: the beam's main lobe and the sidelobes
   above the floor;
2. computes each kept tile's echo with the single tile's whole pipeline
   (:meth:`seaecho.simulation.Simulation.sea_echo`: facets, ray-traced occlusion by the
   waves of the tile, two-scale facet model, speckle, radar equation), in the tile's own
   flat frame (eq T5): the radar's states and antenna axes are carried into that frame
   (:class:`TilePlatform`), so delays, gains and angles are those of the tile on the
   Earth (its drop and local vertical); the tile's own sea (its seed, ``"sea-tile"``
   stream) with the ships' wakes where its grid lies;
3. weights each facet by whether its tile owns it (eq T4: no facet counted twice),
   whether the beams' bound in its own direction reaches the floor (:func:`point_bounds`)
   and, on a spherical Earth, whether its centroid is above the radar's horizon (the
   straight ray of :meth:`~seaecho.geometry.earth.SphericalEarth.visible`): the horizon
   cuts tiles facet by facet (a held sea sends only the weighted facets through the
   facet model, the same numbers);
4. accumulates each tile's echo into the pulse's samples before the next tile
   (:meth:`seaecho.radar.system.RadarSystem.receive` is linear in its echoes), in the
   tiles' fixed order.

Memory. Tiles of at most :data:`CACHE_NODES` grid nodes in all are held between pulses
(their surface, its per-block speckle draws and traced occlusion: the tiles of the beam,
reused by the next pulses while the beam crosses them); a tile the beam leaves is
dropped, and a tile that would exceed the budget is computed and dropped at once. One
tile's facets are worked on at a time, so a pulse's memory is at most the budget plus
one tile of ``nx x ny`` nodes, whatever the window's range (the time grows with the
tiles the beam crosses). Which tiles are held changes nothing: each tile's echo is a pure function
of (scene, tile, pulse) (its held surface and speckle are those of the pulse's block), so
pulses stay computable in any order and a Dask run writes the serial bytes.

Truncation. A skipped tile's or facet's echo power is at most g_f times its power at
both beams' peaks (eq C3), so the skipped sea of a pulse is at most

    P_skipped(p) <= g_f sum_(skipped facets f) |a_f|^2 (unit gains)                  (C4)

over the facets of the skipped tiles and those left out of the kept ones.

Neglected: shadowing of a tile's facets by the waves of the tiles in front of it (each
tile is traced alone: the waves shadow along the beam within a tile); the tile's own
curvature (eq T5); ``[[objects]]`` occluders are placed in each tile's frame without the
tile's tilt (an error of its angle rho / (k a) about the scene's origin).
"""

from __future__ import annotations

import dataclasses
from collections import OrderedDict
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .geometry.patchwork import CACHE_NODES, TILE_MARGIN_M


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


def tile_radar(radar_model, frame, seed: int):
    """The radar model seen from a tile's frame: its platforms carried by
    :class:`TilePlatform`, a look-at point moved into the frame, the tile's seed, no
    targets, noise or sea skip (the patchwork selects the tiles)."""
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
        Grid nodes of the tiles held between pulses.
    """

    def __init__(self, models, radar, factory: Callable, cache_nodes: int = CACHE_NODES
                 ) -> None:
        self.models = models
        self.model = models.coverage
        self.patchwork = self.model.patchwork
        self.radar = radar
        self.floor = models.radar.sea_gain_floor
        self._factory = factory
        self.cache_nodes = int(cache_nodes)
        self._nodes = np.array([np.prod(lv.shape) for lv in self.patchwork.levels]
                               )[self.patchwork.level]
        self._boxes = self.patchwork.boxes(TILE_MARGIN_M)
        self._tiles: OrderedDict[int, object] = OrderedDict()
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
        #: tiles computed so far (new simulations made), for the benchmarks [-]
        self.tiles_made = 0

    def __len__(self) -> int:
        return len(self.patchwork)

    def gain_bounds(self, pulse: int) -> NDArray[np.float64]:
        """Two-way gain bound over each tile's box at ``pulse`` (eq C2), (T,) [-]."""
        from .radar.coverage import two_way_bounds

        return two_way_bounds(self.radar, pulse, self._boxes)

    def selected(self, pulse: int) -> NDArray[np.int64]:
        """Tiles computed at ``pulse``: bound at or above the floor, in the patchwork's
        order [-]."""
        return np.flatnonzero(self.gain_bounds(pulse) >= self.floor)

    def tile(self, i: int):
        """The simulation of tile ``i`` (held, or made)."""
        i = int(i)
        if i in self._tiles:
            self._tiles.move_to_end(i)
            return self._tiles[i]
        pw = self.patchwork
        sea_model, tracing = self.model.levels[int(pw.level[i])]
        frame = pw.frame(i)
        models = dataclasses.replace(
            self.models, radar=tile_radar(self.models.radar, frame, pw.seed(i, self.model.seed)),
            sea=self.model.sea(i), sea_model=sea_model, tracing=tracing, hulls=None,
            coverage=None)
        owned = np.repeat(pw.cell_owned(i).reshape(-1), 2).astype(np.float64)
        earth = self.models.radar.earth if self._beyond[i] else None
        floor, radar = self.floor, self.radar

        def facet_weight(sim, state, geo) -> NDArray[np.float64]:
            c = sim.engine.geometry(state)[0]
            # eq C1 at each facet (the beams' bound in its direction): below the floor,
            # its echo is left out as the tiles' (eq C4)
            w = owned * (point_bounds(radar, geo, frame, c) >= floor)
            if earth is None:
                return w
            # eq T5: the facets and the antennas in the simulation frame; the straight
            # ray from each antenna to the facet, or to the sea level under a trough,
            # must clear the sphere (the tile's plane is the sphere at its centre)
            c = frame.to_world(np.concatenate([c[:, :2], np.maximum(c[:, 2:], 0.0)], axis=1))
            seen = (earth.visible(frame.to_world(geo.tx.position), c)
                    & earth.visible(frame.to_world(geo.rx.position), c))
            return w * seen

        sim = self._factory(models, facet_weight)
        self.tiles_made += 1
        held = sum(int(self._nodes[k]) for k in self._tiles)
        if held + int(self._nodes[i]) <= self.cache_nodes:  # else used once and dropped
            self._tiles[i] = sim
        return sim

    def raw(self, pulse: int) -> NDArray[np.complex128] | None:
        """The sea's samples of ``pulse``, (channels, samples) [sqrt(W)], the transmit
        phase included and no noise; None when no tile reaches the floor."""
        keep = self.selected(pulse)
        kept = set(keep.tolist())
        for i in list(self._tiles):  # the tiles the beam left
            if i not in kept:
                del self._tiles[i]
        out = None
        for i in keep:  # a tile at a time: its facets are vectorised
            echo = self.tile(i).sea_echo(pulse).echo
            r = self.radar.receive(pulse, [echo], noise=False)
            out = r if out is None else out + r
        return out

    def facet_count(self, pulse: int) -> int:
        """Facets computed at ``pulse`` (all facets of the selected tiles) [-]."""
        levels = self.patchwork.levels
        n = [levels[int(j)].shape for j in self.patchwork.level[self.selected(pulse)]]
        return int(sum(2 * (ny - 1) * (nx - 1) for ny, nx in n))


__all__ = ["CACHE_NODES", "TILE_MARGIN_M", "CoverageSea", "TilePlatform", "point_bounds",
           "tile_radar"]
