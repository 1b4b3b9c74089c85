"""Multistatic simulation: one transmitter, several receivers over the same sea.

A scene with ``[[receivers]]`` is simulated as one bistatic pair per receiver
(:func:`seaecho.build.receiver_scene`: the scene with that receiver as its
``[receiver]``), over one sea. What does not depend on the receiver is computed once per
sea update or occlusion refresh and shared by every pair
(:meth:`seaecho.simulation.Simulation.share_sea`):

* the sea surface and wake of each block (``Sea.state``: the spectral synthesis), the
  facets' geometry (centroids, areas, normals, velocities), the wake damping and breaking
  placement;
* the per-facet speckle draws (``speckle``, ``speckle-tilt``, ``breaking`` streams keyed
  by the block index, or the evolving sea's anchors): they do not depend on the receiver
  or its index, so every receiver sees the same sub-facet realisation;
* the ray-traced occlusion of the transmitter's leg and the sea's BVH
  (:meth:`seaecho.tracing.engine.FacetEngine.share_transmitter`).

Each receiver then traces its own leg, evaluates the per-facet bistatic scattering
(which depends on both the incidence and the scattering direction, eqs P1-P4 of
``scattering.facet``), its antenna gains and ranges (eq R1) and accumulates its samples
(eq E2) in its own receive window, with its own noise. So receiver i's samples are those
of the bistatic run of :func:`~seaecho.build.receiver_scene` bit for bit, given the same
seed and its window (``window_start_m``/``window_end_m`` of the dataset), and with its
path errors drawn from ``"platform"`` stream index 1 + i (receiver 0: as ``[receiver]``).

Receive windows: with ``[radar] window_start_m/window_end_m`` every receiver has that
window. Otherwise each receiver's window starts where its own automatic window does
(:meth:`seaecho.radar.system.RadarSystem.auto_window_m`) and all have the length of the
longest, so that the samples stack along a ``sample`` axis with a fast-time coordinate
per receiver.

The dataset (:meth:`MultistaticSimulation.static_dataset`, docs/multistatic.md):
``raw`` and ``compressed`` (pulse, receiver, channel, sample); ``fast_time`` and
``range`` (receiver, sample); ``rx_*`` tracks, ``sigma0`` and ``visibility`` and the hull
echoes' truth per receiver; ``bistatic_angle`` (receiver, pulse) at the tile centre. The
channel axis is the union of the receivers' channels; a channel a receiver does not record
holds NaN (``recorded`` (receiver, channel) says which), the documented no-data value.
A scene with ``[receiver]`` is not multistatic and keeps the bistatic layout.
"""

from __future__ import annotations

import dataclasses
import json
import os
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .build import MultistaticModels, build_multistatic
from .constants import C0
from .geometry.bistatic import bistatic_angle
from .radar.echo import ReceiveWindow
from .radar.model import RadarModel
from .radar.system import RadarSystem
from .simulation import Simulation

#: Dimensions of ``raw`` and ``compressed`` in a multistatic dataset.
MULTISTATIC_DIMS = ("pulse", "receiver", "channel", "sample")
#: Static variables that differ between receivers (besides every ``rx_*`` track and the
#: hulls' scattering centres, which are concatenated along ``centre``).
PER_RECEIVER = ("sigma0", "visibility", "wake_mask", "hull_rcs", "hull_rcs_free_space",
                "hull_trace_pulse")


def simulation_of(scene, base_dir: str | os.PathLike = "."):
    """The simulation of a scene: a :class:`MultistaticSimulation` with ``[[receivers]]``,
    else a :class:`seaecho.simulation.Simulation`."""
    if getattr(scene, "receivers", ()):
        return MultistaticSimulation(scene, base_dir)
    return Simulation(scene, base_dir)


