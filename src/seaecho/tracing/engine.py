"""Facets of a sea at any time, seen from a transmitter and a receiver, in either mode.

:class:`FacetEngine` joins a surface provider (``t -> SurfaceState``, e.g.
:meth:`seaecho.sea.Sea.state`), the transmitter and receiver positions (``t -> (3,)``),
the occluding objects and the facet options (:class:`~seaecho.tracing.model.TracingModel`);
one call, :meth:`FacetEngine.facets`, gives the
:class:`~seaecho.geometry.facets.Facets` of a time step in either mode.
:func:`seaecho.build.build_engine` makes the engine of a scene.

Refresh interval
----------------
Ray tracing costs a BVH rebuild and two shadow rays per facet. With
``[tracing] refresh_interval_s = dt > 0`` the *occlusion* (whether the segment from a facet
to the transmitter / receiver is blocked) is computed on the surface, objects and platform
positions of ``t_ref = floor(t / dt) * dt`` and reused for every time in
``[t_ref, t_ref + dt)`` (the surface of t_ref is the provider's ``surface(t_ref)``:
the sea at t_ref, or the surface a simulation holds at t_ref); the facing tests, normals,
ranges, angles and velocities are always those of time ``t``. ``t_ref`` depends on ``t``
only, so a pulse's facets do not depend on which pulses were computed before (pulses may
be computed in any order or in parallel, docs/conventions.md). ``dt = 0`` traces every call. The
analytic mode is cheap and always evaluates at ``t``.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from functools import partial

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
    """Facets of a sea, seen from a transmitter and a receiver, at any time.

    Parameters
    ----------
    surface : callable
        ``t [s] -> SurfaceState`` (:class:`seaecho.sea.SurfaceState` or any object with
        ``x, y, elevation, slope_x, slope_y, velocity``): the surface at a time. A
        simulation that holds its surface over blocks of pulses passes its own map, so
        that the occlusion of a refresh time is traced on the surface held then.
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
    objects : sequence of seaecho.tracing.scene.ObjectGeometry
        Occluders (raytraced mode).
    variant : str, optional
        Mitsuba variant.
    eps_r : complex, optional
        Sea-water permittivity [-], kept by the sea scene
        (:class:`seaecho.tracing.scene.SeaScene`); the shadow rays do not use it.
    frequency_hz : float, optional
        Carrier frequency [Hz]; None leaves the sea scene's nominal one.
    subfacet : (float, float, float), optional
        ``(mss_upwind, mss_crosswind, wind_direction [rad])`` of the unresolved slopes: if
        given, ``visibility`` is multiplied by their Smith shadowing (eq T7,
        :func:`seaecho.geometry.facets.subfacet_shadowing`), also stored in
        ``facets.extra["subfacet_shadowing"]``.
    """

    def __init__(self, surface: Callable[[float], object],
                 tx_position: Callable[[float], np.ndarray],
                 rx_position: Callable[[float], np.ndarray] | None = None, *,
                 mode: str = "raytraced", shadowing: str = "smith",
                 refresh_interval_s: float = 0.0, objects=(), variant: str | None = None,
                 eps_r: complex | None = None, frequency_hz: float | None = None,
                 subfacet: tuple[float, float, float] | None = None,
                 periodic_apron: bool = False) -> None:
        if not callable(surface):
            raise TypeError("surface must be a callable t -> SurfaceState (e.g. sea.state)")
        if mode not in ("raytraced", "analytic"):
            raise ValueError(f"mode = {mode!r}: allowed 'raytraced', 'analytic'")
        if shadowing not in ("smith", "none"):
            raise ValueError(f"shadowing = {shadowing!r}: allowed 'smith', 'none'")
        if refresh_interval_s < 0:
            raise ValueError(f"refresh_interval_s = {refresh_interval_s}: must be >= 0 [s]")
        if subfacet is not None and not (subfacet[0] > 0 and subfacet[1] > 0):
            raise ValueError(f"subfacet = {subfacet}: slope variances must be > 0")
        #: ``t [s] -> SurfaceState``: the surface at a time
        self.surface = surface
        self.tx_position = tx_position
        self.rx_position = rx_position
        self.mode = mode
        self.shadowing = shadowing
        self.refresh_interval_s = float(refresh_interval_s)
        self.objects = list(objects)
        self._tracer = None
        self._cache: tuple[float, object, object] | None = None
        self._geometry: tuple | None = None  # (state, (centroid, area, normal, velocity))
        self._variant = variant
        self.eps_r = eps_r
        self.frequency_hz = frequency_hz
        self.subfacet = subfacet
        self.periodic_apron = bool(periodic_apron)
        self._lead: FacetEngine | None = None

    def share_transmitter(self, lead: FacetEngine) -> None:
        """Take the tracer (the sea's BVH), the facet geometry and the transmitter's
        occlusion from ``lead``, an engine of the same surface provider, transmitter,
        objects and refresh interval with another receiver (several receivers of one
        transmitter, docs/multistatic.md): :meth:`occlusion` then traces only this
        engine's receiver. The masks are those ``lead`` traces, so the facets are the same
        as this engine's alone.
        """
        if lead is self or lead.refresh_interval_s != self.refresh_interval_s:
            raise ValueError("share_transmitter needs another engine of the same refresh "
                             "interval")
        self._lead = lead

    @classmethod
    def from_model(cls, model, surface: Callable[[float], object],
                   tx_position: Callable[[float], np.ndarray],
                   rx_position: Callable[[float], np.ndarray] | None = None) -> FacetEngine:
        """Engine of a :class:`~seaecho.tracing.model.TracingModel`.

        Parameters
        ----------
        model : TracingModel
            Mode, shadowing, refresh, variant, objects, material, sub-facet slopes.
        surface, tx_position, rx_position : callable
            As for the constructor.
        """
        return cls(surface, tx_position, rx_position, mode=model.mode,
                   shadowing=model.shadowing, refresh_interval_s=model.refresh_interval_s,
                   objects=model.objects, variant=model.variant, eps_r=model.eps_r,
                   frequency_hz=model.frequency, subfacet=model.subfacet,
                   periodic_apron=model.periodic_apron)

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

    def _period(self, st) -> tuple[float, float] | None:
        """The periods of the tracer's periodic apron for the grid of ``st`` [m]: an FFT
        tile of n nodes, n * spacing; None without the apron."""
        if not self.periodic_apron:
            return None
        return (st.x.size * float(st.x[1] - st.x[0]), st.y.size * float(st.y[1] - st.y[0]))

    def _get_tracer(self, st):
        if self._lead is not None:
            return self._lead._get_tracer(st)
        if self._tracer is None:
            from .tracer import FacetTracer

            st = self.surface(0.0) if st is None else st
            material = {} if self.frequency_hz is None else {"frequency_hz": self.frequency_hz}
            self._tracer = FacetTracer(st.x, st.y, st.elevation, objects=self.objects,
                                       eps_r=self.eps_r, variant=self._variant,
                                       period_m=self._period(st), **material)
        return self._tracer

    def reuse_tracer(self, tracer, state) -> None:
        """Take ``tracer`` as this engine's, moved onto the grid of ``state`` (a surface
        state of this engine's surface): the tracer of another engine of the same grid
        shape, objects, variant and material (the tiles of one level of a radar-wide
        sea, :mod:`seaecho.coverage`), which that engine must no longer use. The same
        occlusion as the tracer this engine would build (the sea scene's vertices are
        those of ``state``; :meth:`seaecho.tracing.tracer.FacetTracer.move`)."""
        if self._lead is not None or self._tracer is not None:
            raise ValueError("reuse_tracer: this engine already has its tracer")
        tracer.move(state.x, state.y, state.elevation, period_m=self._period(state))
        self._tracer = tracer

    def geometry(self, state) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Centroids [m], areas [m^2], unit normals [-] and velocities [m/s] of the facets of
        a sea state (:func:`seaecho.geometry.mesh.facet_geometry`, ``to_facets``).

        Memoised on the state object: a surface held over several pulses (the same
        :class:`~seaecho.sea.SurfaceState`) is meshed once. The arrays are read-only, as
        they are shared by the facets of those pulses (and by the engines that share
        this one's transmitter, :meth:`share_transmitter`).
        """
        if self._lead is not None:
            return self._lead.geometry(state)
        held = self._geometry[0] if self._geometry is not None else None
        if held is None or not (held is state or (held.elevation is state.elevation
                                                  and held.velocity is state.velocity)):
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
            ``surface(t)`` if already computed.
        """
        f = self._facets(t, state)
        if self.subfacet is None:
            return f
        s = subfacet_shadowing(f, *self.subfacet)
        return dataclasses.replace(f, visibility=f.visibility * s,
                                   extra={**f.extra, "subfacet_shadowing": s})

    def occlusion(self, t: float, state=None) -> tuple[float, object, object]:
        """Occlusion serving time ``t`` [s] (raytraced mode): ``(t_ref, hidden_tx,
        hidden_rx)``, whether each facet's segment to the transmitter / receiver is blocked,
        traced on the surface, objects and platforms of ``t_ref`` (module docstring) for
        every facet, memoised until ``t_ref`` changes. The masks are the tracer's device
        arrays (:meth:`~seaecho.tracing.tracer.FacetTracer.occluded` with ``device``):
        ``tracer.to_numpy`` reads them back.
        """
        st = self.surface(t) if state is None else state
        tracer = self._get_tracer(st)
        t_ref = reference_time(t, self.refresh_interval_s)
        if self._cache is None or self._cache[0] != t_ref:
            st_ref = st if t_ref == t else self.surface(t_ref)
            tx_ref, rx_ref = self.positions(t_ref)
            tracer.set_surface(st_ref.elevation)
            tracer.set_time(t_ref)
            if st_ref is st:  # the usual held surface: meshed once
                c_ref, _, n_ref, _ = self.geometry(st)
            else:  # a surface traced once (a new sea every pulse): meshed on the device
                c_ref, n_ref = tracer.surface_geometry()
            if self._lead is None:
                occ_tx = tracer.occluded(c_ref, n_ref, tx_ref, device=True)
            else:  # the transmitter's leg, traced once for every receiver
                occ_tx = self._lead.occlusion(t, st)[1]
                tracer.set_surface(st_ref.elevation)  # (memoised: the lead's surface)
                tracer.set_time(t_ref)
            occ_rx = occ_tx if np.array_equal(tx_ref, rx_ref) else tracer.occluded(
                c_ref, n_ref, rx_ref, device=True)
            self._cache = (t_ref, occ_tx, occ_rx)
        return self._cache

    def _facets(self, t: float, state=None) -> Facets:
        """Facets at time ``t`` [s] in the engine's mode, without sub-facet shadowing.

        Parameters
        ----------
        t : float
            Time [s] (surface, objects, platforms).
        state : seaecho.sea.SurfaceState, optional
            ``surface(t)`` if already computed.
        """
        st = self.surface(t) if state is None else state
        tx, rx = self.positions(t)
        if self.mode == "analytic":
            return analytic_facets(st.x, st.y, st.elevation, st.slope_x, st.slope_y,
                                   st.velocity, tx, rx, shadowing=self.shadowing, time_s=t,
                                   frames=partial(facet_frames_drjit, variant=self._variant))
        tracer = self._get_tracer(st)
        if self.refresh_interval_s == 0.0:
            return tracer.facets(st.elevation, st.velocity, tx, rx, t=t,
                                 geometry=self.geometry(st))
        t_ref, occ_tx, occ_rx = self.occlusion(t, st)
        occ_tx, occ_rx = tracer.to_numpy(occ_tx), tracer.to_numpy(occ_rx)
        centroid, area, normal, velocity = self.geometry(st)
        geo = facet_frames_drjit(centroid, normal, tx, rx, variant=self._variant)
        lit = (geo["theta_i"] < np.pi / 2) & ~occ_tx
        seen = (geo["theta_s"] < np.pi / 2) & ~occ_rx
        return Facets(mode="raytraced", time_s=float(t), visibility_time_s=float(t_ref),
                      grid_shape=(st.y.size - 1, st.x.size - 1, 2), centroid=centroid,
                      area=area, normal=normal, velocity=velocity,
                      lit=lit.astype(np.float64), seen=seen.astype(np.float64),
                      visibility=(lit & seen).astype(np.float64), **geo)
