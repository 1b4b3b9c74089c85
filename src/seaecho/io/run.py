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
                ("pulse", "xyz", "antenna_axis"), pointing.axes(st),
                {"units": "1", "long_name": "antenna axes (columns boresight, width, "
                 "height) in the world; d_local = axes^T d_world"})
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
        coords["target"] = ("target", np.array(targets.names))
    if truth is not None:
        st = truth["state"]
        data.update({
            "elevation": (("y", "x"), st.elevation,
                          {"units": "m", "long_name": "sea + wake height at the "
                           "sigma-map pulse's surface time"}),
            "wake_elevation": (("y", "x"), st.wake_elevation, {"units": "m"}),
            "wake_mask": (("y", "x"), st.wake_mask,
                          {"units": "1", "long_name": "turbulent wake, 1 = Bragg damped"}),
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
        "carrier_frequency_hz": radar.carrier,
        "wavelength_m": radar.wavelength,
        "sampling_rate_hz": radar.window.sampling_rate,
        "prf_hz": radar.prf,
        "transmit_power_w": radar.transmit_power,
        "window_t0_s": radar.window.t0,
        "waveform_bandwidth_hz": radar.waveform.bandwidth,
        "waveform_duration_s": radar.waveform.duration,
        "monostatic": int(radar.monostatic),
        "sea_clutter": int(truth is not None),
        "raw_units": "sqrt(W): |raw|^2 is the received power [W]",
    })
    out.update(extra_attrs or {})
    if extra is not None:
        data.update(extra[0])
        coords.update(extra[1])
    return xr.Dataset(data, coords=coords, attrs=out)


#: Attributes of the ``raw`` and ``compressed`` variables (file and in-memory datasets).
RAW_ATTRS = {"units": "sqrt(W)", "long_name": "complex baseband raw echo"}
COMPRESSED_ATTRS = {"units": "sqrt(W)", "long_name": "range-compressed echo"}


def pulse_blocks(n_pulses: int, n_channels: int, n_samples: int,
                 pulse: Callable[[int], np.ndarray],
                 compress: Callable[[np.ndarray], np.ndarray], *, progress: bool = True,
                 chunk: int = 16) -> Iterator[tuple[int, int, np.ndarray, np.ndarray]]:
    """Every pulse in order, in blocks of ``chunk``: ``(start, stop, raw, compressed)``.

    The one loop behind :func:`write_run` (file) and :func:`run_in_memory`, so that both
    hold the same bytes. The arrays of a block are reused by the next one: copy them or
    write them before asking for the next block.

    Parameters
    ----------
    n_pulses, n_channels, n_samples : int
        Shape of ``raw`` and ``compressed``.
    pulse : callable
        ``p -> (n_channels, n_samples)`` raw samples of pulse p [sqrt(W)].
    compress : callable
        Range compression of a block of raw pulses (same shape).
    progress : bool
        Show a tqdm progress bar.
    chunk : int
        Pulses per block (memory: chunk x channels x samples x 32 bytes).
    """
    from tqdm import tqdm

    chunk = max(1, min(chunk, n_pulses))
    buf = np.empty((chunk, n_channels, n_samples), dtype=np.complex128)
    with tqdm(total=n_pulses, unit="pulse", disable=not progress, desc="seaecho run") as bar:
        for start in range(0, n_pulses, chunk):
            stop = min(start + chunk, n_pulses)
            for i, p in enumerate(range(start, stop)):
                buf[i] = pulse(p)
                bar.update(1)
            yield start, stop, buf[: stop - start], compress(buf[: stop - start])


def write_run(path: str | os.PathLike, static, *, n_pulses: int, n_channels: int,
              n_samples: int, pulse: Callable[[int], np.ndarray],
              compress: Callable[[np.ndarray], np.ndarray], weighting: str = "none",
              progress: bool = True, chunk: int = 16) -> Path:
    """Write the static dataset, then every pulse as it is computed, atomically.

    Parameters
    ----------
    path : path
        Output netCDF file (h5netcdf, complex variables as HDF5 compounds).
    static : xarray.Dataset
        :func:`run_dataset`.
    n_pulses, n_channels, n_samples, pulse, compress, progress, chunk
        As :func:`pulse_blocks`.
    weighting : str
        Range weighting (an attribute of ``compressed``).
    """
    import h5netcdf

    from .dataset import atomic_path

    with atomic_path(path) as tmp, quiet_invalid_netcdf():
        static.to_netcdf(tmp, engine="h5netcdf", invalid_netcdf=True)
        with h5netcdf.File(tmp, "a", invalid_netcdf=True) as f:
            raw_v, rc_v = (f.create_variable(name, ("pulse", "channel", "fast_time"),
                                             dtype=np.complex128,
                                             chunks=(1, n_channels, n_samples))
                           for name in ("raw", "compressed"))
            raw_v.attrs.update(RAW_ATTRS)
            rc_v.attrs.update(COMPRESSED_ATTRS, weighting=weighting)
            for start, stop, raw, compressed in pulse_blocks(
                    n_pulses, n_channels, n_samples, pulse, compress, progress=progress,
                    chunk=chunk):
                raw_v[start:stop] = raw
                rc_v[start:stop] = compressed
    return Path(path)


def run_in_memory(static, *, n_pulses: int, n_channels: int, n_samples: int,
                  pulse: Callable[[int], np.ndarray],
                  compress: Callable[[np.ndarray], np.ndarray], weighting: str = "none",
                  progress: bool = True, chunk: int = 16):
    """The dataset that :func:`write_run` writes, held in memory.

    Same arguments as :func:`write_run` but the path. Memory: the static dataset plus
    ``raw`` and ``compressed``, n_pulses x n_channels x n_samples x 32 bytes.

    Returns
    -------
    xarray.Dataset
        ``static`` with the variables ``raw`` and ``compressed`` (pulse, channel,
        fast_time) complex128 [sqrt(W)], their attributes as in the file.
    """
    shape = (n_pulses, n_channels, n_samples)
    raw_a, rc_a = np.empty(shape, np.complex128), np.empty(shape, np.complex128)
    for start, stop, raw, compressed in pulse_blocks(
            n_pulses, n_channels, n_samples, pulse, compress, progress=progress, chunk=chunk):
        raw_a[start:stop] = raw
        rc_a[start:stop] = compressed
    dims = ("pulse", "channel", "fast_time")
    ds = static.copy()
    ds["raw"] = (dims, raw_a, dict(RAW_ATTRS))
    ds["compressed"] = (dims, rc_a, dict(COMPRESSED_ATTRS, weighting=weighting))
    return ds


@contextlib.contextmanager
def quiet_invalid_netcdf():
    """Silence h5netcdf's notice that complex variables are not classic netCDF-4."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*invalid netcdf features.*")
        yield


__all__ = ["COMPRESSED_ATTRS", "RAW_ATTRS", "pulse_blocks", "quiet_invalid_netcdf",
           "run_dataset", "run_in_memory", "write_run"]