def common_windows(radars: Sequence[RadarModel]) -> list[RadarModel]:
    """The receivers' radars with receive windows of one length (module docstring).

    Parameters
    ----------
    radars : sequence of RadarModel
        One per receiver, the same transmitter, pulses and sampling.

    Returns
    -------
    list of RadarModel
        With ``window_m`` set: the scene's window for all when it gives one; otherwise
        receiver i's automatic start and the longest automatic length, widened by whole
        samples where rounding left one window a sample shorter.
    """
    if radars[0].window_m is not None:
        return list(radars)
    spans = [RadarSystem(r).auto_window_m() for r in radars]
    starts = [s for s, _ in spans]
    length = max(e - s for s, e in spans)
    fs, duration = radars[0].sampling_rate, radars[0].waveform.duration
    ends = [s + length for s in starts]
    for _ in range(4):  # ceil of float lengths may differ by one sample
        n = [ReceiveWindow.from_ranges(s, e, fs, duration).n_samples
             for s, e in zip(starts, ends, strict=True)]
        if len(set(n)) == 1:
            break
        ends = [e + (0.5 * C0 / fs if k < max(n) else 0.0)
                for e, k in zip(ends, n, strict=True)]
    else:
        raise ValueError(f"receive windows of {sorted(set(n))} samples could not be made "
                         "equal")
    return [dataclasses.replace(r, window_m=(s, e))
            for r, s, e in zip(radars, starts, ends, strict=True)]


