"""The dataset of ``seaecho run``: static part (coordinates, tracks, truth) and the
streamed pulses.

Layout: ``raw`` and ``compressed`` (pulse, channel, fast_time) complex [sqrt(W)], with
``|raw|^2`` the received power [W]; platform tracks (true and nominal) per pulse; the
targets; with sea clutter, the surface, wake and the NRCS map ``sigma0`` of the
sigma-map pulse; attributes with the full scene and the radar's parameters.

``sigma0`` (polarisation, y_cell, x_cell) is the normalised radar cross section per unit
*horizontal* area of each grid cell [m^2/m^2]: the mean radar cross section of the cell's
two facets (sigma_mn per facet area times facet area times visibility) divided by the
cell's horizontal area dx dy. Its mean over the cells is the scene's sigma0, the quantity
``seaecho sigma`` gives for the mean plane.
"""

from __future__ import annotations

import contextlib
import os
import warnings
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

from ..constants import C0
from ..conventions import CHANNELS
from .product import PRODUCT_VERSION, antenna_variables
from .pulses import COMPRESSED_ATTRS, PULSE_DIMS, RAW_ATTRS, blocks_of
from .zarr_run import is_zarr, write_block, write_zarr_run


def run_dataset(radar, attrs: dict, truth: dict | None = None, x=None, y=None,
                extra_attrs: dict | None = None, extra: tuple[dict, dict] | None = None):
    """Everything of a run's dataset but the pulses.

    Parameters
    ----------
    radar : seaecho.radar.system.RadarSystem
        The radar (pulses, window, platforms, targets of its model).
    attrs : dict
        Attributes that say how the file was made (``seaecho.build.scene_attrs``).
    truth : dict, optional
        ``Simulation.sea_truth()``: surface state, ``sigma0`` cells, ``visibility``,
        ``ship_position``.
    x, y : arrays, optional
        Grid node coordinates [m] (with ``truth``).
    extra_attrs : dict, optional
        More attributes (sea update, tracing mode, ...).
    extra : (dict, dict), optional
        More variables and their coordinates, as xarray takes them (e.g. the hulls'
        ground truth, ``seaecho.tracing.hull_echo.HullEchoes.truth``).

    Returns
    -------
    xarray.Dataset
    """
    import xarray as xr

    pulses = np.arange(radar.n_pulses)
    t = radar.emission_time(pulses)
    fast = radar.window.fast_time
    coords = {
        "pulse": ("pulse", pulses, {"long_name": "pulse index"}),
        "time": ("pulse", t, {"units": "s", "long_name": "emission time"}),
        "channel": ("channel", np.array(radar.channel_names),
                    {"long_name": "receive port, transmit port"}),
        "fast_time": ("fast_time", fast,
                      {"units": "s", "long_name": "delay after emission"}),
        "range": ("fast_time", 0.5 * C0 * fast,
                  {"units": "m", "long_name": "c * delay / 2 (half bistatic path)"}),
        "xyz": ("xyz", np.array(["x", "y", "z"])),
    }
    data = {}
    for name, platform in (("tx", radar.tx), ("rx", radar.rx)):
        true, nominal = platform.state(t), platform.nominal_state(t)
        for kind, st in (("", true), ("_nominal", nominal)):
            data[f"{name}_position{kind}"] = (("pulse", "xyz"), st.position, {"units": "m"})
            data[f"{name}_velocity{kind}"] = (("pulse", "xyz"), st.velocity,
                                              {"units": "m s-1"})
            data[f"{name}_attitude{kind}"] = (
                ("pulse", "angle"), st.attitude,
                {"units": "rad", "long_name": "yaw, pitch, roll"})
            # Antenna axes in the world (image calibration: gains towards each pixel)
            pointing = radar.tx_pointing if name == "tx" else radar.rx_pointing
            data[f"{name}_antenna_axes{kind}"] = (
                ("pulse", "xyz", "antenna_axis"), pointing.axes(st, t),
                {"units": "1", "long_name": "antenna axes (columns boresight, width, "
                 "height) in the world; d_local = axes^T d_world"})
    scan, scanner = radar.tx_pointing.scan, "tx"
    if scan is None:
        scan, scanner = radar.rx_pointing.scan, "rx"
    if scan is not None:  # a scanning antenna: its angle and sweep at every pulse
        data["scan_azimuth"] = (("pulse",), scan.azimuth(t), {
            "units": "rad", "long_name": "scanning antenna's boresight azimuth in the "
            "body frame, counter-clockwise from body x"})
        data["sweep"] = (("pulse",), scan.sweep(t), {
            "units": "1", "long_name": "sweep index (revolution or sector pass) since t = 0",
            "scan_mode": scan.mode, "scan_period_s": scan.period, "scan_antenna": scanner})
    for name, antenna in (("tx", radar.tx_antenna), ("rx", radar.rx_antenna)):
        data.update(antenna_variables(name, antenna))  # the product's gain patterns
    coords["angle"] = ("angle", np.array(["yaw", "pitch", "roll"]))
    coords["antenna_axis"] = ("antenna_axis", np.array(["boresight", "width", "height"]))
    targets = radar.model.targets
    if targets is not None and len(targets):
        data["target_position"] = (("target", "xyz"), targets.positions,
                                   {"units": "m", "long_name": "target position at t = 0"})
        data["target_velocity"] = (("target", "xyz"), targets.velocities, {"units": "m s-1"})
        data["target_scattering"] = (("target", "polarisation"),
                                     targets.scattering.reshape(-1, 4),
                                     {"units": "m", "long_name": "s_mn, |s|^2 = RCS"})
        if targets.swerling is not None:
            data["target_swerling"] = (("target",), targets.swerling, {
                "long_name": "Swerling case (0 steady; target_scattering is the mean)"})
            data["target_dwell_pulses"] = ((), int(targets.dwell_pulses), {
                "long_name": "pulses per dwell (Swerling 1, 3: one RCS per dwell)"})
        coords["target"] = ("target", np.array(targets.names))
    if truth is not None:
        st = truth["state"]
        data.update({
            "elevation": (("y", "x"), st.elevation,
                          {"units": "m", "long_name": "sea + wake height at the "
                           "sigma-map pulse's surface time"}),
            "wake_elevation": (("y", "x"), st.wake_elevation, {"units": "m"}),
            "wake_mask": (("y", "x"), st.wake_mask,
                          {"units": "1", "long_name": "wake's Bragg spectrum change d: "
                           "x (1 - d); 1 = damped, < 0 narrow-V"}),
            "sigma0": (("polarisation", "y_cell", "x_cell"), truth["sigma0"],
                       {"units": "m2 m-2", "long_name": "normalised radar cross section per "
                        "unit horizontal area of the cell (visibility included) at the "
                        "sigma-map pulse"}),
            "visibility": (("y_cell", "x_cell"), truth["visibility"], {"units": "1"}),
        })
        if truth.get("ship_position") is not None:
            data["ship_position"] = (("pulse", "xy"), truth["ship_position"],
                                     {"units": "m", "long_name": "hull centre (x, y)"})
        dx, dy = float(x[1] - x[0]), float(y[1] - y[0])
        coords.update(x=("x", x, {"units": "m"}), y=("y", y, {"units": "m"}),
                      x_cell=("x_cell", x[:-1] + 0.5 * dx, {"units": "m"}),
                      y_cell=("y_cell", y[:-1] + 0.5 * dy, {"units": "m"}))
    coords["polarisation"] = ("polarisation", np.array(CHANNELS))
    data["transmitted_pulse"] = (
        ("pulse_sample",), radar.waveform.samples,
        {"units": "1", "long_name": "transmitted pulse samples s[n] (unit amplitude), "
         "the matched filter's reference"})
    out = dict(attrs)
    out.update({
        "product_version": PRODUCT_VERSION,
        "carrier_frequency_hz": radar.carrier,
        "wavelength_m": radar.wavelength,
        "sampling_rate_hz": radar.window.sampling_rate,
        "prf_hz": radar.prf,
        "transmit_power_w": radar.transmit_power,
        "window_t0_s": radar.window.t0,
        "waveform_bandwidth_hz": radar.waveform.bandwidth,
        "waveform_duration_s": radar.waveform.duration,
        "waveform_chirp_rate_hz_s": radar.waveform.chirp_rate,
        "monostatic": int(radar.monostatic),
        "sea_clutter": int(truth is not None),
        "raw_units": "sqrt(W): |raw|^2 is the received power [W]",
    })
    out.update(extra_attrs or {})
    if extra is not None:
        data.update(extra[0])
        coords.update(extra[1])
    return xr.Dataset(data, coords=coords, attrs=out)


