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
from collections.abc import Callable
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
    n_pulses, n_channels, n_samples : int
        Shape of ``raw`` and ``compressed``.
    pulse : callable
        ``p -> (n_channels, n_samples)`` raw samples of pulse p [sqrt(W)].
    compress : callable
        Range compression of a block of raw pulses (same shape).
    weighting : str
        Range weighting (an attribute of ``compressed``).
    progress : bool
        Show a tqdm progress bar.
    chunk : int
        Pulses buffered per write (memory: chunk x channels x samples x 32 bytes).
    """
    import h5netcdf
    from tqdm import tqdm

    from .dataset import atomic_path

    chunk = max(1, min(chunk, n_pulses))
    with atomic_path(path) as tmp, quiet_invalid_netcdf():
        static.to_netcdf(tmp, engine="h5netcdf", invalid_netcdf=True)
        with h5netcdf.File(tmp, "a", invalid_netcdf=True) as f:
            raw_v = f.create_variable("raw", ("pulse", "channel", "fast_time"),
                                      dtype=np.complex128, chunks=(1, n_channels, n_samples))
            raw_v.attrs.update(units="sqrt(W)", long_name="complex baseband raw echo")
            rc_v = f.create_variable("compressed", ("pulse", "channel", "fast_time"),
                                     dtype=np.complex128, chunks=(1, n_channels, n_samples))
            rc_v.attrs.update(units="sqrt(W)", long_name="range-compressed echo",
                              weighting=weighting)
            buf = np.empty((chunk, n_channels, n_samples), dtype=np.complex128)
            bar = tqdm(total=n_pulses, unit="pulse", disable=not progress, desc="seaecho run")
            try:
                for start in range(0, n_pulses, chunk):
                    stop = min(start + chunk, n_pulses)
                    for i, p in enumerate(range(start, stop)):
                        buf[i] = pulse(p)
                        bar.update(1)
                    raw_v[start:stop] = buf[: stop - start]
                    rc_v[start:stop] = compress(buf[: stop - start])
            finally:
                bar.close()
    return Path(path)


@contextlib.contextmanager
def quiet_invalid_netcdf():
    """Silence h5netcdf's notice that complex variables are not classic netCDF-4."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*invalid netcdf features.*")
        yield


__all__ = ["quiet_invalid_netcdf", "run_dataset", "write_run"]