class MultistaticSimulation:
    """A scene's multistatic simulation (module docstring).

    :func:`simulation_of` returns one for a scene with ``[[receivers]]``; it has the
    interface the runners use (:meth:`pulses`,
    :meth:`block_edges`, :meth:`static_dataset`, :meth:`run`, :meth:`dataset`).

    Parameters
    ----------
    scene : seaecho.config.Scene
        With ``[[receivers]]``; read only by the builder.
    base_dir : path
        Folder of the scene file.
    """

    def __init__(self, scene, base_dir: str | os.PathLike = ".") -> None:
        self._setup(build_multistatic(scene, base_dir))

    @classmethod
    def from_models(cls, models: MultistaticModels) -> MultistaticSimulation:
        """A simulation of prebuilt stage models (:func:`seaecho.build.build_multistatic`)."""
        sim = cls.__new__(cls)
        sim._setup(models)
        return sim

    def _setup(self, models: MultistaticModels) -> None:
        self.models = models
        #: receiver names, the ``receiver`` coordinate
        self.names = models.names
        radars = common_windows([m.radar for m in models.receivers])
        sims: list[Simulation] = []
        for m, r in zip(models.receivers, radars, strict=True):
            sim = Simulation.from_models(dataclasses.replace(m, radar=r))
            if sims:
                sim.share_sea(sims[0])
            sims.append(sim)
        #: one bistatic Simulation per receiver; the first holds the shared sea
        self.receivers: tuple[Simulation, ...] = tuple(sims)
        lead = sims[0]
        self.radar = lead.radar  # pulses, PRF, transmitter (the same for every receiver)
        self.block = lead.block
        self.sea = lead.sea
        names: list[str] = []
        for s in sims:
            names += [c for c in s.radar.channel_names if c not in names]
        #: the channel axis: the union of the receivers' channels
        self.channels: tuple[str, ...] = tuple(names)
        self._slots = [np.array([names.index(c) for c in s.radar.channel_names])
                       for s in sims]

    @property
    def shape(self) -> tuple[int, int, int, int]:
        """(pulses, receivers, channels, samples) of ``raw`` and ``compressed``."""
        return (self.radar.n_pulses, len(self.receivers), len(self.channels),
                self.radar.window.n_samples)

    # ------------------------------------------------------------------- pulses
    def pulses(self, start: int, stop: int) -> tuple[NDArray[np.complex128],
                                                     NDArray[np.complex128]]:
        """Raw and range-compressed samples of pulses ``start`` to ``stop - 1``, each
        (stop - start, receivers, channels, samples) [sqrt(W)], NaN in the channels a
        receiver does not record.

        Pulse by pulse, every receiver in turn (the shared sea, speckle and transmitter
        occlusion of a block are computed by the first and reused by the others).
        """
        lead = self.receivers[0]
        n = stop - start
        raw = np.full((n, *self.shape[1:]), complex(np.nan, np.nan), dtype=np.complex128)
        for p in range(start, stop):
            if p + 1 < stop and lead.sea is not None:
                lead.surface_state(p)
                lead.prefetch_surface(p + 1)
            for i, sim in enumerate(self.receivers):
                raw[p - start, i, self._slots[i]] = sim.pulse(p)
        compressed = raw.copy()
        for i, sim in enumerate(self.receivers):
            compressed[:, i, self._slots[i]] = sim.compress(raw[:, i, self._slots[i]])
        return raw, compressed

    def block_edges(self) -> NDArray[np.int64]:
        """As :meth:`seaecho.simulation.Simulation.block_edges` (the same for every
        receiver: the sea and the occlusion refresh are the transmitter's and the sea's)."""
        return self.receivers[0].block_edges()

    # ------------------------------------------------------------------ dataset
    def static_dataset(self):
        """Everything but the pulses, with a ``receiver`` dimension (module docstring)."""
        import xarray as xr

        from .checks.guards import check_dataset

        parts = [s.static_dataset() for s in self.receivers]
        first = parts[0]
        recv = ("receiver", list(self.names))
        data, coords = {}, {}
        for name, var in first.data_vars.items():
            if "centre" in var.dims:
                data[name] = xr.concat([p[name] for p in parts], dim="centre")
            elif name.startswith("rx_") or name in PER_RECEIVER:
                data[name] = xr.concat([p[name] for p in parts], dim="receiver")
            else:
                data[name] = var
        if "hull_centre_path" in first:
            data["hull_centre_receiver"] = (
                ("centre",), np.concatenate([np.full(p.sizes["centre"], i, dtype=np.int16)
                                             for i, p in enumerate(parts)]),
                {"long_name": "index of the receiver whose pair these centres serve"})
        fast = np.stack([s.radar.window.fast_time for s in self.receivers])
        coords.update({
            "receiver": (recv[0], np.array(recv[1]), {"long_name": "receiver name"}),
            "channel": ("channel", np.array(self.channels),
                        {"long_name": "receive port, transmit port"}),
            "fast_time": (("receiver", "sample"), fast,
                          {"units": "s", "long_name": "delay after emission"}),
            "range": (("receiver", "sample"), 0.5 * C0 * fast,
                      {"units": "m", "long_name": "c * delay / 2 (half bistatic path)"}),
        })
        recorded = np.zeros((len(self.receivers), len(self.channels)), dtype=bool)
        for i, slots in enumerate(self._slots):
            recorded[i, slots] = True
        t = self.radar.emission_time(np.arange(self.radar.n_pulses))
        tx = self.radar.tx.state(t).position
        beta = np.stack([bistatic_angle(tx, s.radar.rx.state(t).position, np.zeros(3))
                         for s in self.receivers])
        windows = np.array([s.models.radar.window_m for s in self.receivers], dtype=float)
        data.update({
            "recorded": (("receiver", "channel"), recorded,
                         {"long_name": "whether the receiver records the channel (else NaN)"}),
            "window_start_m": (("receiver",), windows[:, 0], {"units": "m"}),
            "window_end_m": (("receiver",), windows[:, 1], {"units": "m"}),
            "window_t0_s": (("receiver",), fast[:, 0],
                            {"units": "s", "long_name": "delay of the first sample"}),
            "bistatic_angle": (("receiver", "pulse"), beta, {
                "units": "rad", "long_name": "bistatic angle at the tile centre (0, 0, 0) "
                "between the directions to the transmitter and to the receiver"}),
        })
        keep = {k: v for k, v in first.coords.items()
                if k not in ("channel", "fast_time", "range") and "fast_time" not in v.dims}
        ds = xr.Dataset(data, coords={**keep, **coords})
        ds.attrs = {k: v for k, v in first.attrs.items() if k not in ("window_t0_s",
                                                                        "monostatic")}
        ds.attrs.update({"multistatic": 1, "n_receivers": len(self.receivers),
                         "monostatic": 0,
                         "receiver_note": "one transmitter, several receivers over one sea "
                         "realisation and one set of sub-facet draws (docs/multistatic.md)"})
        check_dataset(ds)
        return ds

    # ---------------------------------------------------------------------- run
    def run(self, path: str | os.PathLike, progress: bool = True, chunk: int | None = None,
            resume: bool = False, runner=None) -> Path:
        """Simulate every pulse for every receiver and write the dataset to ``path``
        (netCDF, or a resumable Zarr store): as
        :meth:`seaecho.simulation.Simulation.run`."""
        from .io.run import write_run

        return write_run(path, self.static_dataset, identity=self.models.attrs,
                         progress=progress, resume=resume, **self._blocks(chunk, runner))

    def dataset(self, progress: bool = True, chunk: int | None = None, runner=None):
        """The dataset that :meth:`run` writes, in memory (the same values bit for bit)."""
        from .io.run import run_in_memory

        return run_in_memory(self.static_dataset(), progress=progress,
                             **self._blocks(chunk, runner))

    def _blocks(self, chunk: int | None, runner) -> dict:
        from .io.run import SerialBlocks, block_size

        return {"shape": self.shape, "dims": MULTISTATIC_DIMS,
                "block": block_size(self.block_edges(), chunk),
                "runner": SerialBlocks(self.pulses) if runner is None else runner,
                "weighting": self.receivers[0].models.radar.range_weighting}


