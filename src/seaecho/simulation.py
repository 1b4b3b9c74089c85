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
the first pulse of its block, t_s = t_(N floor(p / N)) with N = ``sea_update_pulses``
(the paper's section V-B keeps the map between pings); platforms and facet geometry are
those of t_p. Speckle is drawn per block (``"speckle"`` stream, block index), so the
clutter stays coherent while its surface is held and decorrelates when it is renewed;
noise is drawn per pulse (``"noise"`` stream, pulse index).

:meth:`Simulation.run` writes pulses to a temporary file beside the destination as they
are computed (memory bounded by one block of pulses) and renames it into place at the end;
an exception or an interrupt removes it (``seaecho.io.dataset.atomic_path``).

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .build import SimulationModels, build_simulation
from .conventions import CHANNELS
from .guards import check_dataset, check_pulse
from .processing.range_compression import range_compress
from .radar.system import RadarSystem, ScattererEcho
from .rng import generator

#: Names of the 2x2 scattering channels, (h, v) order flattened.
POLARISATIONS = CHANNELS


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
    def from_models(cls, models: SimulationModels) -> Simulation:
        """A simulation of prebuilt stage models (:func:`seaecho.build.build_simulation`)."""
        sim = cls.__new__(cls)
        sim._setup(models)
        return sim

    def _setup(self, models: SimulationModels) -> None:
        self.models = models
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
        # Per-sea-state quantities, computed once per block of held pulses and reused by
        # its pulses: (block, {"damping": ..., "draws": ...}). A pulse's result still
        # depends only on (scene, pulse): the cache holds what the block index determines.
        self._block_cache: tuple[int, dict] | None = None
        if self.sea is not None:
            from .tracing.engine import FacetEngine

            r = models.radar
            tx, rx = r.tx, r.rx
            rx_fn = None if rx is tx else (lambda t: rx.state(t).position)
            # The occlusion of a refresh time t_ref is traced on the surface held at t_ref
            self.engine = FacetEngine.from_model(models.tracing, self.surface_state_at,
                                                 lambda t: tx.state(t).position, rx_fn)
            from .radar.resident import resident_sea  # the fused pulse, where it applies

            self._resident = resident_sea(self.radar, models.tracing, self.sea_model)
        # Echoes of the [[objects]] with scatterer = true (docs/ship.md), or None
        from .tracing.hull_echo import HullEchoes

        self.hulls = HullEchoes.from_model(
            models.hulls, self.radar, variant=self.variant,
            surface=self.surface_state_at if self.sea is not None else None)

    # --------------------------------------------------------------------- the sea
    def surface_time(self, pulse: int) -> float:
        """Time of the sea surface used by ``pulse`` [s] (start of its block)."""
        return float(self.radar.emission_time((pulse // self.block) * self.block))

    def surface_state(self, pulse: int):
        """Sea state of ``pulse``'s block (memoised: the same for every pulse of a block)."""
        t = self.surface_time(pulse)
        if self._state_cache is None or self._state_cache[0] != t:
            self._state_cache = (t, self.sea.state(t))
        return self._state_cache[1]

    def surface_state_at(self, t: float):
        """Sea state held at time ``t`` [s]: that of the pulse emitted at or before t
        (the first pulse before the start, the last after the end)."""
        p = int(np.floor((t - self.radar.start_time) * self.radar.prf + 1e-9))
        return self.surface_state(min(max(p, 0), self.radar.n_pulses - 1))

    def _block_quantities(self, pulse: int, state, n_facets: int) -> dict:
        """Wake damping per facet and speckle draws of ``pulse``'s block (memoised).

        The speckle draws come from the ``"speckle"`` stream of the block index, one pair
        (g_K, g_B) per facet, so that facet j gets the same draw at every pulse of its
        block whatever order the pulses are computed in.
        """
        from .geometry.mesh import to_facets
        from .scattering.facet import speckle_draws

        block = pulse // self.block
        if self._block_cache is None or self._block_cache[0] != block:
            rng = generator(self.radar.seed, "speckle", block)
            q = {"damping": to_facets(state.wake_mask).reshape(-1),
                 "draws": speckle_draws(n_facets, rng)}
            for a in (q["damping"], *q["draws"]):  # held: kept on the device
                a.setflags(write=False)
            self._block_cache = (block, q)
        return self._block_cache[1]

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
        if self.sea is None:
            raise ValueError("sea clutter is off in this scene ([radar] sea_clutter)")
        from .scattering.facet import facet_terms, speckled_facet_amplitudes

        geo = self.radar.geometry(pulse) if geometry is None else geometry
        st = self.surface_state(pulse)
        if self._resident is not None and not sigma:  # one kernel, the same numbers
            held = self._block_quantities(pulse, st, self._resident.n_facets(st))
            _, *hidden = self.engine.occlusion(geo.time, st)
            echo = self._resident.echo(geo, st, hidden, held["draws"], held["damping"])
            return SeaEcho(echo, None, None)
        facets = self.engine.facets(geo.time, state=st)
        vis = facets.visibility
        held = self._block_quantities(pulse, st, vis.size)
        damping = held["damping"]
        # All facets, so that facet j always gets the j-th speckle draw of its block
        # (visibility may change from pulse to pulse within a block). Eq P4 of
        # scattering.facet: |a|^2 is the facet's RCS [m^2]; visibility weights it. The
        # draws are the block's (drawn once per held surface); eqs P1-P4 run in one kernel
        args = (facets.n_i, facets.n_s, facets.normal)
        model = self.sea_model.facet_model
        amp = speckled_facet_amplitudes(*args, facets.area * vis, *model,
                                        draws=held["draws"], wake_damping=damping,
                                        local=facets, variant=self.variant)
        visible = vis > 0
        if visible.all():  # the usual case: no copies
            pos, vel = facets.centroid, facets.velocity
        else:
            pos, vel, amp = facets.centroid[visible], facets.velocity[visible], amp[visible]
        echo = self.radar.scatterer_echo(geo, pos, vel, amp.reshape(-1, 2, 2),
                                         variant=self.variant)
        sig = None
        if sigma:
            sig = facet_terms(*args, *model, wake_damping=damping, local=facets,
                              variant=self.variant).sigma() * vis[:, None]
        return SeaEcho(echo, sig, facets)

    # ------------------------------------------------------------------- one pulse
    def pulse(self, pulse: int) -> NDArray[np.complex128]:
        """Raw samples of one pulse, shape (channels, fast_time) [sqrt(W)]."""
        if not 0 <= pulse < self.radar.n_pulses:
            raise ValueError(f"pulse = {pulse}: must be in [0, {self.radar.n_pulses})")
        geo = self.radar.geometry(pulse)
        echoes = []
        if self.sea is not None:
            echoes.append(self.sea_echo(pulse, geo).echo)
        t = self.radar.target_echo(geo, variant=self.variant)
        if t is not None:
            echoes.append(t)
        if self.hulls is not None:
            echoes += self.hulls.echoes(geo, pulse)
        raw = self.radar.receive(pulse, echoes)
        check_pulse(self, pulse, raw, echoes)  # NaN/Inf: NonFiniteEchoError (guards.py)
        return raw

    def pulses(self, start: int, stop: int) -> tuple[NDArray[np.complex128],
                                                     NDArray[np.complex128]]:
        """Raw and range-compressed samples of pulses ``start`` to ``stop - 1``, each
        (stop - start, channels, fast_time) [sqrt(W)]: :meth:`pulse` and :meth:`compress`."""
        raw = np.stack([self.pulse(p) for p in range(start, stop)])
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

        Returns
        -------
        dict
            ``state`` (the SurfaceState), ``sigma0`` (4, ny - 1, nx - 1) NRCS per unit
            horizontal area of each cell [m^2/m^2], ``visibility`` (ny - 1, nx - 1) cell
            mean, ``ship_position`` (pulses, 2) [m] or None.
        """
        p = self.models.radar.sigma_map_pulse
        st = self.surface_state(p)
        se = self.sea_echo(p, sigma=True)
        dx, dy = float(self.sea.x[1] - self.sea.x[0]), float(self.sea.y[1] - self.sea.y[0])
        ship = None
        if self.sea.ship is not None:
            t = self.radar.emission_time(np.arange(self.radar.n_pulses))
            ship = self.sea.ship.position(0.0)[None, :] + t[:, None] * self.sea.ship.velocity
        return {"state": st, "sigma0": se.sigma0_cells(dx * dy),
                "visibility": se.facets.cell_mean("visibility"), "ship_position": ship}

    def static_dataset(self):
        """Everything but the pulses: coordinates, tracks, surface, NRCS maps, truth
        (:func:`seaecho.io.run.run_dataset`)."""
        from .io.run import run_dataset

        truth = self.sea_truth() if self.sea is not None else None
        tracing = self.models.tracing
        # The hulls' centres at the sigma-map pulse and their RCS against pulse
        hulls = (self.hulls.truth(self.models.radar.sigma_map_pulse)
                 if self.hulls is not None else None)
        ds = run_dataset(self.radar, self.models.attrs, truth=truth, extra=hulls,
                         x=None if self.sea is None else self.sea.x,
                         y=None if self.sea is None else self.sea.y,
                         extra_attrs={
                             "sea_update_pulses": self.block,
                             "sea_update_interval_s": self.block / self.radar.prf,
                             "tracing_mode": tracing.mode if tracing else "none",
                             "tracing_refresh_interval_s":
                                 tracing.refresh_interval_s if tracing else 0.0,
                             "sigma_map_pulse": self.models.radar.sigma_map_pulse,
                             "range_weighting": self.models.radar.range_weighting})
        check_dataset(ds)  # NaN/Inf in tracks, surface, maps: NonFiniteEchoError
        return ds

    # ------------------------------------------------------------------------ run
    def run(self, path: str | os.PathLike, progress: bool = True, chunk: int | None = None,
            resume: bool = False) -> Path:
        """Simulate every pulse in this process and write the dataset to ``path``.

        A ``.zarr`` path gets a Zarr store written block by block and resumable
        (:mod:`seaecho.io.zarr_run`); any other path a netCDF file written atomically.
        :func:`seaecho.distributed.run` does the same on a Dask cluster, with the same
        bytes.

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

        Returns
        -------
        Path
        """
        from .io.run import SerialBlocks, block_size, write_run

        size = block_size(self.block_edges(), chunk)
        return write_run(path, self.static_dataset, identity=self.models.attrs,
                         shape=(self.radar.n_pulses, len(self.radar.channels),
                                self.radar.window.n_samples), block=size,
                         runner=SerialBlocks(self.pulses),
                         weighting=self.models.radar.range_weighting, progress=progress,
                         resume=resume)


__all__ = ["POLARISATIONS", "SeaEcho", "Simulation"]