#: Default pulses per block: memory of a block is block x channels x samples x 32 bytes.
DEFAULT_BLOCK_PULSES = 16


def block_size(edges: np.ndarray, size: int | None = None,
               target: int = DEFAULT_BLOCK_PULSES) -> int:
    """Pulses per block of work (and per Zarr chunk along ``pulse``).

    Parameters
    ----------
    edges : array of int
        ``Simulation.block_edges()``: 0, the pulses where the held sea or the occlusion
        refresh changes, and n_pulses.
    size : int, optional
        A block size chosen by the caller (>= 1): returned as it is (capped at n_pulses).
    target : int
        Wanted block size when ``size`` is None.

    Returns
    -------
    int
        With ``size`` None: the size in [target / 2, 2 target] whose block boundaries
        cut the fewest held segments (a cut segment is rebuilt by the next block: its
        surface synthesis, speckle draws and occlusion trace), the nearest to ``target``
        among equals.
    """
    edges = np.asarray(edges, dtype=np.int64)
    n = int(edges[-1])
    if n < 1:
        raise ValueError(f"n_pulses = {n}: nothing to run")
    if size is not None:
        if int(size) < 1:
            raise ValueError(f"block size {size}: must be >= 1 pulse")
        return min(int(size), n)
    best = None
    for c in range(max(1, target // 2), 2 * target + 1):
        if c >= n:
            c = n
        bounds = np.arange(c, n, c)
        cuts = bounds.size - np.isin(bounds, edges).sum()
        key = (int(cuts), abs(c - target))
        if best is None or key < best[0]:
            best = (key, c)
        if c == n:
            break
    return best[1]


class SerialBlocks:
    """Blocks computed one after the other in this process (the runner of
    ``Simulation.run``; ``seaecho.distributed`` has the Dask runner).

    Parameters
    ----------
    compute : callable
        ``(start, stop) -> (raw, compressed)``, each (stop - start, channels, samples).
    """

    def __init__(self, compute: Callable[[int, int], tuple[np.ndarray, np.ndarray]]):
        self.compute = compute

    def ordered(self, blocks: list[tuple[int, int]]) -> Iterator[tuple[np.ndarray,
                                                                      np.ndarray]]:
        """The blocks' (raw, compressed) in block order."""
        for a, b in blocks:
            yield self.compute(a, b)

    def stored(self, part: Path, todo: list[int], blocks: list[tuple[int, int]]
               ) -> Iterator[dict]:
        """Compute and write each block of ``todo`` into the Zarr run ``part``; yield
        its completion record (:func:`seaecho.io.zarr_run.write_block`)."""
        for i in todo:
            a, b = blocks[i]
            yield write_block(part, i, a, b, *self.compute(a, b))


def write_run(path: str | os.PathLike, static: Callable[[], object], *, identity: dict,
              shape: tuple[int, ...], block: int, runner, weighting: str = "none",
              progress: bool = True, resume: bool = False,
              dims: tuple[str, ...] = PULSE_DIMS) -> Path:
    """Write a run's dataset: the static part, then every block of pulses.

    Parameters
    ----------
    path : path
        ``*.zarr``: a Zarr store (:func:`seaecho.io.zarr_run.write_zarr_run`, resumable);
        else a netCDF file (h5netcdf, complex variables as HDF5 compounds), written
        atomically.
    static : callable
        ``() -> xarray.Dataset`` of :func:`run_dataset` (not called when a Zarr run is
        resumed).
    identity : dict
        ``scene_json``, ``seaecho_version``, ``seed`` of the run (``scene_attrs``): what a
        resumed store must match.
    shape : (n_pulses, n_channels, n_samples)
        Shape of ``raw`` and ``compressed``.
    block : int
        Pulses per block (:func:`block_size`).
    runner : SerialBlocks or seaecho.distributed.DaskBlocks
        Computes the blocks: ``ordered(blocks)`` and ``stored(part, todo, blocks)``.
    weighting : str
        Range weighting (an attribute of ``compressed``).
    progress : bool
        Show a tqdm progress bar over the pulses.
    resume : bool
        Zarr only: continue an interrupted run (:mod:`seaecho.io.zarr_run`).
    dims : tuple of str
        Dimensions of ``raw`` and ``compressed``, pulse first (``shape``'s); a
        multistatic run's are (pulse, receiver, channel, sample).
    """
    if is_zarr(path):
        return write_zarr_run(path, static, identity=identity, shape=shape, block=block,
                              runner=runner, weighting=weighting, progress=progress,
                              resume=resume, dims=dims)
    if resume:
        raise ValueError(f"{path}: --resume needs a Zarr output (*.zarr); a netCDF run "
                         "is written atomically and restarts from the beginning")
    return write_netcdf_run(path, static(), shape=shape, block=block, runner=runner,
                            weighting=weighting, progress=progress, dims=dims)


def write_netcdf_run(path: str | os.PathLike, static, *, shape: tuple[int, ...],
                     block: int, runner, weighting: str = "none",
                     progress: bool = True, dims: tuple[str, ...] = PULSE_DIMS) -> Path:
    """Write the static dataset, then every block of pulses in order, atomically.

    Memory: the runner's blocks in flight (one for :class:`SerialBlocks`). The file's
    bytes depend neither on the runner nor on the block size: the pulses are written in
    order, one at a time.

    Parameters
    ----------
    path : path
        Output netCDF file.
    static : xarray.Dataset
        :func:`run_dataset`.
    shape, block, runner, weighting, progress, dims
        As :func:`write_run`.
    """
    import h5netcdf

    from .dataset import atomic_path

    n_pulses = shape[0]
    with atomic_path(path) as tmp, quiet_invalid_netcdf():
        static.to_netcdf(tmp, engine="h5netcdf", invalid_netcdf=True)
        with h5netcdf.File(tmp, "a", invalid_netcdf=True) as f:
            raw_v, rc_v = (f.create_variable(name, dims, dtype=np.complex128,
                                             chunks=(1, *shape[1:]))
                           for name in ("raw", "compressed"))
            raw_v.attrs.update(RAW_ATTRS)
            rc_v.attrs.update(COMPRESSED_ATTRS, weighting=weighting)
            for a, b, raw, compressed in in_order(n_pulses, block, runner, progress):
                for k in range(b - a):  # pulse by pulse: the file's layout (chunk
                    raw_v[a + k] = raw[k]  # order) does not depend on the block size
                    rc_v[a + k] = compressed[k]
    return Path(path)


def run_in_memory(static, *, shape: tuple[int, ...], block: int, runner,
                  weighting: str = "none", progress: bool = True,
                  dims: tuple[str, ...] = PULSE_DIMS):
    """The dataset that :func:`write_netcdf_run` writes, held in memory: the same blocks
    from the same runner, so the same values bit for bit.

    Memory: the static dataset plus ``raw`` and ``compressed``, n_pulses x n_channels x
    n_samples x 32 bytes.

    Parameters
    ----------
    static : xarray.Dataset
        :func:`run_dataset`.
    shape, block, runner, weighting, progress, dims
        As :func:`write_run`.

    Returns
    -------
    xarray.Dataset
        ``static`` with the variables ``raw`` and ``compressed`` (pulse, channel,
        fast_time) complex128 [sqrt(W)], their attributes as in the file.
    """
    raw_a, rc_a = np.empty(shape, np.complex128), np.empty(shape, np.complex128)
    for a, b, raw, compressed in in_order(shape[0], block, runner, progress):
        raw_a[a:b] = raw
        rc_a[a:b] = compressed
    ds = static.copy()
    ds["raw"] = (dims, raw_a, dict(RAW_ATTRS))
    ds["compressed"] = (dims, rc_a, dict(COMPRESSED_ATTRS, weighting=weighting))
    return ds


def in_order(n_pulses: int, block: int, runner, progress: bool = True
             ) -> Iterator[tuple[int, int, np.ndarray, np.ndarray]]:
    """Every block of pulses in order, ``(start, stop, raw, compressed)``, with a tqdm
    progress bar: the loop of :func:`write_netcdf_run` and :func:`run_in_memory`."""
    from tqdm import tqdm

    blocks = blocks_of(n_pulses, block)
    with tqdm(total=n_pulses, unit="pulse", disable=not progress, desc="seaecho run") as bar:
        for (a, b), (raw, compressed) in zip(blocks, runner.ordered(blocks), strict=True):
            yield a, b, raw, compressed
            bar.update(b - a)


def open_run(path: str | os.PathLike):
    """Open a run's dataset, netCDF file or Zarr store, with xarray (lazily)."""
    import xarray as xr

    if is_zarr(path):
        return xr.open_zarr(path, consolidated=False)
    return xr.open_dataset(path, engine="h5netcdf")


@contextlib.contextmanager
def quiet_invalid_netcdf():
    """Silence h5netcdf's notice that complex variables are not classic netCDF-4."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*invalid netcdf features.*")
        yield


__all__ = ["DEFAULT_BLOCK_PULSES", "SerialBlocks", "block_size", "in_order", "open_run",
           "quiet_invalid_netcdf", "run_dataset", "run_in_memory", "write_netcdf_run",
           "write_run"]