def receiver_dataset(ds, receiver: str | int, *, receiver_scene: bool = True):
    """One receiver of a multistatic dataset in the bistatic layout of ``seaecho run``
    (``raw``/``compressed`` (pulse, channel, fast_time), ``rx_*`` tracks and antenna,
    ``sigma0``...), its unrecorded channels left out: what ``seaecho image`` and the other
    readers of a bistatic run take.

    Parameters
    ----------
    ds : xarray.Dataset
        A multistatic run (``ds.attrs["multistatic"] == 1``).
    receiver : str or int
        The receiver's name or index.
    receiver_scene : bool
        Give ``scene_json`` the receiver's bistatic scene (parsed from the run's, so only
        a scene this seaecho can read); False keeps the run's scene as it is (the image
        processor reads the raw product only, docs/products.md).
    """
    if not int(ds.attrs.get("multistatic", 0)):
        raise ValueError("not a multistatic run (no receiver dimension)")
    names = [str(n) for n in ds["receiver"].values]
    if isinstance(receiver, str):
        if receiver not in names:
            raise ValueError(f"receiver = {receiver!r}: the run has {', '.join(names)}")
        index = names.index(receiver)
    else:
        index = int(receiver)
        if not 0 <= index < len(names):
            raise ValueError(f"receiver = {receiver}: the run has {len(names)} receivers")
    one = ds.isel(receiver=index)
    one = one.isel(channel=np.flatnonzero(one["recorded"].values))
    if "hull_centre_receiver" in one:
        one = one.isel(centre=np.flatnonzero(one["hull_centre_receiver"].values == index))
        one = one.drop_vars("hull_centre_receiver")
    fast = one["fast_time"].values
    one = one.drop_vars(["fast_time", "range", "recorded", "window_t0_s", "window_start_m",
                         "window_end_m", "bistatic_angle", "receiver"])
    one = one.rename({"sample": "fast_time"}).assign_coords(
        fast_time=("fast_time", fast, {"units": "s", "long_name": "delay after emission"}),
        range=("fast_time", 0.5 * C0 * fast,
               {"units": "m", "long_name": "c * delay / 2 (half bistatic path)"}))
    attrs = {k: v for k, v in ds.attrs.items()
             if k not in ("multistatic", "n_receivers", "receiver_note")}
    attrs.update(window_t0_s=float(fast[0]), monostatic=0, receiver=names[index],
                 multistatic_scene_json=ds.attrs["scene_json"],
                 scene_json=(_receiver_scene_json(ds.attrs["scene_json"], index)
                             if receiver_scene else ds.attrs["scene_json"]))
    one.attrs = attrs
    return one


def image_multistatic(ds, config=None, *, backend: str = "drjit", progress: bool = False,
                      timings: dict | None = None):
    """Focus every receiver of a multistatic run and combine them incoherently.

    Each receiver's data are focused as a bistatic run (:func:`receiver_dataset`,
    :func:`seaecho.imaging.focus.focus`: backprojection along the transmitter-receiver
    pair's delays (r_t + r_r) / c, calibrated with the pair's radar equation) on the
    grid of ``config``, the same for every receiver (its extent is the sea tile or the
    targets' box, not a receiver's). The multistatic image is their incoherent
    combination on that grid: the mean over the receivers that record a channel of the
    calibrated intensities, ``fused_sigma0 = <sigma0_i>`` [m^2/m^2] and
    ``fused_rcs = <|image_i|^2>`` [m^2] (non-coherent multistatic combination: Willis
    and Griffiths, *Advances in Bistatic Radar*, 2007, ch. 9; the pairs' speckle is
    independent where their bistatic geometries differ, so it averages down).

    Parameters
    ----------
    ds : xarray.Dataset
        A multistatic run (:class:`MultistaticSimulation`).
    config : seaecho.config.image.ImageConfig, optional
        The processing (default all defaults).
    backend, progress, timings
        As :func:`seaecho.imaging.focus.focus` (``timings`` gets each receiver's under
        its name).

    Returns
    -------
    xarray.Dataset
        The receivers' image datasets stacked along ``receiver`` (the channel axis the
        union, NaN where a receiver does not record a channel), plus ``fused_sigma0`` and
        ``fused_rcs`` (channel, y, x) and ``fused_receivers`` (channel,) the number of
        receivers combined.
    """
    import xarray as xr

    from .checks.guards import check_image
    from .imaging.focus import focus

    names = [str(n) for n in ds["receiver"].values]
    images = []
    for name in names:
        own: dict = {}
        img = focus(receiver_dataset(ds, name, receiver_scene=False), config,
                    backend=backend, progress=progress, timings=own)
        check_image(img, f"receiver {name}")  # Inf, or NaN at a defined pixel
        if timings is not None:
            timings[name] = own
        images.append(img)
    out = xr.concat(images, dim="receiver", join="outer", data_vars="all",
                    coords="minimal", compat="override", combine_attrs="override")
    out = out.assign_coords(receiver=("receiver", np.array(names),
                                      {"long_name": "receiver name"}))
    sigma0 = out["sigma0"].astype(np.float64)
    rcs = np.abs(out["image"].astype(np.complex128)) ** 2
    count = np.isfinite(sigma0).any(dim=("y", "x")).sum("receiver")
    out["fused_sigma0"] = sigma0.mean("receiver", skipna=True).astype(np.float32).assign_attrs(
        units="m2 m-2", long_name="incoherent multistatic combination: mean of the "
        "receivers' calibrated sigma0")
    out["fused_rcs"] = rcs.mean("receiver", skipna=True).astype(np.float32).assign_attrs(
        units="m2", long_name="incoherent multistatic combination: mean of the receivers' "
        "|image|^2")
    out["fused_receivers"] = count.astype(np.int16).assign_attrs(
        long_name="receivers combined per channel")
    out.attrs.update(multistatic=1, n_receivers=len(names),
                     scene_json=ds.attrs["scene_json"],
                     fusion="incoherent: mean of the receivers' calibrated intensities")
    return out


