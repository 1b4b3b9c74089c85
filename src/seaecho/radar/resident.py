"""The sea's echo of one pulse as one kernel on device-resident facets.

The reference path of ``Simulation.sea_echo`` runs the sea's per-pulse stages one after
the other, each a Dr.Jit kernel with numpy arrays in and out: facet frames and
visibility (``FacetEngine.facets``), the speckled amplitudes (eqs P1-P4,
``speckled_facet_amplitudes``), the radar equation (eqs R1, R3,
``RadarSystem.scatterer_echo``). Between them every per-facet quantity goes to the host
and back: on a GPU, over the bus; on the CPU, through single-threaded numpy copies that
cost as much as the kernels (``docs/performance.md``).

:class:`ResidentSea` evaluates the same functions (:func:`seaecho.radar.kernels.
sea_echo_terms`) as one kernel per pulse on the back end of the scene's Mitsuba variant
(``drjit.llvm`` on the CPU, ``drjit.cuda`` on a GPU):

- what a held sea determines is copied to the device once per sea state: the grid's node
  heights and velocities (the kernel computes each facet's centroid, area, normal and
  velocity from its vertices, :func:`seaecho.geometry.mesh.facet_geometry_in`), the wake
  damping, the breaking zones' area fractions (eq P7) and the speckle draws of every
  mechanism (read-only numpy arrays, :func:`seaecho.backend.resident`);
  the occlusion masks stay on the device from the ray tracer to the kernel
  (``FacetEngine.occlusion``);
- per pulse only the platform states enter (opaque constants: no recompilation);
- out come the delays and the channels' amplitudes of the facets that are visible and
  inside the receive window, in facet order, each channel packed by the kernel into the
  memory layout of a (K,) complex array. On the CPU they are numpy views of that memory
  (no copy) for :func:`seaecho.radar.echo.accumulate`; on a GPU they stay there for
  :func:`seaecho.radar.echo.accumulate_cuda`, and only the pulse's samples come back.

The mechanisms are those of the reference path: the Kirchhoff/SPM blend, the Bragg term
averaged over the unresolved tilts (eq P6, ``tilt``) and the breaking zones (eq P7); the
numbers are those of the reference path, bit for bit (the same operations on the same
values; tests). Eqs P1-P7, the antenna gains and the port states are evaluated in float32
(``precision``; the delays, the carrier phase and the amplitudes' magnitude in float64),
within 2e-6 of each channel's largest amplitude of the float64 kernel (docs/scattering.md,
"Working precision"). A held sea (``[scattering] sea_motion = "held"``, the paper's) has its
facets' echoes at their centroids and the block's speckle draws; an evolving sea
(docs/dynamics.md) has them at its surface particles' positions carried from the
surface's time to the pulse's (eq D1: the nodes' displacement and acceleration, copied
once per surface, averaged per facet in the kernel) and the speckle of the pulse's time
(eqs D2-D4, the anchors of :class:`seaecho.scattering.dynamics.EvolvingSpeckle` read in
the kernel): the same functions as the reference path's, the same bytes (tests).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import os
import weakref
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..backend import Boundary, drjit_namespace
from ..geometry.mesh import facet_count, facet_geometry_in
from ..scattering.dynamics import extrapolate, particle_centre
from ..scattering.facet import (
    PRECISION,
    FacetModel,
    facet_arrays,
    kernel_sea,
    mechanism_sigma,
    mechanisms,
)
from ..scattering.spectrum_table import BraggSpectrumTable
from .kernels import facet_visibility, sea_echo_terms
from .replay import _BoundGeometry, _view_key, no_garbage_collection
from .system import DeviceEcho, PulseGeometry, RadarSystem, ScattererEcho

__all__ = ["FREEZE", "ResidentSea", "resident_sea"]

#: Default of ``ResidentSea(freeze=...)``: the environment variable ``SEAECHO_FREEZE``
#: ("1" on, "0" off), else None: on for the CUDA back end (an H100's held pulse 7.0 ms
#: frozen against 14-15 ms traced), off on the CPU (1-3 % of a pulse for tens of MiB;
#: docs/performance.md gives the measurements).
FREEZE: bool | None = ({"1": True, "0": False}.get(os.environ["SEAECHO_FREEZE"])
                       if "SEAECHO_FREEZE" in os.environ else None)
#: Recordings of the frozen kernel after which Dr.Jit warns (a scene whose pulses keep
#: changing its structure would re-record at every pulse).
FREEZE_WARN_AFTER = 10


class ResidentSea:
    """Per-pulse sea echo evaluated as one kernel (module docstring).

    Parameters
    ----------
    radar : RadarSystem
        Antennas, channels, carrier, receive window.
    facet_model : seaecho.scattering.facet.FacetModel
        ``SeaModel.facet_model``: the sea's scattering inputs, whole (wavenumber,
        permittivity, the Bragg spectrum table, the tilting band's slope variances as
        numbers, wind, model, tilt nodes of eq P6, breaking tilt of BR5).
    variant : str, optional
        Mitsuba variant: ``drjit.llvm`` for ``llvm_*`` (default), ``drjit.cuda`` for
        ``cuda_*`` (:func:`seaecho.backend.drjit_namespace`, which refuses a variant that
        differs from the one Mitsuba runs).
    freeze : bool, optional
        Record the pulse's kernel once with ``drjit.freeze`` and replay it at the next
        pulses instead of tracing it in Python at each (the same bytes; tests). None
        takes :data:`FREEZE`, and where that is None too, freezes on ``drjit.cuda`` only.
    precision : {"single", "double"}, optional
        Working precision of the scattering formulas (eqs P1-P7) in the kernel; None
        takes :data:`seaecho.scattering.facet.PRECISION`. The geometry, the delays, the
        carrier phase and the radar equation's magnitudes are float64 in either.

    Raises
    ------
    ValueError
        A variant that cannot run here, or a spectrum that is not a
        :class:`~seaecho.scattering.spectrum_table.BraggSpectrumTable` (a kernel needs
        the tabulated spectrum).
    """

    def __init__(self, radar: RadarSystem, facet_model: FacetModel, *,
                 variant: str | None = None, freeze: bool | None = None,
                 precision: str | None = None) -> None:
        if not isinstance(facet_model, FacetModel):
            raise ValueError("ResidentSea takes the sea as a scattering.facet.FacetModel "
                             "(SeaModel.facet_model)")
        if not isinstance(facet_model.spectrum, BraggSpectrumTable):
            raise ValueError("ResidentSea needs the Bragg spectrum as a BraggSpectrumTable")
        if np.ndim(facet_model.mss_upwind) or np.ndim(facet_model.mss_crosswind):
            raise ValueError("ResidentSea takes the sub-facet slope variances as numbers")
        self.xp = drjit_namespace(variant)
        #: the namespace of the scattering formulas (eqs P1-P7)
        self.xs = self.xp.with_precision(PRECISION if precision is None else precision)
        self.radar = radar
        #: the sea's scattering inputs (eqs P1-P7)
        self.facet_model = facet_model
        self.model = facet_model.model
        self.tilt = facet_model.tilt
        self._lo, self._hi = radar.window.bounds(radar.waveform.n_samples)
        self._surface: tuple[weakref.ref, dict] | None = None
        self._motion_cache: tuple[NDArray, dict] | None = None
        #: replay the recorded pulse kernel (``drjit.freeze``) instead of tracing it
        if freeze is None:
            freeze = self.xp.name == "cuda" if FREEZE is None else FREEZE
        self.freeze = bool(freeze)
        self._frozen = None
        self._bound = None
        #: why freezing was given up (a recording Dr.Jit refused), or None
        self.freeze_error: str | None = None

    def _mechanisms(self, io: Boundary, damping: Any, breaking: Any = None):
        """``(n_i, n_s, N) -> mechanisms`` with the sea's values as kernel constants, in
        the namespace :attr:`xs` of the scattering formulas: the values of
        :func:`seaecho.scattering.facet.kernel_sea` and ``facet_arrays``, the functions
        the reference path calls, so the same kernel values."""
        xs = self.xs  # the scattering precision's namespace (float32 by default)
        sea = kernel_sea(io, self.facet_model, xs)
        damping, breaking = facet_arrays(io, xs, damping, breaking)

        def of(n_i, n_s, normal, monostatic=False):
            return mechanisms(xs, n_i, n_s, normal, sea, damping=damping, breaking=breaking,
                              monostatic=monostatic)
        return of

    @staticmethod
    def n_facets(surface) -> int:
        """Number of facets of a surface state's grid [-]."""
        return facet_count(np.size(surface.x), np.size(surface.y))

    def _nodes(self, surface) -> dict[str, Any]:
        """The surface's node arrays on the device (copied once per surface state)."""
        if self._surface is not None and self._surface[0]() is surface:
            return self._surface[1]
        xp = self.xp
        io = Boundary(xp)
        nodes = dict(x=io.array(surface.x), y=io.array(surface.y),
                     z=io.array(np.asarray(surface.elevation, dtype=np.float64).reshape(-1)),
                     v=io.vec3(np.asarray(surface.velocity, dtype=np.float64).reshape(-1, 3)))
        xp.eval(*nodes.values())
        nodes["keep"] = io._keep  # the aligned buffers the LLVM back end aliases
        self._surface = (weakref.ref(surface), nodes)
        return nodes

    def echo(self, geometry: PulseGeometry, surface, hidden: tuple,
             draws: tuple[NDArray, NDArray] | dict[str, NDArray] | Callable,
             damping: NDArray | None = None, *, breaking: NDArray | None = None,
             motion: dict | None = None) -> ScattererEcho | DeviceEcho:
        """The sea facets' echo of one pulse.

        Parameters
        ----------
        geometry : PulseGeometry
            Platform states and antenna axes of the pulse.
        surface : seaecho.sea.SurfaceState
            The held surface (``x``, ``y``, ``elevation``, ``velocity`` on the grid); its
            nodes are copied to the device once, the facets' centroids, areas, normals
            and velocities are computed in the kernel
            (:func:`seaecho.geometry.mesh.facet_geometry_in`).
        hidden : (hidden_tx, hidden_rx)
            Occlusion masks (``FacetEngine.occlusion``), device arrays or numpy.
        draws : (g_K, g_B) or dict or callable
            Speckle draws of the sea state (N,) complex each (eq P4): ``(g_K, g_B)``, or
            one per mechanism (``"specular"``, ``"bragg"``, ``"bragg1"`` .. ``"bragg4"``
            with ``tilt``, ``"breaking"`` with ``breaking``); or the evolving sea's
            ``draws(xp, io, context)`` of the pulse's time
            (:meth:`seaecho.scattering.dynamics.EvolvingSpeckle.draws`), evaluated in the
            kernel.
        damping : (N,) array, optional
            Turbulent-wake damping in [0, 1].
        breaking : (N,) array, optional
            Fraction of each facet covered by breaking zones, in [0, 1] (eq P7).
        motion : dict, optional
            The evolving sea's phase centres (eq D1 of
            :mod:`seaecho.scattering.dynamics`): ``"displacement"`` (ny, nx, 2) the
            particles' horizontal displacement [m] and ``"acceleration"`` (ny, nx, 3)
            [m/s^2] or None at the surface's nodes (copied to the device once per such
            dict), ``"dt"`` the pulse's time after the surface's [s]. The facets' echoes
            then come from ``r + D + v dt + a dt^2 / 2`` (facet means of the nodes'
            values, :func:`~seaecho.scattering.dynamics.particle_centre`,
            :func:`~seaecho.scattering.dynamics.extrapolate`) instead of the centroids.
            An evolving pulse is traced, never frozen.

        Returns
        -------
        ScattererEcho
            On the CPU: ``tau`` and ``amplitudes`` (a list of C (K,) complex arrays) of
            the visible facets inside the window, numpy views of the kernel's output
            (ranges and gains are None).
        DeviceEcho
            On a GPU: the same, left on the device.
        """
        xp = self.xp
        nx, ny = np.size(surface.x), np.size(surface.y)
        n = facet_count(nx, ny)
        nodes = self._nodes(surface)
        io = Boundary(xp, n)
        # every per-facet input on the device before the kernel is traced (or replayed)
        inputs = dict(
            nodes=(nodes["x"], nodes["y"], nodes["z"], nodes["v"]),
            hidden=(self._mask(hidden[0]), self._mask(hidden[1])),
            draws=draws if callable(draws) else
            {m: io.complex(d) for m, d in self._draws(draws, n, breaking).items()},
            damping=None if damping is None else io.array(damping),
            breaking=None if breaking is None else io.array(breaking),
            table=self.facet_model.spectrum._values(self.xs))
        if motion is not None:
            inputs["motion"] = dict(self._motion(motion), dt=float(motion["dt"]))
        if callable(draws) or motion is not None:  # per-pulse anchors: traced
            tau, keep, packed = self._terms(xp, inputs, geometry, nx, ny)
        elif self.freeze:
            tau, keep, packed = self._frozen_terms(inputs, geometry, nx, ny)
        else:
            tau, keep, packed = self._terms(xp, inputs, geometry, nx, ny)
        c = len(packed)
        xp.eval(tau, keep, *packed)
        kept = xp.count(keep)
        if kept < n:  # hidden facets or echoes outside the window: compacted in order
            sel = xp.compress(keep)
            tau = xp.gather(tau, sel)
            out, j = [], xp.arange(kept)
            for buf in packed:
                new = xp.empty(2 * kept)
                xp.scatter(new, xp.gather(buf, sel, dtype=xp.module.Array2f64), j)
                out.append(new)
            packed = out
            xp.eval(tau, *packed)
            n = kept
        if xp.name == "cuda":
            return DeviceEcho(xp, tau, tuple(packed), c)
        amplitudes = [xp.host(b).view(np.complex128) for b in packed]
        return ScattererEcho(xp.host(tau), amplitudes, None, None, None, None, None, None)

    def _terms(self, xp, inputs: dict, geometry: PulseGeometry, nx: int, ny: int
               ) -> tuple[Any, Any, list]:
        """The pulse's kernel, traced: ``(tau, keep, packed channels)`` of every facet
        (:meth:`echo`; ``inputs`` are device values, ``xp`` the namespace, or the one with
        the geometry bound to inputs when frozen)."""
        n = facet_count(nx, ny)
        io = Boundary(xp, n)
        motion = inputs.get("motion")
        fields = None if motion is None else motion["nodes"]
        facets = facet_geometry_in(xp, *inputs["nodes"], nx, ny, fields)
        facets.update(hidden_tx=inputs["hidden"][0], hidden_rx=inputs["hidden"][1])
        if motion is not None:  # eq D1: the particles' positions at the pulse's time
            centre = particle_centre(facets["centroid"], (facets.pop("dx"), facets.pop("dy")),
                                     xp)
            acc = None
            if "ax" in fields:
                acc = xp.vec(facets.pop("ax"), facets.pop("ay"), facets.pop("az"))
            facets["position"] = extrapolate(centre, facets["velocity"], acc, motion["dt"],
                                             xp)
        t = sea_echo_terms(xp, self.radar, geometry, facets,
                           self._mechanisms(io, inputs["damping"], inputs["breaking"]),
                           inputs["draws"], self._lo, self._hi, scattering=self.xs,
                           wavenumber=float(self.facet_model.k))
        # Each channel packed as the memory of a complex (N,) array, in the kernel (one
        # buffer per channel: scatters into distinct arrays share the kernel)
        idx = xp.arange(n)
        packed = []
        for a in t["amplitudes"]:
            buf = xp.empty(2 * n)
            xp.scatter(buf, xp.pair(xp.real(a), xp.imag(a)), idx)
            packed.append(buf)
        return t["tau"], t["keep"], packed

    def _frozen_terms(self, inputs: dict, geometry: PulseGeometry, nx: int, ny: int
                      ) -> tuple[Any, Any, list]:
        """:meth:`_terms` through ``drjit.freeze``: recorded at the first pulse (and again
        when the grid, the inputs' types or the monostatic flag change), replayed at the
        next ones without tracing.

        The pulse's platform vectors (positions, receiver velocity, vertical axes, antenna
        axes), the only values of the kernel that change from pulse to pulse, enter as
        inputs: while recording, ``vconst`` of the geometry's arrays (or views of them)
        returns those inputs (:class:`_BoundGeometry`), so a replay computes with the
        current pulse's values. Everything else the kernel reads is an input too (Dr.Jit
        refuses a recording that uses a variable it was not given).
        """
        xp = self.xp
        tx, rx = geometry.tx, geometry.rx
        plain = (tx.position, rx.position, rx.velocity, tx.rotation, rx.rotation,
                 geometry.tx_axes, geometry.rx_axes)
        if not all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in plain):
            return self._terms(xp, inputs, geometry, nx, ny)  # views could not be bound
        arrays = {"tx_position": tx.position, "rx_position": rx.position,
                  "rx_velocity": rx.velocity, "tx_up": tx.rotation[:, 2],
                  "rx_up": rx.rotation[:, 2]}
        for side, axes in (("tx", geometry.tx_axes), ("rx", geometry.rx_axes)):
            for j in range(3):
                arrays[f"{side}_axis{j}"] = np.asarray(axes, dtype=np.float64)[:, j]
        values = {name: xp.vconst(a) for name, a in arrays.items()}
        self._bound = (geometry, {_view_key(a): values[name] for name, a in arrays.items()},
                       plain)
        monostatic = bool(np.array_equal(tx.position, rx.position))
        if self._frozen is None:
            self._frozen = xp.dr.freeze(self._record, warn_after=FREEZE_WARN_AFTER)
        try:
            with no_garbage_collection():
                return self._frozen({**inputs, "geometry": values}, nx, ny, monostatic)
        except RuntimeError as exc:  # a kernel Dr.Jit cannot record: traced from now on
            self.freeze, self._frozen, self.freeze_error = False, None, str(exc)
            return self._terms(xp, inputs, geometry, nx, ny)
        finally:
            self._bound = None

    def _record(self, inputs: dict, nx: int, ny: int, monostatic: bool
                ) -> tuple[Any, Any, list]:
        """The frozen function's body: :meth:`_terms` with the geometry bound."""
        geometry, bindings, arrays = self._bound
        return self._terms(_BoundGeometry(self.xp, bindings, arrays), inputs, geometry,
                           nx, ny)

    def sigma_cells(self, geometry: PulseGeometry, surface, hidden: tuple,
                    damping: NDArray | None = None, *, breaking: NDArray | None = None
                    ) -> tuple[NDArray, NDArray]:
        """NRCS of each grid cell and its visibility, as one kernel (the sigma map).

        The quantities of ``SeaEcho.sigma0_cells`` and ``Facets.cell_mean("visibility")``
        of the reference path: per facet ``sigma_mn`` (eq P3,
        :func:`seaecho.scattering.facet.mechanism_sigma`) times the visibility, times the
        area, summed over the cell's two triangles and divided by the cell's horizontal
        area.

        Parameters
        ----------
        geometry, surface, hidden, damping, breaking
            As :meth:`echo`.

        Returns
        -------
        sigma0 : ndarray (4, ny - 1, nx - 1)
            HH, HV, VH, VV per unit horizontal area [m^2/m^2].
        visibility : ndarray (ny - 1, nx - 1)
            Mean of the two triangles' visibility [-].
        """
        xp = self.xp
        nx, ny = np.size(surface.x), np.size(surface.y)
        n = facet_count(nx, ny)
        nodes = self._nodes(surface)
        io = Boundary(xp, n)
        facets = facet_geometry_in(xp, nodes["x"], nodes["y"], nodes["z"], nodes["v"], nx, ny)
        facets.update(hidden_tx=self._mask(hidden[0]), hidden_rx=self._mask(hidden[1]))
        visible, n_i, n_s = facet_visibility(xp, geometry, facets)
        vis = xp.select(visible, xp.const(1.0), xp.const(0.0))
        xs = self.xs
        mech = self._mechanisms(io, damping, breaking)(
            xs.cast(n_i), xs.cast(n_s), xs.cast(facets["normal"]),
            monostatic=bool(np.array_equal(geometry.tx.position, geometry.rx.position)))
        sigma = mechanism_sigma(xs, mech)
        sig, vis_h, area = io.numpy(sigma, vis, facets["area"])
        rcs = sig.reshape(n, 4) * vis_h[:, None] * area[:, None]  # [m^2] per facet
        grid = (ny - 1, nx - 1, 2)
        dx = float(surface.x[1] - surface.x[0])
        dy = float(surface.y[1] - surface.y[0])
        sigma0 = np.moveaxis(rcs.reshape(grid + (4,)).sum(axis=2), -1, 0) / (dx * dy)
        return sigma0, vis_h.reshape(grid).mean(axis=2)

    def _motion(self, motion: dict) -> dict:
        """The evolving sea's node fields on the device: ``{"nodes": {"dx", "dy"[, "ax",
        "ay", "az"]}}`` (copied once per ``motion["displacement"]`` array)."""
        disp = motion["displacement"]
        if self._motion_cache is not None and self._motion_cache[0] is disp:
            return self._motion_cache[1]
        xp = self.xp
        io = Boundary(xp)
        nodes = {name: io.array(np.ascontiguousarray(disp[..., i], dtype=np.float64)
                                .reshape(-1)) for i, name in enumerate(("dx", "dy"))}
        acc = motion.get("acceleration")
        if acc is not None:
            nodes.update({name: io.array(np.ascontiguousarray(acc[..., i], dtype=np.float64)
                                         .reshape(-1))
                          for i, name in enumerate(("ax", "ay", "az"))})
        xp.eval(*nodes.values())
        out = {"nodes": nodes, "keep": io._keep}
        self._motion_cache = (disp, out)
        return out

    def _draws(self, draws: Any, n: int, breaking: Any) -> dict[str, NDArray]:
        """The draws as ``{mechanism: (N,) complex}``, one for each of the model's
        mechanisms (a clear error for a missing one or a wrong shape)."""
        names = ([] if self.model == "spm" else ["specular"])
        if self.model != "kirchhoff":
            names += ["bragg"] + ([] if self.tilt is None else
                                  [f"bragg{j + 1}" for j in range(len(self.tilt.slopes))])
        if breaking is not None:
            names.append("breaking")
        if isinstance(draws, dict):
            d = draws
        else:
            g_k, g_b = draws
            d = {"specular": g_k, "bragg": g_b}
        missing = [m for m in names if m not in d]
        if missing:
            raise ValueError(f"draws: none given for the mechanisms {missing}")
        for m in names:
            shape = self._shape(d[m])
            if shape != (n,):
                raise ValueError(f"draws of shape {shape} for {m!r}: need ({n},)")
        return {m: d[m] for m in names}

    def _shape(self, a: Any) -> tuple[int, ...]:
        """Shape of a numpy input, (width,) of a value already on the device."""
        if isinstance(a, self.xp.Complex | self.xp.Float):
            return (self.xp.width(a),)
        return np.shape(a)

    def _mask(self, hidden: Any) -> Any:
        if isinstance(hidden, np.ndarray):
            return self.xp.Bool(np.ascontiguousarray(hidden, dtype=bool))
        return hidden


