"""Facets of a scene at any time: the entry point of the radar stage.

:class:`FacetEngine` joins the sea (:class:`seaecho.sea.Sea`), the platforms
(:mod:`seaecho.radar.platforms`), the ``[[objects]]`` and the ``[tracing]`` options; one
call, :meth:`FacetEngine.facets`, gives the :class:`~seaecho.geometry.facets.Facets` of a
time step in either mode.

Refresh interval
----------------
Ray tracing costs a BVH rebuild and two shadow rays per facet. With
``[tracing] refresh_interval_s = dt > 0`` the *occlusion* (whether the segment from a facet
to the transmitter / receiver is blocked) is computed on the surface, objects and platform
positions of ``t_ref = floor(t / dt) * dt`` and reused for every time in
``[t_ref, t_ref + dt)`` (the surface of t_ref is ``FacetEngine.surface_state(t_ref)``:
the sea at t_ref, or the surface a simulation holds at t_ref); the facing tests, normals,
ranges, angles and velocities are always those of time ``t``. ``t_ref`` depends on ``t``
only, so a pulse's facets do not depend on which pulses were computed before (pulses may
be computed in any order or in parallel, DESIGN.md). ``dt = 0`` traces every call. The
analytic mode is cheap and always evaluates at ``t``.
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Callable

import numpy as np

from ..geometry.facets import Facets, analytic_facets, subfacet_shadowing
from ..geometry.mesh import facet_geometry, grid_vertices, to_facets
from .kernels import facet_frames_drjit

__all__ = ["FacetEngine", "reference_time"]


def reference_time(t: float, interval: float) -> float:
    """Time whose occlusion serves time ``t``: ``floor(t / interval) * interval`` [s].

    A relative tolerance of 1e-9 absorbs rounding (t = 3 * 0.1 maps to 0.3, not 0.2).
    """
    if interval <= 0.0:
        return float(t)
    return math.floor(t / interval + 1e-9) * interval


class FacetEngine:
    """Facets of the sea of a scene, seen from its transmitter and receiver, at any time.

    Parameters
    ----------
    sea : seaecho.sea.Sea
        The sea (surface realisation + wake); ``sea.state(t)`` gives the surface.
    tx_position : callable
        ``t [s] -> (3,) array``: transmitter position [m].
    rx_position : callable, optional
        Receiver position; None for monostatic.
    mode : {"raytraced", "analytic"}
        Facet mode.
    shadowing : {"smith", "none"}
        Analytic mode's statistical shadowing.
    refresh_interval_s : float
        Occlusion refresh interval [s] (module docstring), raytraced mode.
    objects : list of seaecho.tracing.scene.ObjectGeometry
        Occluders (raytraced mode).
    variant : str, optional
        Mitsuba variant.
    eps_r : complex, optional
        Sea-water permittivity for the Sionna material [-].
    frequency_hz : float
        Carrier frequency [Hz].
    subfacet : (float, float, float), optional
        ``(mss_upwind, mss_crosswind, wind_direction [rad])`` of the unresolved slopes: if
        given, ``visibility`` is multiplied by their Smith shadowing (eq T7,
        :func:`seaecho.geometry.facets.subfacet_shadowing`), also stored in
        ``facets.extra["subfacet_shadowing"]``.
    """

    def __init__(self, sea, tx_position: Callable[[float], np.ndarray],
                 rx_position: Callable[[float], np.ndarray] | None = None, *,
                 mode: str = "raytraced", shadowing: str = "smith",
                 refresh_interval_s: float = 0.0, objects=(), variant: str | None = None,
                 eps_r: complex | None = None, frequency_hz: float = 10.0e9,
                 subfacet: tuple[float, float, float] | None = None) -> None:
        if mode not in ("raytraced", "analytic"):
            raise ValueError(f"mode = {mode!r}: allowed 'raytraced', 'analytic'")
        if refresh_interval_s < 0:
            raise ValueError(f"refresh_interval_s = {refresh_interval_s}: must be >= 0 [s]")
        self.sea = sea
        #: ``t [s] -> SurfaceState``: the surface at a time, ``sea.state`` by default; a
        #: simulation that holds its surface over blocks of pulses replaces it by its own
        #: map, so that the occlusion of ``t_ref`` is traced on the surface held at t_ref.
        self.surface_state = sea.state
        self.tx_position = tx_position
        self.rx_position = rx_position
        self.mode = mode
        self.shadowing = shadowing
        self.refresh_interval_s = float(refresh_interval_s)
        self.objects = list(objects)
        self._tracer = None
        self._cache: tuple[float, np.ndarray, np.ndarray] | None = None
        self._geometry: tuple | None = None  # (state, (centroid, area, normal, velocity))
        self._variant = variant
        self.eps_r = eps_r
        self.frequency_hz = frequency_hz
        self.subfacet = subfacet

    # ------------------------------------------------------------------ construction
    @classmethod
    def from_scene(cls, scene, *, base_dir: str | os.PathLike = ".", sea=None,
                   mode: str | None = None, variant: str | None = None,
                   tx_position: np.ndarray | None = None,
                   rx_position: np.ndarray | None = None) -> FacetEngine:
        """Engine of a validated scene.

        Parameters
        ----------
        scene : seaecho.config.Scene
            Needs ``[transmitter]`` (``[receiver]`` optional: monostatic).
        base_dir : path
            Folder of the scene file (``[[objects]]`` paths are relative to it).
        sea : seaecho.sea.Sea, optional
            An existing sea of this scene (else ``Sea.from_scene(scene)``).
        mode, variant : str, optional
            Override ``[tracing] mode`` / ``variant``.
        tx_position, rx_position : (3,) arrays, optional
            Fixed positions [m] that replace the scene's ``[transmitter]`` /
            ``[receiver]`` platforms (rx None with tx given: monostatic).
        """
        from ..radar.platforms import platforms_from_scene
        from ..sea import Sea

        if tx_position is not None:
            p_tx = np.asarray(tx_position, dtype=np.float64).reshape(3)
            p_rx = None if rx_position is None else np.asarray(rx_position,
                                                                dtype=np.float64).reshape(3)
            tx_fn = lambda t: p_tx  # noqa: E731
            rx_fn = None if p_rx is None else (lambda t: p_rx)
        else:
            if scene.transmitter is None:
                raise ValueError("the scene has no [transmitter]: facets need a transmitter")
            tx, rx = platforms_from_scene(scene)
            tx_fn = lambda t: tx.state(t).position  # noqa: E731
            rx_fn = None if scene.receiver is None else (lambda t: rx.state(t).position)
        cfg = scene.tracing
        mode = cfg.mode if mode is None else mode
        objects = []
        if mode == "raytraced":
            from .scene import load_object

            for o in scene.objects:
                objects += load_object(o, base_dir=str(base_dir), ship=scene.ship)
        freq = scene.radar.carrier_frequency_hz if scene.radar is not None else 10.0e9
        from ..ocean.seawater import sea_water_permittivity

        eps_r = complex(sea_water_permittivity(freq, scene.sea.temperature_c,
                                               scene.sea.salinity_psu))
        sea = Sea.from_scene(scene) if sea is None else sea
        subfacet = None
        if cfg.subfacet_shadowing:
            from ..constants import C0
            from ..ocean.twoscale import unresolved_statistics

            dx, dy = float(sea.x[1] - sea.x[0]), float(sea.y[1] - sea.y[0])
            stats = unresolved_statistics(sea.spectrum, dx, dy, 2.0 * np.pi * freq / C0 / 3.0)
            if stats.mss_upwind > 0 and stats.mss_crosswind > 0:
                subfacet = (stats.mss_upwind, stats.mss_crosswind,
                            float(np.deg2rad(scene.sea.wind_direction_deg)))
        return cls(sea, tx_fn, rx_fn, subfacet=subfacet,
                   mode=mode, shadowing=cfg.shadowing,
                   refresh_interval_s=cfg.refresh_interval_s, objects=objects,
                   variant=cfg.variant if variant is None else variant, eps_r=eps_r,
                   frequency_hz=freq)

    # --------------------------------------------------------------------- facets
    def positions(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """(tx, rx) positions at time ``t`` [m] (rx = tx when monostatic)."""
        tx = np.asarray(self.tx_position(t), dtype=np.float64).reshape(3)
        rx = tx if self.rx_position is None else np.asarray(self.rx_position(t),
                                                              dtype=np.float64).reshape(3)
        return tx, rx

    @property
    def tracer(self):
        """The :class:`~seaecho.tracing.tracer.FacetTracer` (built on first use)."""
        return self._get_tracer(None)

    def _get_tracer(self, st):
        if self._tracer is None:
            from .tracer import FacetTracer

            st = self.sea.state(0.0) if st is None else st
            self._tracer = FacetTracer(st.x, st.y, st.elevation, objects=self.objects,
                                       eps_r=self.eps_r, frequency_hz=self.frequency_hz,
                                       variant=self._variant)
        return self._tracer

    def geometry(self, state) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Centroids [m], areas [m^2], unit normals [-] and velocities [m/s] of the facets of
        a sea state (:func:`seaecho.geometry.mesh.facet_geometry`, ``to_facets``).

        Memoised on the state object: a surface held over several pulses (the same
        :class:`~seaecho.sea.SurfaceState`) is meshed once. The arrays are read-only, as
        they are shared by the facets of those pulses.
        """
        if self._geometry is None or self._geometry[0] is not state:
            centroid, area, normal = facet_geometry(grid_vertices(state.x, state.y,
                                                                  state.elevation))
            velocity = to_facets(np.asarray(state.velocity, dtype=np.float64))
            arrays = (centroid, area, normal, velocity)
            for a in arrays:
                a.setflags(write=False)
            self._geometry = (state, arrays)
        return self._geometry[1]

    def facets(self, t: float, state=None) -> Facets:
        """Facets at time ``t`` [s] in the engine's mode.

        Parameters
        ----------
        t : float
            Time [s] (surface, objects, platforms).
        state : seaecho.sea.SurfaceState, optional
            ``sea.state(t)`` if already computed.
        """
        f = self._facets(t, state)
        if self.subfacet is None:
            return f
        s = subfacet_shadowing(f, *self.subfacet)
        return dataclasses.replace(f, visibility=f.visibility * s,
                                   extra={**f.extra, "subfacet_shadowing": s})

    def _facets(self, t: float, state=None) -> Facets:
        """Facets at time ``t`` [s] in the engine's mode, without sub-facet shadowing.

        Parameters
        ----------
        t : float
            Time [s] (surface, objects, platforms).
        state : seaecho.sea.SurfaceState, optional
            ``sea.state(t)`` if already computed.
        """
        st = self.sea.state(t) if state is None else state
        tx, rx = self.positions(t)
        if self.mode == "analytic":
            return analytic_facets(st.x, st.y, st.elevation, st.slope_x, st.slope_y,
                                   st.velocity, tx, rx, shadowing=self.shadowing, time_s=t,
                                   frames=facet_frames_drjit)
        tracer = self._get_tracer(st)
        if self.refresh_interval_s == 0.0:
            return tracer.facets(st.elevation, st.velocity, tx, rx, t=t,
                                 geometry=self.geometry(st))
        t_ref = reference_time(t, self.refresh_interval_s)
        if self._cache is None or self._cache[0] != t_ref:
            st_ref = st if t_ref == t else self.surface_state(t_ref)
            tx_ref, rx_ref = self.positions(t_ref)
            tracer.set_surface(st_ref.elevation)
            tracer.set_time(t_ref)
            if st_ref is st:  # the usual held surface: meshed once
                c_ref, _, n_ref, _ = self.geometry(st)
            else:
                c_ref, _, n_ref = facet_geometry(grid_vertices(st_ref.x, st_ref.y,
                                                               st_ref.elevation))
            occ_tx = tracer.occluded(c_ref, n_ref, tx_ref)
            occ_rx = occ_tx if np.array_equal(tx_ref, rx_ref) else tracer.occluded(
                c_ref, n_ref, rx_ref)
            self._cache = (t_ref, occ_tx, occ_rx)
        _, occ_tx, occ_rx = self._cache
        centroid, area, normal, velocity = self.geometry(st)
        geo = facet_frames_drjit(centroid, normal, tx, rx)
        lit = (geo["theta_i"] < np.pi / 2) & ~occ_tx
        seen = (geo["theta_s"] < np.pi / 2) & ~occ_rx
        return Facets(mode="raytraced", time_s=float(t), visibility_time_s=float(t_ref),
                      grid_shape=(st.y.size - 1, st.x.size - 1, 2), centroid=centroid,
                      area=area, normal=normal, velocity=velocity,
                      lit=lit.astype(np.float64), seen=seen.astype(np.float64),
                      visibility=(lit & seen).astype(np.float64), **geo)