def receiver_image(img, receiver: str | int):
    """One receiver's image of :func:`image_multistatic`, in the layout of a bistatic
    image (its recorded channels only)."""
    names = [str(n) for n in img["receiver"].values]
    index = names.index(receiver) if isinstance(receiver, str) else int(receiver)
    one = img.isel(receiver=index).drop_vars(
        ["receiver", "fused_sigma0", "fused_rcs", "fused_receivers"])
    keep = np.flatnonzero(np.isfinite(one["sigma0"].values).any(axis=(1, 2)))
    one = one.isel(channel=keep)
    one.attrs = {k: v for k, v in img.attrs.items()
                 if k not in ("multistatic", "n_receivers", "fusion")}
    one.attrs["receiver"] = names[index]
    return one


def multistatic_figures(img, stem: str | os.PathLike, dynamic_range_db: float = 50.0
                        ) -> list[Path]:
    """Figures of :func:`image_multistatic`: every receiver's (``<stem>_<name>_*.png``,
    :func:`seaecho.plotting.image.image_figures`) and the incoherent combination's,
    ``<stem>_fused_sigma0.png`` (or ``_fused_rcs.png`` without sea), on one dB scale per
    figure."""
    from .plotting.image import image_figures, sigma0_figure

    out: list[Path] = []
    for name in img["receiver"].values:
        out += image_figures(receiver_image(img, str(name)), f"{stem}_{name}",
                             dynamic_range_db)
    first = img.isel(receiver=0).drop_vars("receiver")
    first = first.assign(sigma0=img["fused_sigma0"],
                         image=np.sqrt(img["fused_rcs"]).astype(np.complex64))
    first["valid"] = img["valid"].max("receiver") if "receiver" in img["valid"].dims else \
        img["valid"]
    if "tile" in img:
        out.append(sigma0_figure(first, f"{stem}_fused_sigma0.png",
                                 dynamic_range_db=dynamic_range_db))
    else:
        out.append(sigma0_figure(first, f"{stem}_fused_rcs.png", "rcs", dynamic_range_db))
    return out


def _receiver_scene_json(scene_json: str, index: int) -> str:
    """The JSON of receiver ``index``'s bistatic scene (:func:`seaecho.build.receiver_scene`)
    of a multistatic scene's JSON: what the readers of a bistatic run parse (antennas)."""
    from .build import receiver_scene
    from .config import parse_scene
    from .io.dataset import scene_attrs

    scene = parse_scene(json.loads(scene_json), source="the dataset's scene_json")
    return scene_attrs(receiver_scene(scene, index))["scene_json"]


__all__ = ["MULTISTATIC_DIMS", "PER_RECEIVER", "MultistaticSimulation",
           "common_windows", "image_multistatic", "multistatic_figures", "receiver_dataset",
           "receiver_image", "simulation_of"]