def resident_sea(radar: RadarSystem, tracing, sea_model) -> ResidentSea | None:
    """The fused sea echo of a simulation, or None where the reference path runs.

    The kernel covers ray-traced facets (visibility = facing and not occluded) of a held
    or an evolving sea (``sea_model.dynamics``: phase centres carried between updates,
    speckle of each pulse's time; :meth:`ResidentSea.echo`, ``motion``). Analytic facets
    (Smith's statistical visibility) and the sub-facet shadowing are evaluated by numpy
    functions of the geometry stage, so those scenes keep the reference path, as do
    machines where Dr.Jit's CPU back end does not run.

    Parameters
    ----------
    radar : RadarSystem
    tracing : seaecho.tracing.model.TracingModel or None
    sea_model : seaecho.scattering.sea_model.SeaModel or None

    Raises
    ------
    ValueError
        A ``[tracing] variant`` that cannot run here (a CUDA variant without a GPU, or one
        that differs from the variant Mitsuba already runs): at the start of a run.
    """
    from ..backend import check_variant, drjit_available

    if tracing is None or sea_model is None:
        return None
    variant = check_variant(tracing.variant)  # a clear error now, not mid-run
    if tracing.mode != "raytraced" or tracing.subfacet is not None:
        return None
    if radar.model.multipath is not None:  # the two-ray factors: the reference path
        return None
    if variant.startswith("llvm") and not drjit_available():
        return None
    return ResidentSea(radar, sea_model.facet_model, variant=variant)
