"""The simulation: every stage joined, pulse by pulse, streamed to a netCDF file.

This is the only module that knows every stage (docs/design.md). Its stage models come
from the builder (:func:`seaecho.build.build_simulation`), the only code that reads the
scene:

``Sea`` (ocean + wake) -> ``FacetEngine`` (ray-traced or analytic facets) ->
``scattering.facet`` (per-facet 2x2 amplitudes with speckle, ``SeaModel``) ->
``RadarSystem`` (antennas, radar equation, time of flight, NUFFT accumulation, noise) ->
range compression -> file (:mod:`seaecho.io.run`).

Per-pulse work is a pure function of (scene, pulse index): :meth:`Simulation.pulse`.
Pulse p is emitted at t_p = t_start + p / PRF. The sea surface used by pulse p is that of
the first pulse of its block, t_s = t_(N floor(p / N)) with N = ``sea_update_pulses``;
platforms and the facets' frames are those of t_p. What happens within a block is
``[scattering] sea_motion``, as resolved by :func:`seaecho.build.sea_motion` (``"auto"``,
the default, is ``"evolving"`` when the sea is renewed within the run and ``"held"`` when
one surface serves every pulse):

* ``"held"`` (the paper's section V-B keeps the map between pings): the facets stay at
  their positions of t_s and the speckle is drawn per block (``"speckle"``,
  ``"speckle-tilt"``, ``"breaking"`` streams, block index), so the clutter stays coherent
  while its surface is held and decorrelates when it is renewed;
* ``"evolving"``: the facets' phase centres (their surface particles' positions) are
  carried from t_s to t_p by velocity and acceleration, and each mechanism's speckle is a
  process of time (Bragg lines, orbital Doppler spread, finite lifetimes) whose anchors
  come from the ``"speckle-evolution"`` stream (:mod:`seaecho.scattering.dynamics`,
  docs/dynamics.md); the surface geometry (normals, visibility, breaking placement) is
  updated every block.

Noise is drawn per pulse (``"noise"`` stream, pulse index).

A pulse whose beams do not reach the tile skips the sea (``[radar] sea_gain_floor_db``,
:meth:`Simulation.sea_skipped`: the two-way gain bounded over the tile's box below the
floor, a pure function of the scene and the pulse index; docs/scanning.md); targets and
hulls are computed at every pulse.

:meth:`Simulation.run` writes pulses to a temporary file beside the destination as they
are computed (memory bounded by one block of pulses) and renames it into place at the end;
an exception or an interrupt removes it (``seaecho.io.dataset.atomic_path``).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .build import SimulationModels, build_simulation
from .checks.guards import check_dataset, check_pulse
from .conventions import CHANNELS
from .processing.range_compression import range_compress
from .radar.system import RadarSystem, ScattererEcho
from .rng import facet_gaussians
from .scattering.breaking import breaking_placement, modulating_wavenumber_limit

#: Names of the 2x2 scattering channels, (h, v) order flattened.
POLARISATIONS = CHANNELS

#: Margin of the sea tile's box in the beam's bound [m]: sea elevations and the facets'
#: horizontal displacements stay below it (a 30 m crest is beyond sea state 9).
SEA_MARGIN_M = 30.0


def wake_damping(state) -> NDArray[np.float64]:
    """Turbulent-wake damping of the Bragg waves per facet, in [0, 1], shape (N,): the
    sea state's wake mask averaged over each facet's vertices."""
    from .geometry.mesh import to_facets

    return to_facets(state.wake_mask).reshape(-1)


def _block_damping(state) -> NDArray[np.float64] | None:
    """:func:`wake_damping` of a block's sea state, None where its wake mask is zero
    everywhere (no ship): the formulas then skip the factor sqrt(1 - 0) = 1, the same
    numbers without the per-facet average and its copy to the device."""
    return wake_damping(state) if np.any(state.wake_mask) else None


def breaking_fraction(sea_model, sea, state, area: NDArray,
                      acceleration_z: NDArray | None = None) -> NDArray[np.float64]:
    """Fraction of each facet covered by breaking zones on a surface state, shape (N,).

    Downward acceleration of the wind sea at the state's time (linear kinematics,
    :meth:`seaecho.sea.Sea.vertical_acceleration`, or the nodes' ``acceleration_z`` [m/s^2]
    of :meth:`seaecho.sea.Sea.kinematics` at that time where already computed: the same
    bytes) averaged over each facet's vertices; the
    facets of largest value, of areas ``area`` [m^2], cover the fraction q of KHCC03
    (:func:`seaecho.scattering.breaking.breaking_placement`): the crests of the resolved
    waves, where the long waves that modulate breaking (eq BR7) have theirs. The zones'
    mean orbital velocity is eq BR8 (:func:`seaecho.scattering.breaking.
    placement_orbital_velocity`).
    """
    from .geometry.mesh import to_facets

    if acceleration_z is None:
        acceleration_z = sea.vertical_acceleration(state.t)
    acc = to_facets(acceleration_z).reshape(-1)
    return breaking_placement(-acc, area, sea_model.breaking.q)


def breaker_short_velocity(sea_model, sea, state, band: NDArray | None = None
                           ) -> NDArray[np.float64]:
    """Per facet, the velocity of the resolved waves shorter than the breakers' modulating
    waves, ``|K| >= k_mod`` (eq BR7), at the state's time [m/s], shape (N, 3): the part
    of the facets' velocity that the breaking zones' Doppler leaves out (eq BR10 of
    :mod:`seaecho.scattering.breaking`; :meth:`seaecho.sea.Sea.band_velocity`). ``band``:
    that velocity at the nodes (:func:`breaker_band_velocity` of the state's time) where
    already computed, the same bytes."""
    from .geometry.mesh import to_facets

    if band is None:
        band = breaker_band_velocity(sea_model, sea, state.t)
    return np.ascontiguousarray(to_facets(band).reshape(-1, 3))


def breaker_band_velocity(sea_model, sea, t: float) -> NDArray[np.float64]:
    """The nodes' velocity of the waves ``|K| >= k_mod`` (eq BR7) at ``t`` [s] [m/s],
    (ny, nx, 3): :meth:`seaecho.sea.Sea.band_velocity` (eq BR10)."""
    return sea.band_velocity(t, modulating_wavenumber_limit(sea_model.breaking.k_wb))


def facet_sigma0(sea_model, facets, damping: NDArray | None, breaking: NDArray | None,
                 variant: str | None = None) -> NDArray[np.float64]:
    """The per-facet ``sigma_mn`` x visibility that a run writes as ``sigma0``, (N, 4).

    Eqs P1-P7 of :mod:`seaecho.scattering.facet` with the scene's whole facet model
    (``SeaModel.facet_model``: the blend, the unresolved-tilt average of eq P6, the
    breaking zones of eq P7 where ``breaking`` puts them) and the wake's Bragg damping,
    in the simulation's working precision: the one scene NRCS of seaecho, which
    ``seaecho run`` maps and ``seaecho compare`` sums.

    Parameters
    ----------
    sea_model : seaecho.scattering.SeaModel
    facets : seaecho.geometry.facets.Facets
    damping : ndarray (N,) or None
        :func:`wake_damping` of the surface state.
    breaking : ndarray (N,) or None
        :func:`breaking_fraction` (None without breaking zones).
    variant : str, optional
        The scene's Mitsuba variant (Dr.Jit back end).
    """
    from .scattering.facet import PRECISION, facet_terms

    terms = facet_terms(facets.n_i, facets.n_s, facets.normal, sea_model.facet_model,
                        wake_damping=damping, breaking_fraction=breaking, local=facets,
                        variant=variant, precision=PRECISION)
    return terms.sigma() * facets.visibility[:, None]


def _take(facets, keep: NDArray[np.int64]):
    """The facets ``keep`` of a :class:`~seaecho.geometry.facets.Facets` (every per-facet
    array, ``extra`` included)."""
    n = facets.visibility.size
    upd = {f.name: getattr(facets, f.name)[keep] for f in dataclasses.fields(facets)
           if isinstance(getattr(facets, f.name), np.ndarray)
           and getattr(facets, f.name).shape[:1] == (n,)}
    upd["extra"] = {k: (v[keep] if isinstance(v, np.ndarray) and v.shape[:1] == (n,) else v)
                    for k, v in facets.extra.items()}
    return dataclasses.replace(facets, **upd)


def _take_held(held: dict, keep: NDArray[np.int64], draws: dict) -> dict:
    """A held block's quantities (:meth:`Simulation._block_quantities`) of the facets
    ``keep``: wake damping, breaking placement and the host speckle draws."""
    out = dict(held)
    for name in ("damping", "breaking"):
        if out.get(name) is not None:
            out[name] = out[name][keep]
    out["host_draws"] = {m: g[keep] for m, g in draws.items()}
    return out


@dataclass(frozen=True)
class SeaEcho:
    """The sea's contribution to one pulse.

    Attributes
    ----------
    echo : ScattererEcho
        Delays and amplitudes of the visible facets.
    sigma_facet : ndarray (N, 4) or None
        Per-facet scattering coefficients sigma_mn (HH, HV, VH, VV) per unit *facet*
        area [m^2/m^2] times the facet's visibility, all facets, when asked for:
        ``area * sigma_facet`` is the facet's mean radar cross section [m^2].
    facets : seaecho.geometry.facets.Facets or None
        The facets of the pulse (None from the fused kernel, ``radar.resident``).
    """

    echo: ScattererEcho
    sigma_facet: NDArray[np.float64] | None
    facets: object

    def sigma0_cells(self, cell_area: float) -> NDArray[np.float64]:
        """Normalised radar cross section per unit *horizontal* area of each grid cell,
        shape (4, ny - 1, nx - 1) [m^2/m^2]: the two triangles' ``area * sigma_facet``
        summed and divided by the cell's horizontal area ``cell_area`` [m^2].

        Its mean over the cells is the scene's NRCS sigma0 = <sigma> per unit horizontal
        area, the quantity a radar measures and ``seaecho sigma`` predicts.
        """
        if self.sigma_facet is None:
            raise ValueError("sea_echo(..., sigma=True) computes sigma_facet")
        f = self.facets
        rcs = self.sigma_facet * f.area[:, None]  # [m^2] per facet
        return np.moveaxis(rcs.reshape(f.grid_shape + (4,)).sum(axis=2), -1, 0) / cell_area


@dataclass(frozen=True)
class SeaStage:
    """A pulse's sea up to the facet model (:meth:`Simulation.sea_stage`).

    Attributes
    ----------
    pulse : int
    geometry : seaecho.radar.system.PulseGeometry
    state : seaecho.sea.SurfaceState
    facets : seaecho.geometry.facets.Facets
        The facets evaluated (a tile's weighted ones only).
    visibility : ndarray (N,)
        Their visibility times the tile's weight [-].
    keep : ndarray or None
        The indices of those facets among the surface's (a tile's culling).
    held : dict
        The block's quantities of those facets (damping, breaking, draws).
    sigma : bool
        Whether the echo also returns sigma_mn.
    args, kwargs : tuple, dict
        The arguments of :func:`seaecho.scattering.facet.speckled_facet_amplitudes`.
    """

    pulse: int
    geometry: object
    state: object
    facets: object
    visibility: NDArray[np.float64]
    keep: NDArray[np.int64] | None
    held: dict
    sigma: bool
    args: tuple
    kwargs: dict


def _crosses_rectangle(a: NDArray, b: NDArray, x: NDArray, y: NDArray) -> NDArray[np.bool_]:
    """Whether the 2-D segments a -> b (N, 2) [m] meet the rectangle spanned by the grid
    coordinates x, y [m] (Liang-Barsky clipping, vectorised)."""
    d = b - a
    lo = np.zeros(a.shape[0])
    hi = np.ones(a.shape[0])
    ok = np.ones(a.shape[0], dtype=bool)
    for k, (mn, mx) in enumerate(((x.min(), x.max()), (y.min(), y.max()))):  # 2 axes
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = (mn - a[:, k]) / d[:, k]
            t2 = (mx - a[:, k]) / d[:, k]
        flat = d[:, k] == 0
        ok &= ~flat | ((a[:, k] >= mn) & (a[:, k] <= mx))
        lo = np.where(flat, lo, np.maximum(lo, np.minimum(t1, t2)))
        hi = np.where(flat, hi, np.minimum(hi, np.maximum(t1, t2)))
    return ok & (lo <= hi)


class Simulation:
    """A scene's radar simulation (module docstring).

    Parameters
    ----------
    scene : seaecho.config.Scene
        Needs ``[radar]`` and ``[transmitter]``; read only by the builder.
    base_dir : path
        Folder of the scene file (``[[objects]]`` paths are relative to it).
    """

    def __init__(self, scene, base_dir: str | os.PathLike = ".") -> None:
        self._setup(build_simulation(scene, base_dir))

    @classmethod
    def from_models(cls, models: SimulationModels, facet_weight=None) -> Simulation:
        """A simulation of prebuilt stage models (:func:`seaecho.build.build_simulation`).

        ``facet_weight(sim, state, geometry)``, if given, weights each facet's visibility
        ((N,) [-]; a tile of a radar-wide sea, :mod:`seaecho.coverage`: the facets it owns
        and that are above the horizon); the sea then takes the reference path."""
        sim = cls.__new__(cls)
        sim._setup(models, facet_weight)
        return sim

    def _setup(self, models: SimulationModels, facet_weight=None) -> None:
        self.models = models
        #: per-facet weight of the visibility (a radar-wide sea's tile), or None
        self.facet_weight = facet_weight
        #: held sea with a facet weight: only the weighted facets through the facet model
        self.cull = True
        #: Mitsuba variant of the Dr.Jit kernels (``[tracing] variant``, checked by the builder)
        self.variant = models.variant
        self.radar = RadarSystem(models.radar)
        self.block = models.radar.sea_update_pulses
        #: the sea (surface + wake), None when sea clutter is off
        self.sea = models.sea
        #: the sea at the radar carrier: k, eps_r, sub-facet slopes, Bragg table
        self.sea_model = models.sea_model
        self.engine = None
        self._resident = None
        self._state_cache: tuple[float, object] | None = None
        self._state_before: tuple[float, object] | None = None  # the one held before
        self._lazy_slopes = False  # sea states' slopes synthesised when read (LazySlopes)
        # (time, job) of the sea state computed ahead on a thread (prefetch_surface)
        self._prefetch: tuple[float, object] | None = None
        # {time: job} of the evolving blocks' kinematics computed ahead (fused kernel):
        # the next pulse's is started before this pulse reads its own, so two are kept
        self._kinematics_ahead: dict[float, object] = {}
        # Per-sea-state quantities, computed once per block of held pulses and reused by
        # its pulses: (block, {"damping": ..., "draws": ...}). A pulse's result still
        # depends only on (scene, pulse): the cache holds what the block index determines.
        self._block_cache: tuple[int, dict] | None = None
        #: sea_motion = "evolving": facets move and their speckle evolves between updates
        self.evolving = self.sea_model is not None and self.sea_model.dynamics is not None
        self._speckle = None
        self._tile_box = None  # the sea tile's box of sea_gain_bound (8, 3) [m]
        self._skip_cache: dict[int, bool] = {}  # sea_skipped by pulse (a pure function)
        #: targets_hidden of a block of pulses (first, end, (2, end - first, T) or None),
        #: computed at once by pulses()
        self._hidden_ahead: tuple | None = None
        if self.sea is not None:
            from .tracing.engine import FacetEngine

            r = models.radar
            tx, rx = r.tx, r.rx
            rx_fn = None if rx is tx else (lambda t: rx.state(t).position)
            # The occlusion of a refresh time t_ref is traced on the surface held at t_ref
            self.engine = FacetEngine.from_model(models.tracing, self.surface_state_at,
                                                 lambda t: tx.state(t).position, rx_fn)
            # ray-traced facets come from the heights: the slopes only if read (outputs;
            # the same bytes either way)
            self._lazy_slopes = self.engine.mode == "raytraced"
            if self._lazy_slopes:
                self.sea.lazy_slopes = True
            from .radar.resident import resident_sea  # the fused pulse, where it applies

            if facet_weight is None:
                self._resident = resident_sea(self.radar, models.tracing, self.sea_model)
        #: the radar-wide sea ([sea] coverage = "radar"), None for the single tile
        self.coverage = None
        if getattr(models, "coverage", None) is not None:
            from .coverage import CoverageSea

            self.coverage = CoverageSea(models, self.radar, type(self).from_models)
        # Echoes of the [[objects]] with scatterer = true (docs/ship.md), or None
        from .tracing.hull_echo import HullEchoes

        self.hulls = HullEchoes.from_model(
            models.hulls, self.radar, variant=self.variant,
            surface=self.surface_state_at if self.sea is not None else None,
            sea_surface=self.sea.surface if self.sea is not None else None)
        #: the [[land]]: occluder of targets and land clutter (docs/land.md), or None
        self.land = None
        if models.land is not None:
            from .tracing.land import LandEchoes

            self.land = LandEchoes(models.land, self.radar, self.radar.seed,
                                   variant=self.variant)

    def share_sea(self, lead: Simulation) -> None:
        """Take the sea's per-block work from ``lead``, a simulation of the same sea
        surface, transmitter and seed with another receiver (``seaecho.multistatic``): its
        surface states (and their prefetch), per-block quantities (breaking placement,
        speckle draws, which depend on the seed and the block only), facet geometry,
        tracer and transmitter occlusion
        (:meth:`~seaecho.tracing.engine.FacetEngine.share_transmitter`). With a ship, this
        simulation's own turbulent-wake mask replaces the lead's in the states and the
        damping (its film term is evaluated at this pair's Bragg wavenumber, eq W17). The
        pulses are those of this simulation alone, bit for bit. Held sea only.
        """
        if (lead.models.sea_model is not self.models.sea_model or (self.sea is None)
                != (lead.sea is None) or (self.sea is not None
                                          and self.sea.surface is not lead.sea.surface)):
            raise ValueError("share_sea needs a simulation of the same sea models")
        if self.sea is None:
            return
        if self.evolving:
            raise ValueError("share_sea: not implemented yet for an evolving sea")
        self.prefetch_surface = lead.prefetch_surface
        self.engine.share_transmitter(lead.engine)
        if self.sea.ship is None or self.sea.ship == lead.sea.ship:
            self.surface_state = lead.surface_state
            self._block_quantities = lead._block_quantities
            return
        own: dict = {}  # the lead's state with this pair's wake mask, and its damping

        def surface_state(pulse: int):
            st = lead.surface_state(pulse)
            if own.get("state", (None,))[0] is not st:
                from .wake import turbulent_wake_mask

                mask = turbulent_wake_mask(self.sea.ship, st.x, st.y, st.t,
                                           length=self.sea.turbulent_wake_length)
                own["state"] = (st, dataclasses.replace(
                    st, wake_mask=np.asarray(mask, dtype=np.float64)))
            return own["state"][1]

        def block_quantities(pulse: int, state, n_facets: int) -> dict:
            from .geometry.mesh import to_facets

            q = lead._block_quantities(pulse, lead.surface_state(pulse), n_facets)
            if own.get("block", (None,))[0] is not q:
                damping = to_facets(state.wake_mask).reshape(-1)
                damping.setflags(write=False)
                if "draws" in q and q["draws"] is not None and not self._resident:
                    lead._host_draws(q)  # copied from the device once, for both
                own["block"] = (q, dict(q, damping=damping))
            return own["block"][1]

        self.surface_state = surface_state
        self._block_quantities = block_quantities

    # --------------------------------------------------------------------- the sea
    def surface_time(self, pulse: int) -> float:
        """Time of the sea surface used by ``pulse`` [s] (start of its block)."""
        return float(self.radar.emission_time((pulse // self.block) * self.block))

    def surface_state(self, pulse: int):
        """Sea state of ``pulse``'s block (memoised: the same for every pulse of a block;
        taken from :meth:`prefetch_surface` when it was started for this block). The
        state held before is kept too: with a new sea every pulse, the occlusion refresh
        traces the surface of the pulse before the refresh time (``surface_state_at``),
        which is then not synthesised again."""
        t = self.surface_time(pulse)
        if self._state_cache is None or self._state_cache[0] != t:
            ahead = self._prefetch
            before, self._state_before = self._state_before, self._state_cache
            if before is not None and before[0] == t:
                state = before[1]
            elif ahead is not None and ahead[0] == t:
                self._prefetch = None
                state = ahead[1].result()
            else:
                state = self.sea.state(t)
            self._state_cache = (t, state)
        return self._state_cache[1]

    def prefetch_surface(self, pulse: int) -> None:
        """Start computing the sea state of ``pulse``'s block on a thread of its own, if it
        is not the one held (:meth:`pulses` does it for the next pulse).

        The state is a pure function of its time, so the pulses' bytes do not change; the
        sea's synthesis (scipy's FFTs, finufft, numpy: they release the GIL) runs while
        the current pulse's serial stages (tracing, compaction, hull echo) leave a core
        free. Does nothing without a sea or outside the run.
        """
        if self.sea is None or not 0 <= pulse < self.radar.n_pulses:
            return
        t = self.surface_time(pulse)
        if ((self._state_cache is not None and self._state_cache[0] == t)
                or (self._prefetch is not None and self._prefetch[0] == t)):
            return
        from .sea import ThreadJob

        self._prefetch = (t, ThreadJob(self.sea.state, t))
        if self.evolving and self._resident is not None:  # the block's kinematics too
            kept = self._state_cache[0] if self._state_cache is not None else None
            self._kinematics_ahead = {s: job for s, job in self._kinematics_ahead.items()
                                      if s == kept}
            self._kinematics_ahead[t] = ThreadJob(self._kinematics, t)

    def surface_state_at(self, t: float):
        """Sea state held at time ``t`` [s]: that of the pulse emitted at or before t
        (the first pulse before the start, the last after the end)."""
        p = int(np.floor((t - self.radar.start_time) * self.radar.prf + 1e-9))
        return self.surface_state(min(max(p, 0), self.radar.n_pulses - 1))

    def _block_quantities(self, pulse: int, state, n_facets: int) -> dict:
        """Per-block quantities of ``pulse``'s block (memoised): wake damping per facet,
        speckle draws (held sea) and the breaking zones' placement.

        The speckle draws are circular complex Gaussians of unit variance per facet
        (:func:`seaecho.rng.facet_gaussians`: Philox4x32 keyed by (seed, stream, block),
        counted by facet and draw), so that facet j gets the same draw at every pulse of
        its block whatever order the pulses are computed in, on any number of threads or
        workers: (g_K, g_B) from the ``"speckle"`` stream, the unresolved-tilt nodes and
        the breaking zones from the ``"speckle-tilt"`` and ``"breaking"`` streams of the
        block. They are drawn in one kernel on the scene's Dr.Jit back end and stay there
        (numpy copies for the reference path, :meth:`_host_draws`). The breaking zones sit
        on the facets of largest downward acceleration of the block's surface, covering
        the fraction q of KHCC03 (:func:`breaking_fraction`).
        """

        block = pulse // self.block
        if self._block_cache is None or self._block_cache[0] != block:
            if self.evolving:
                self._block_cache = (block, self._evolving_block(state))
                return self._block_cache[1]
            seed, xp = self.radar.seed, self._draw_namespace()
            g_k, g_b = facet_gaussians(n_facets, 2, seed, "speckle", block, xp=xp)
            draws = {"specular": g_k, "bragg": g_b}
            model = self.sea_model
            if model.tilt is not None:
                nodes = facet_gaussians(n_facets, len(model.tilt.slopes), seed,
                                        "speckle-tilt", block, xp=xp)
                draws.update({f"bragg{j + 1}": g for j, g in enumerate(nodes)})
            q = {"damping": _block_damping(state), "draws": draws,
                 "breaking": None}
            if model.breaking is not None:
                (g_w,) = facet_gaussians(n_facets, 1, seed, "breaking", block, xp=xp)
                draws["breaking"] = g_w
                q["breaking"] = self.breaking_fraction(state)
            for a in (q["damping"], q["breaking"]):  # held: on the device
                if a is not None:
                    a.setflags(write=False)
            self._block_cache = (block, q)
        return self._block_cache[1]

    def _draw_namespace(self):
        """The back end the speckle is drawn on: the fused kernel's, else the scene's
        variant's Dr.Jit where it runs, else numpy (:func:`seaecho.backend.namespace`)."""
        if self._resident is not None:
            return self._resident.xp
        from .backend import namespace

        return namespace("auto", self.variant)

    @staticmethod
    def _host_draws(held: dict) -> dict:
        """The block's speckle draws as read-only numpy complex arrays (the reference
        path's kernels take numpy), copied from the device once per block."""
        if "host_draws" not in held:
            out = {}
            for m, g in held["draws"].items():
                if not isinstance(g, np.ndarray):
                    h = np.empty(g.real.numpy().shape, dtype=np.complex128)
                    h.real, h.imag = g.real.numpy(), g.imag.numpy()
                    h.setflags(write=False)
                    g = h
                out[m] = g
            held["host_draws"] = out
        return held["host_draws"]

    def _evolving_block(self, state, reference: bool = False) -> dict:
        """Per-block quantities of an evolving sea: wake damping, breaking placement, and
        the facets' phase centres with their velocities and accelerations at the block's
        surface time (the particles' positions ``r + D``, eq D1), from which each pulse
        extrapolates to its own time (:meth:`phase_centres`)."""
        from .geometry.mesh import to_facets
        from .scattering.dynamics import particle_centre

        if self._resident is not None and not reference:
            return self._evolving_block_fused(state)
        kin = self.sea.kinematics(state.t)
        centroid, area, _, velocity = self.engine.geometry(state)
        disp = np.stack([to_facets(kin.displacement[..., i]).reshape(-1) for i in range(2)],
                        axis=-1)
        acc = np.stack([to_facets(kin.acceleration[..., i]).reshape(-1) for i in range(3)],
                       axis=-1)
        centre = particle_centre(centroid, disp)
        q = {"damping": _block_damping(state), "draws": None,
             "breaking": None, "t": float(state.t), "centre": centre, "velocity": velocity,
             "acceleration": acc}
        if self.sea_model.breaking is not None:
            q["breaking"] = breaking_fraction(self.sea_model, self.sea, state, area,
                                              kin.acceleration_z)
            q["breaker_short"] = breaker_short_velocity(self.sea_model, self.sea, state)
        return q

    def _evolving_block_fused(self, state) -> dict:
        """:meth:`_evolving_block` for the fused kernel (``radar.resident``), which
        computes the phase centres from the nodes' displacement and acceleration (the same
        facet means and operations): those node fields (the acceleration only where a
        pulse of the block is after its surface time, ``sea_update_pulses > 1``), the wake
        damping and the breaking placement (:func:`breaking_fraction`)."""
        breaking = self.sea_model.breaking
        ahead = self._kinematics_ahead.pop(state.t, None)
        if ahead is not None:  # computed on a thread (prefetch)
            kin, band = ahead.result()
        else:
            kin, band = self._kinematics(state.t)
        q = {"damping": _block_damping(state), "draws": None, "breaking": None,
             "t": float(state.t), "motion": {"displacement": kin.displacement,
                                             "acceleration": kin.acceleration if
                                             self.block > 1 else None}}
        if breaking is not None:
            q["breaking"] = breaking_fraction(self.sea_model, self.sea, state,
                                              self.engine.geometry(state)[1],
                                              kin.acceleration_z)
            q["breaker_short"] = breaker_short_velocity(self.sea_model, self.sea, state,
                                                        band)
        return q

    def _kinematics(self, t: float):
        """The particles' kinematics of the fused kernel's evolving block at ``t`` [s]
        (:meth:`seaecho.sea.Sea.kinematics`): the acceleration where a pulse of a block is
        after its surface time (``sea_update_pulses > 1``), else its vertical component
        alone where the breaking zones are placed by it; and with the breaking zones the
        nodes' band velocity of eq BR10 (:func:`breaker_band_velocity`, else None) right
        after, on the same thread, from the travelling waves the kinematics made."""
        breaking = self.sea_model.breaking is not None
        kin = self.sea.kinematics(t, acceleration=True if self.block > 1 else
                                  "vertical" if breaking else False)
        return kin, (breaker_band_velocity(self.sea_model, self.sea, t) if breaking
                     else None)

    def phase_centres(self, pulse: int, state) -> NDArray[np.float64]:
        """Phase centres of the facets at ``pulse``'s emission time [m], shape (N, 3).

        Held sea: the facets' centroids (the surface of the block, frozen). Evolving sea:
        the particle positions of the block's surface time ``t_s`` carried to the pulse's
        time ``t_p`` by their velocity and acceleration,
        ``r(t_p) = r(t_s) + v (t_p - t_s) + a (t_p - t_s)^2 / 2`` (exact for ``t_p = t_s``,
        i.e. ``sea_update_pulses = 1``; the error of the next order is
        ``|da/dt| (t_p - t_s)^3 / 6``).
        """
        held = self._block_quantities(pulse, state, self.engine.geometry(state)[0].shape[0])
        if not self.evolving:
            return self.engine.geometry(state)[0]
        from .scattering.dynamics import extrapolate

        if "centre" not in held:  # the fused kernel's block: the reference's quantities
            held.update({k: v for k, v in self._evolving_block(state, reference=True).items()
                         if k not in held})
        dt = float(self.radar.emission_time(pulse)) - held["t"]
        return extrapolate(held["centre"], held["velocity"], held["acceleration"], dt)

    def _speckle_process(self, n_facets: int):
        """The evolving speckle of the facets (:class:`seaecho.scattering.dynamics.
        EvolvingSpeckle`), made once."""
        from .scattering.dynamics import EvolvingSpeckle

        if self._speckle is None or self._speckle.n != n_facets:
            m = self.sea_model
            self._speckle = EvolvingSpeckle(
                m.dynamics, self.radar.seed, n_facets,
                tilt_nodes=0 if m.tilt is None else len(m.tilt.slopes),
                breaking=m.breaking is not None)
        return self._speckle

    def breaking_fraction(self, state) -> NDArray[np.float64]:
        """Fraction of each facet covered by breaking zones on a surface state, shape (N,).

        :func:`breaking_fraction`: the downward acceleration of the wind sea (one inverse
        FFT), averaged over each facet's vertices; the facets of largest value cover the
        fraction q of KHCC03.
        """
        return breaking_fraction(self.sea_model, self.sea, state,
                                 self.engine.geometry(state)[1])

    def sea_echo(self, pulse: int, geometry=None, sigma: bool = False) -> SeaEcho:
        """Echo of the sea facets for one pulse.

        Parameters
        ----------
        pulse : int
            Pulse index.
        geometry : PulseGeometry, optional
            ``self.radar.geometry(pulse)`` if already computed.
        sigma : bool
            Also return the per-facet sigma_mn (all facets, times visibility).
        """
        stage = self.sea_stage(pulse, geometry, sigma)
        if isinstance(stage, SeaEcho):
            return stage
        from .scattering.facet import speckled_facet_amplitudes

        return self.sea_finish(stage, speckled_facet_amplitudes(*stage.args, **stage.kwargs))

    def sea_stage(self, pulse: int, geometry=None, sigma: bool = False
                  ) -> SeaEcho | SeaStage:
        """:meth:`sea_echo` up to the facet model: the pulse's facets and the arguments
        of :func:`seaecho.scattering.facet.speckled_facet_amplitudes` (a
        :class:`SeaStage`; :meth:`sea_finish` completes the echo from its amplitudes),
        or the echo itself where no facet model is left to evaluate (the fused kernel,
        no facet in a tile). The facet model is per facet, so the stages of several
        simulations of one sea model can share one evaluation (the tiles of a
        radar-wide sea, :mod:`seaecho.coverage`)."""
        if self.sea is None:
            raise ValueError("sea clutter is off in this scene ([radar] sea_clutter)")
        from .scattering.facet import PRECISION

        geo = self.radar.geometry(pulse) if geometry is None else geometry
        st = self.surface_state(pulse)
        if self._resident is not None and not sigma:  # one kernel, the same numbers
            n = self._resident.n_facets(st)
            held = self._block_quantities(pulse, st, n)
            _, *hidden = self.engine.occlusion(geo.time, st)
            draws, motion = held["draws"], None
            if self.evolving:  # eqs D1-D4 of the pulse's time, in the kernel
                draws = self._speckle_process(n).draws(float(geo.time),
                                                       held.get("breaker_short"))
                motion = dict(held["motion"],
                              dt=float(self.radar.emission_time(pulse)) - held["t"])
            echo = self._resident.echo(geo, st, hidden, draws, held["damping"],
                                       breaking=held["breaking"], motion=motion)
            return SeaEcho(echo, None, None)
        facets = self.engine.facets(geo.time, state=st)
        vis = facets.visibility
        keep = None
        held = self._block_quantities(pulse, st, vis.size)
        if self.facet_weight is not None:  # a tile of a radar-wide sea (seaecho.coverage)
            vis = vis * self.facet_weight(self, st, geo)
            if not self.evolving and self.cull:  # only its weighted facets, each with
                keep = np.flatnonzero(vis > 0)  # its own draws: the same numbers
                facets, vis, held = _take(facets, keep), vis[keep], _take_held(
                    held, keep, self._host_draws(held))
                if keep.size == 0:  # none in the beam, the horizon or the tile
                    none = np.zeros((0, 3))
                    return SeaEcho(self.radar.scatterer_echo(
                        geo, none, none, np.zeros((0, 2, 2), complex)), None, facets)
        damping = held["damping"]
        # All facets, so that facet j always gets the j-th speckle draw of its block
        # (visibility may change from pulse to pulse within a block). Eq P4 of
        # scattering.facet: |a|^2 is the facet's RCS [m^2]; visibility weights it. The
        # draws are the block's (drawn once per held surface); eqs P1-P4 run in one kernel
        args = (facets.n_i, facets.n_s, facets.normal)
        draws = None if self.evolving else self._host_draws(held)
        if self.evolving:  # eqs D2-D4 evaluated inside the facet kernel
            draws = self._speckle_process(vis.size).draws(float(geo.time),
                                                          held.get("breaker_short"))
        return SeaStage(pulse, geo, st, facets, vis, keep, held, sigma,
                        (*args, facets.area * vis, self.sea_model.facet_model),
                        dict(draws=draws, wake_damping=damping,
                             breaking_fraction=held["breaking"], local=facets,
                             variant=self.variant, precision=PRECISION))

    def sea_finish(self, stage: SeaStage, amp: NDArray[np.complex128]) -> SeaEcho:
        """The echo of a :class:`SeaStage` of :meth:`sea_stage` from its facets'
        speckled amplitudes ``amp`` (N, 4) [m] (its facet model's)."""
        from .scattering.facet import PRECISION

        facets, vis, geo = stage.facets, stage.visibility, stage.geometry
        centres = self.phase_centres(stage.pulse, stage.state)
        if stage.keep is not None:
            centres = centres[stage.keep]
        visible = vis > 0
        if visible.all():  # the usual case: no copies
            pos, vel = centres, facets.velocity
        else:
            pos, vel, amp = centres[visible], facets.velocity[visible], amp[visible]
        echo = self.radar.scatterer_echo(geo, pos, vel, amp.reshape(-1, 2, 2),
                                         variant=self.variant, precision=PRECISION,
                                         multipath=True)
        sig = None
        if stage.sigma:
            sig = facet_sigma0(self.sea_model, facets, stage.held["damping"],
                               stage.held["breaking"], variant=self.variant)
        return SeaEcho(echo, sig, facets)

    # ------------------------------------------------------ the beam and the tile
    def sea_gain_bound(self, pulse: int) -> float:
        """Upper bound of the two-way antenna gain relative to the beams' peaks over the
        whole sea tile at ``pulse`` [-] (:func:`seaecho.radar.coverage.two_way_bound` on
        the tile's box, :data:`SEA_MARGIN_M` around the grid and its mean level)."""
        if self.sea is None:
            raise ValueError("sea clutter is off in this scene ([radar] sea_clutter)")
        from .radar.coverage import tile_box, two_way_bound

        if self._tile_box is None:
            self._tile_box = tile_box(self.sea.x, self.sea.y, SEA_MARGIN_M)
        return two_way_bound(self.radar, pulse, self._tile_box)

    def _hull_seen(self, pulse: int):
        """``corners -> bool``: whether the two-way gain bound over a hull's box at
        ``pulse`` reaches ``[radar] sea_gain_floor_db`` (the floor the sea's skip uses,
        applied to each hull; :func:`seaecho.radar.coverage.two_way_bound`); None when
        the floor is off."""
        floor = self.models.radar.sea_gain_floor
        if floor is None:
            return None
        from .radar.coverage import two_way_bound

        return lambda corners: two_way_bound(self.radar, pulse, corners) >= floor

    def sea_skipped(self, pulse: int) -> bool:
        """True when ``pulse`` skips the sea: ``[radar] sea_gain_floor_db`` is set and
        :meth:`sea_gain_bound` is below it. A pure function of (scene, pulse), so the
        pulses stay computable in any order (docs/scanning.md)."""
        floor = self.models.radar.sea_gain_floor
        if self.sea is None or floor is None:
            return False
        if pulse not in self._skip_cache:  # asked up to three times per pulse by pulses
            if len(self._skip_cache) > 4096:
                self._skip_cache.clear()
            self._skip_cache[pulse] = self.sea_gain_bound(pulse) < floor
        return self._skip_cache[pulse]

    # ------------------------------------------------------------------- one pulse
    def pulse(self, pulse: int) -> NDArray[np.complex128]:
        """Raw samples of one pulse, shape (channels, fast_time) [sqrt(W)]."""
        if not 0 <= pulse < self.radar.n_pulses:
            raise ValueError(f"pulse = {pulse}: must be in [0, {self.radar.n_pulses})")
        geo = self.radar.geometry(pulse)
        echoes = []
        if self.sea is not None and not self.sea_skipped(pulse):
            echoes.append(self.sea_echo(pulse, geo).echo)
        ahead = self._hidden_ahead  # computed for a block of pulses by pulses()
        if ahead is not None and ahead[0] <= pulse < ahead[1]:
            hidden = None if ahead[2] is None else ahead[2][:, pulse - ahead[0]][:, None]
        else:
            hidden = self.targets_hidden(pulse)  # behind the land or a wave crest
        hide = {} if hidden is None or not hidden.any() else {"hidden": hidden.any(axis=0)[0]}
        t = self.radar.target_echo(geo, variant=self.variant, **hide)  # its pulse: geo.time
        if t is not None:
            echoes.append(t)
        if self.hulls is not None:
            echoes += self.hulls.echoes(geo, pulse, seen=self._hull_seen(pulse))
        if self.land is not None and self.land.n_facets:
            e = self.land.echo(geo, self.land_patches(pulse), variant=self.variant)
            if e is not None:
                echoes.append(e)
        raw = self.radar.receive(pulse, echoes)
        if self.coverage is not None:  # the radar-wide sea, accumulated tile by tile
            sea = self.coverage.raw(pulse)
            if sea is not None:
                raw += sea
        check_pulse(self, pulse, raw, echoes)  # NaN/Inf: NonFiniteEchoError (checks/guards.py)
        return raw

    # ---------------------------------------------------- the land and the wave crests
    def land_patches(self, pulse: int) -> NDArray[np.bool_] | None:
        """Which land patches ``pulse`` computes: those whose two-way gain bound
        (:func:`seaecho.radar.coverage.one_way_bound` over each patch's box, eq C2) is at
        or above ``[radar] sea_gain_floor_db``; None (all) without a floor. The skipped
        land's power obeys the sea's bound, eq C3 of docs/scanning.md."""
        floor = self.models.radar.sea_gain_floor
        if self.land is None or floor is None:
            return None
        from .radar.coverage import one_way_bounds

        geo = self.radar.geometry(pulse)
        boxes = self.land.patch_boxes
        g = one_way_bounds(self.radar.tx_antenna, geo.tx_axes, geo.tx.position, boxes)
        return g * one_way_bounds(self.radar.rx_antenna, geo.rx_axes, geo.rx.position,
                                  boxes) >= floor

    def targets_hidden(self, pulses) -> NDArray[np.bool_] | None:
        """Which point targets are hidden at ``pulses`` (an int or an array), shape
        (2, P, T): [0] behind the land (the segment from either antenna to the target
        hits a ``[[land]]`` triangle), [1] behind a wave crest (it hits the sea surface
        held at the pulse, ray traced on the tile: the waves outside the tile are not
        modelled). None when the scene has no target.

        Only segments whose ground track crosses the tile's rectangle are traced against
        the waves (the sea state of their blocks is computed for them).
        """
        targets = self.radar.model.targets
        if targets is None or not len(targets):
            return None
        pulses = np.atleast_1d(np.asarray(pulses, dtype=np.int64))
        t = self.radar.emission_time(pulses)
        pos = targets.positions[None] + t[:, None, None] * targets.velocities[None]
        earth = self.radar.model.earth
        if earth is not None:
            pos = earth.position(pos)
        ends = [self.radar.tx.state(t).position]
        if self.radar.rx is not self.radar.tx:  # bistatic: the receiver's line too
            ends.append(self.radar.rx.state(t).position)
        out = np.zeros((2,) + pos.shape[:2], dtype=bool)
        flat = pos.reshape(-1, 3)
        for a in ends:
            start = np.repeat(a, pos.shape[1], axis=0)
            if self.land is not None:
                out[0] |= self.land.hidden(flat, start).reshape(pos.shape[:2])
            tr = self.models.tracing
            if self.engine is None or tr is None or tr.mode != "raytraced":
                continue
            cross = _crosses_rectangle(start[:, :2], flat[:, :2], self.sea.x, self.sea.y)
            cross = cross.reshape(pos.shape[:2])
            if not cross.any():
                continue
            from .tracing.scene import segments_blocked

            blocks = pulses // self.block
            for b in np.unique(blocks[cross.any(axis=1)]):  # one sea state per block
                rows = np.flatnonzero((blocks == b) & cross.any(axis=1))
                st = self.surface_state(int(pulses[rows[0]]))
                tracer = self.engine.tracer
                tracer.set_surface(st.elevation)
                sel = np.zeros(pos.shape[:2], dtype=bool)
                sel[rows] = cross[rows]
                hit = segments_blocked([tracer.sea.mi_scene], start[sel.ravel()],
                                       flat[sel.ravel()], variant=tracer.variant)
                out[1][sel] |= hit
        return out

    def truth_hidden(self) -> NDArray[np.bool_] | None:
        """The objects of the ground truth (ships, then targets) hidden at every pulse,
        (2, P, S + T): [0] behind the land, [1] behind a wave crest
        (:meth:`targets_hidden`; a ship by its waterline point at its position, against
        the land only: its hull's own trace sees the waves). None when nothing can hide
        them (no land, and no target or no ray-traced sea)."""
        ships = self.models.ships
        n = self.radar.n_pulses
        targets = self.targets_hidden(np.arange(n))
        if self.land is None and (targets is None or not targets.any()):
            return None
        n_t = 0 if targets is None else targets.shape[2]
        out = np.zeros((2, n, len(ships) + n_t), dtype=bool)
        if n_t:
            out[:, :, len(ships):] = targets
        if ships and self.land is not None:
            t = self.radar.emission_time(np.arange(n))
            pos = np.zeros((n, len(ships), 3))
            for i, ship in enumerate(ships):  # a few ships
                pos[:, i, :2] = ship.position(t)
            earth = self.radar.model.earth
            flat = (pos if earth is None else earth.position(pos)).reshape(-1, 3)
            for a in (self.radar.tx.state(t).position, self.radar.rx.state(t).position):
                start = np.repeat(a, len(ships), axis=0)
                out[0, :, :len(ships)] |= self.land.hidden(flat, start).reshape(n, -1)
        return out

    def pulses(self, start: int, stop: int) -> tuple[NDArray[np.complex128],
                                                     NDArray[np.complex128]]:
        """Raw and range-compressed samples of pulses ``start`` to ``stop - 1``, each
        (stop - start, channels, fast_time) [sqrt(W)]: :meth:`pulse` and :meth:`compress`."""
        out = []
        for p in range(start, stop):
            if (p + 1 < stop and self.sea is not None and not self.sea_skipped(p)
                    and not self.sea_skipped(p + 1)):
                self.surface_state(p)  # this pulse's sea (computed ahead, if it was)
                self.prefetch_surface(p + 1)  # the next one's, while this pulse runs
            ahead = self._hidden_ahead
            if ahead is None or not ahead[0] <= p < ahead[1]:
                # the targets' lines of sight of the rest of this sea block at once (a
                # pure function of the pulse: the same bytes as pulse by pulse)
                end = min(stop, (p // self.block + 1) * self.block)
                self._hidden_ahead = (p, end, self.targets_hidden(np.arange(p, end)))
            out.append(self.pulse(p))
        raw = np.stack(out)
        return raw, self.compress(raw)

    def block_edges(self) -> NDArray[np.int64]:
        """Pulse indices at which the held sea surface or the occlusion refresh time
        changes, with 0 and ``n_pulses``: the pulses between two edges share every
        per-block cache (surface, speckle, wake damping, traced occlusion)."""
        p = np.arange(self.radar.n_pulses)
        change = np.diff(p // self.block, prepend=-1) != 0
        tr = self.models.tracing
        if self.engine is not None and tr.mode == "raytraced" and tr.refresh_interval_s > 0:
            # tracing.engine.reference_time, vectorised
            ref = np.floor(self.radar.emission_time(p) / tr.refresh_interval_s + 1e-9)
            change |= np.diff(ref, prepend=ref[0] - 1.0) != 0
        return np.append(np.flatnonzero(change), p.size)

    def compress(self, raw: NDArray[np.complex128]) -> NDArray[np.complex128]:
        """Range-compressed samples with the model's weighting (same shape as ``raw``)."""
        m = self.models.radar
        return range_compress(raw, self.radar.waveform.samples, m.range_weighting,
                              nbar=m.taylor_nbar, sidelobe_db=m.taylor_sidelobe_db)

    # ------------------------------------------------------------------ the dataset
    def sea_truth(self) -> dict:
        """Surface, wake and NRCS maps at the sigma-map pulse, and the ship's track.

        The NRCS map comes from the fused kernel (``ResidentSea.sigma_cells``) where the
        pulses do, else from the reference path (``SeaEcho.sigma0_cells``); the two agree
        to a few float64 ulps (Dr.Jit fuses multiply-adds), and each scene always uses one.

        Returns
        -------
        dict
            ``state`` (the SurfaceState), ``sigma0`` (4, ny - 1, nx - 1) NRCS per unit
            horizontal area of each cell [m^2/m^2], ``visibility`` (ny - 1, nx - 1) cell
            mean, ``ship_position`` (pulses, 2) [m] or None.
        """
        p = self.models.radar.sigma_map_pulse
        st = self.surface_state(p)
        dx, dy = float(self.sea.x[1] - self.sea.x[0]), float(self.sea.y[1] - self.sea.y[0])
        if self._resident is not None:  # one kernel (reference's numbers to 1e-15)
            geo = self.radar.geometry(p)
            held = self._block_quantities(p, st, self._resident.n_facets(st))
            _, *hidden = self.engine.occlusion(geo.time, st)
            sigma0, vis = self._resident.sigma_cells(geo, st, hidden, held["damping"],
                                                     breaking=held["breaking"])
        else:
            se = self.sea_echo(p, sigma=True)
            sigma0, vis = se.sigma0_cells(dx * dy), se.facets.cell_mean("visibility")
        ship = None
        if self.sea.ship is not None:
            t = self.radar.emission_time(np.arange(self.radar.n_pulses))
            ship = self.sea.ship.position(t)  # the first ship's (truth_position: all)
        return {"state": st, "sigma0": sigma0, "visibility": vis, "ship_position": ship}

    def static_dataset(self):
        """Everything but the pulses: coordinates, tracks, surface, NRCS maps, truth
        (:func:`seaecho.io.run.run_dataset`)."""
        from .io.run import run_dataset

        truth = self.sea_truth() if self.sea is not None else None
        tracing = self.models.tracing
        # The hulls' centres at the sigma-map pulse and their RCS against pulse
        hulls = (self.hulls.truth(self.models.radar.sigma_map_pulse)
                 if self.hulls is not None else None)
        # Per-pulse truth of every ship and target (seaecho.radar.truth)
        from .radar.truth import ground_truth

        rcs = {}
        if hulls is not None:
            names = [str(n) for n in hulls[1]["hull"][1]]
            rcs = {n: hulls[0]["hull_rcs"][1][i] for i, n in enumerate(names)}
        objects = ground_truth(self.radar, self.models.ships, rcs, hidden=self.truth_hidden())
        if hulls is not None:
            objects = ({**hulls[0], **objects[0]}, {**hulls[1], **objects[1]})
        if self.land is not None:  # the coastline: outlines, gamma (docs/land.md)
            land = self.land.dataset_variables()
            objects = ({**objects[0], **land[0]}, {**objects[1], **land[1]})
        ds = run_dataset(self.radar, self.models.attrs, truth=truth, extra=objects,
                           x=None if self.sea is None else self.sea.x,
                           y=None if self.sea is None else self.sea.y,
                           extra_attrs={
                               "sea_update_pulses": self.block,
                               "sea_update_interval_s": self.block / self.radar.prf,
                               "tracing_mode": tracing.mode if tracing else "none",
                               "tracing_refresh_interval_s":
                                   tracing.refresh_interval_s if tracing else 0.0,
                               "sigma_map_pulse": self.models.radar.sigma_map_pulse,
                               "range_weighting": self.models.radar.range_weighting,
                               **self.sea_attrs()})
        check_dataset(ds)  # NaN/Inf in tracks, surface, maps: NonFiniteEchoError
        return ds

    def sea_attrs(self) -> dict:
        """Dataset attributes that say how the sea scatters and moves."""
        m = self.sea_model
        if m is None:
            return {}
        out = {"scattering_model": "blend+breaking" if m.breaking is not None else "blend",
               "unresolved_tilt": int(m.tilt is not None),
               "sea_motion": "evolving" if self.evolving else "held",
               "sea_frozen": int(not self.evolving),
               "sea_motion_note": (
                   "evolving: facets move with the surface particles and their speckle "
                   "evolves at every pulse (Bragg lines, orbital motion, finite lifetimes); "
                   "geometry (normals, visibility, breaking placement) updated every "
                   "sea_update_pulses" if self.evolving else
                   "held: the surface and its speckle are frozen within each block of "
                   "sea_update_pulses pulses (the paper's section V-B)"),
               "phase_update_interval_s": (1.0 / self.radar.prf) if self.evolving else 0.0,
               # [radar] sea_gain_floor_db as a two-way gain [-]: the sea is skipped where
               # the beams' bound over the tile is below it (docs/scanning.md, eq C3)
               "sea_gain_floor": ("off" if self.models.radar.sea_gain_floor is None
                                  else self.models.radar.sea_gain_floor),
               "subfacet_mss_upwind": m.mss_upwind,
               "subfacet_mss_crosswind": m.mss_crosswind}
        if self.coverage is not None:  # [sea] coverage = "radar" (docs/scanning.md)
            pw = self.coverage.patchwork
            out.update({"sea_coverage": "radar", "sea_tiles": len(pw),
                        "sea_level_spacing_m": [lv.spacing[0] for lv in pw.levels],
                        "sea_level_band_edges_m": [float(e) for e in pw.edges],
                        "subfacet_mss_note": "of the finest level; each level has its own"})
        if m.breaking is not None:
            out["breaking_fraction"] = m.breaking.q
        if self.evolving:
            for fam, t in m.dynamics.lifetimes.items():
                out[f"speckle_lifetime_{fam.replace('+', '_plus').replace('-', '_minus')}_s"] = t
            c = m.dynamics.velocity_covariance
            out["subfacet_velocity_rms_m_s"] = [float(np.sqrt(c[i, i])) for i in range(3)]
        return out

    # ------------------------------------------------------------------------ run
    def run(self, path: str | os.PathLike, progress: bool = True, chunk: int | None = None,
            resume: bool = False, runner=None) -> Path:
        """Simulate every pulse and write the dataset to ``path``.

        A ``.zarr`` path gets a Zarr store written block by block and resumable
        (:mod:`seaecho.io.zarr_run`); any other path a netCDF file written atomically.
        The blocks are computed in this process, or by ``runner``
        (:class:`seaecho.distributed.DaskBlocks`: on a Dask cluster, with the same bytes).

        Parameters
        ----------
        path : path
            Output netCDF file (h5netcdf, complex variables as HDF5 compounds) or Zarr
            store (``*.zarr``).
        progress : bool
            Show a tqdm progress bar over the pulses.
        chunk : int, optional
            Pulses per block (memory: chunk x channels x samples x 32 bytes; the Zarr
            chunk along ``pulse``); default :func:`seaecho.io.run.block_size` of
            :meth:`block_edges`.
        resume : bool
            Zarr only: continue an interrupted run of the same scene, computing only the
            blocks it lacks.
        runner : optional
            Computes the blocks (:func:`seaecho.io.run.write_run`); default
            :class:`seaecho.io.run.SerialBlocks` of :meth:`pulses`, in this process.

        Returns
        -------
        Path
        """
        from .io.run import write_run

        return write_run(path, self.static_dataset, identity=self.models.attrs,
                         progress=progress, resume=resume, **self._blocks(chunk, runner))

    def dataset(self, progress: bool = True, chunk: int | None = None, runner=None):
        """Simulate every pulse and return the dataset that :meth:`run` writes, held in
        memory (:func:`seaecho.io.run.run_in_memory`: the same blocks, the same values
        bit for bit).

        Memory: ``raw`` and ``compressed``, pulses x channels x samples x 32 bytes, plus
        the static part (:meth:`static_dataset`).

        Parameters
        ----------
        progress, chunk, runner
            As :meth:`run`.

        Returns
        -------
        xarray.Dataset
        """
        from .io.run import run_in_memory

        return run_in_memory(self.static_dataset(), progress=progress,
                             **self._blocks(chunk, runner))

    def _blocks(self, chunk: int | None, runner) -> dict:
        """Shape, block size, runner and weighting of this run's pulses
        (:func:`seaecho.io.run.write_run`)."""
        from .io.run import SerialBlocks, block_size

        return {"shape": (self.radar.n_pulses, len(self.radar.channels),
                          self.radar.window.n_samples),
                "block": block_size(self.block_edges(), chunk),
                "runner": SerialBlocks(self.pulses) if runner is None else runner,
                "weighting": self.models.radar.range_weighting}


__all__ = ["POLARISATIONS", "SEA_MARGIN_M", "SeaEcho", "Simulation"]
