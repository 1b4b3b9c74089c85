"""Products as detection frames, and detection tables as files.

Readers (a product in, :class:`seaecho.detection.frames.Frame` objects out):

- :func:`run_truth`: the objects of a run (``seaecho run``): per-pulse truth
  ``truth_position (pulse, object, xyz)`` where the run has it, else the point targets
  (``target_position`` + ``target_velocity`` t, extent 0) and the ray-traced hulls
  (``hull_position``, extent twice the farthest scattering centre from the hull's
  origin). The ``[ship]`` of the wake alone is not an object (it has no echo of its own).
- :func:`profile_frames`: the range-compressed pulses of a run, ``|compressed|^2``
  (pulse x range) of one channel; objects gated in range (half the bistatic path) by
  half their extent plus the range resolution c / (2 B) (or the sample spacing, if
  coarser); a plot's x, y is the point of the sea, along the receive antenna's
  boresight azimuth, with the plot's range (where two points have it, the one nearer
  the boresight). A monostatic run's gates cover on the sea the pulse-limited cell
  R theta_B Delta R sec psi (:mod:`seaecho.detection.footprint`, eq F1: theta_B the
  receive antenna's half-power azimuth width, psi the grazing angle on the run's flat or
  4/3 Earth): with the gate spacing as Delta R the tested area of a look (false alarms
  per km^2), with c / (2 B) the resolution cell of each plot (``cell_area_m2``).
- :func:`sweep_frames`: PPI sweeps (azimuth x range, azimuth in degrees clockwise from
  north as CfRadial 2 has it), from plain arrays; :func:`run_sweeps` cuts a scanning run
  (its ``sweep`` variable) into them and :func:`cfradial_sweeps` reads a CfRadial 2 file's
  ``sweep_N`` groups. Objects gated in x, y by half their extent plus the range resolution
  or the arc of ``azimuth_gate_deg`` at their range, whichever is larger. Each plot
  carries the receiver's x, y (``radar_x_m``, ``radar_y_m``): the origin of its bearing
  and ground range in the Stone Soup export.
- :func:`image_frames`: a SAR image of ``seaecho image``, |image|^2 [m^2] of one channel
  (pixels outside ``valid`` not tested); objects at the aperture's middle time, gated by
  half their extent plus twice the pixel or c / B. :func:`image_stack_frames`: several
  images of one grid, one look each in their order (what a clutter map takes).

Writers: :func:`write_table` (a CSV with ``# key = value`` header lines, atomically) and
:func:`write_stonesoup` (the detections and the ground truth as the CSV files Stone Soup's
``CSVDetectionReader`` and ``CSVGroundTruthReader`` read, sorted by time, with the
measurement noise in ``stonesoup.json``); :func:`stonesoup_readers` reads them back with
Stone Soup (the only module that imports it), a linear x, y model or, for PPI sweeps, a
bearing-range model centred on the radar.
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..constants import C0
from ..detection.association import ground_point, half_path
from ..detection.footprint import (
    clutter_cell_area,
    compressed_extent,
    half_power_width,
    level_extent,
)
from ..detection.frames import Frame, ObjectTruth
from ..geometry.earth import effective_radius, grazing_angle

__all__ = ["STONESOUP_FILES", "antenna_beamwidth", "cfradial_sweeps", "earth_radius",
           "land_spread",
           "image_frames", "image_stack_frames", "image_truth", "profile_frames",
           "read_table", "run_land_outlines", "run_sweeps", "run_truth", "stonesoup_readers",
           "sweep_frames",
           "bearing_from_azimuth", "MEASUREMENTS",
           "write_stonesoup", "write_table"]

#: Files of a Stone Soup export directory.
STONESOUP_FILES = {"detections": "detections.csv", "truth": "truth.csv",
                   "settings": "stonesoup.json"}


def _channel(ds, channel: str | None) -> str:
    names = [str(c) for c in ds["channel"].values]
    if channel is None:
        return names[0]
    if channel not in names:
        raise ValueError(f"channel = {channel!r}: not in the dataset (has "
                         f"{', '.join(names)})")
    return channel


def run_truth(run) -> ObjectTruth:
    """The objects of a run and their positions at every pulse (module docstring)."""
    t = np.asarray(run["time"].values, dtype=float)
    if "truth_position" in run:
        pos = np.asarray(run["truth_position"].values, dtype=float)
        dim = run["truth_position"].dims[1]
        names = tuple(str(n) for n in run[dim].values) if dim in run.coords else \
            tuple(f"object{i}" for i in range(pos.shape[1]))
        extent = np.zeros(pos.shape[1])
        for v in run.data_vars:  # an extent on the object dimension, if the run has one
            if run[v].dims == (dim,) and ("length" in v or "extent" in v):
                extent = np.nan_to_num(np.asarray(run[v].values, dtype=float))
                break
        visible = (np.asarray(run["truth_visible"].values) > 0
                   if "truth_visible" in run else None)
        return ObjectTruth(t, pos, names, extent, visible)
    names, parts, extents = [], [], []
    if "target_position" in run:
        p0 = np.asarray(run["target_position"].values, dtype=float)
        v = np.asarray(run["target_velocity"].values, dtype=float)
        parts.append(p0[None] + t[:, None, None] * v[None])
        names += [str(n) for n in run["target"].values]
        extents.append(np.zeros(p0.shape[0]))
    if "hull_position" in run:
        hp = np.moveaxis(np.asarray(run["hull_position"].values, dtype=float), 0, 1)
        parts.append(hp)
        names += [str(n) for n in run["hull"].values]
        ext = np.zeros(hp.shape[1])
        if "hull_centre_position" in run:
            c = np.asarray(run["hull_centre_position"].values, dtype=float)
            which = np.asarray(run["hull_centre_hull"].values, dtype=np.int64)
            k = int(run.attrs.get("sigma_map_pulse", 0))
            d = np.linalg.norm(c[:, :2] - hp[min(k, hp.shape[0] - 1), which, :2], axis=1)
            np.maximum.at(ext, which, 2.0 * d)
        extents.append(ext)
    if not parts:
        return ObjectTruth(t, np.zeros((t.size, 0, 3)), (), np.zeros(0))
    return ObjectTruth(t, np.concatenate(parts, axis=1), tuple(names),
                       np.concatenate(extents))


def _range_resolution(ds) -> float:
    """c / (2 B) of the run's waveform (the sample spacing if coarser) [m]."""
    res = 0.0
    if "waveform_bandwidth_hz" in ds.attrs and float(ds.attrs["waveform_bandwidth_hz"]) > 0:
        res = C0 / (2.0 * float(ds.attrs["waveform_bandwidth_hz"]))
    rng = np.asarray(ds["range"].values, dtype=float)
    return max(res, float(np.median(np.diff(rng))) if rng.size > 1 else 0.0)


def antenna_beamwidth(ds, prefix: str = "rx") -> float:
    """One-way half-power azimuth width of a run's ``<prefix>`` antenna [rad]
    (:func:`seaecho.detection.footprint.half_power_width` of its product pattern); NaN
    when the dataset does not describe the antenna."""
    from .product import read_antenna

    if f"{prefix}_antenna_pattern" not in ds:
        return float("nan")
    wavelength = float(ds.attrs.get("wavelength_m", 0.0) or 0.0) or \
        C0 / float(ds.attrs.get("carrier_frequency_hz", np.nan))
    try:
        return half_power_width(read_antenna(ds, prefix, wavelength).gain_local)
    except (KeyError, ValueError):
        return float("nan")


def land_spread(ds, level_db: float) -> tuple[float, float]:
    """How far a strong echo spreads past its own cell on a scanning run's PPI, down to
    ``level_db`` below its peak: (azimuth half-extent [rad], range half-extent [m])
    (docs/detection.md, "Land blanking").

    Azimuth: :func:`seaecho.detection.footprint.level_extent` of the two-way pattern
    G_t G_r of the run's antennas along their azimuth plane (eq A1 of
    :mod:`seaecho.radar.antennas` with the width's illumination, eqs A4-A5; the receive
    antenna taken along the transmit antenna's azimuth plane, as a monostatic radar's
    co-located antennas are; the transmit antenna twice where the run records no receive
    antenna). Range: :func:`seaecho.detection.footprint.compressed_extent` of the run's
    ``transmitted_pulse`` through its matched filter (the scene's ``range_weighting``),
    times the sample spacing c / (2 f_s).

    Raises
    ------
    ValueError
        The run does not describe its transmit antenna (``tx_antenna_*``) or its pulse
        (``transmitted_pulse``, ``sampling_rate_hz``).
    """
    from ..processing.range_compression import weighting_window
    from .product import read_antenna

    missing = [v for v in ("tx_antenna_pattern", "transmitted_pulse") if v not in ds]
    fs = float(ds.attrs.get("sampling_rate_hz", 0.0) or 0.0)
    if missing or not (np.isfinite(fs) and fs > 0):
        raise ValueError(f"land_spread_db = {level_db:g}: the spread of the land's echo "
                         "needs the run's antenna and pulse (tx_antenna_*, "
                         "transmitted_pulse, sampling_rate_hz > 0: docs/products.md); this "
                         f"dataset lacks {', '.join(missing) or 'sampling_rate_hz'}: give "
                         "land_spread_db = none (--no-land-spread)")
    wavelength = float(ds.attrs.get("wavelength_m", 0.0) or 0.0) or \
        C0 / float(ds.attrs.get("carrier_frequency_hz", np.nan))
    tx = read_antenna(ds, "tx", wavelength)
    rx = read_antenna(ds, "rx", wavelength) if "rx_antenna_pattern" in ds else tx
    azimuth = level_extent(lambda d: tx.gain_local(d) * rx.gain_local(d), level_db)
    radar = json.loads(ds.attrs.get("scene_json", "{}") or "{}").get("radar") or {}
    pulse = np.asarray(ds["transmitted_pulse"].values)
    w = weighting_window(radar.get("range_weighting", "none") or "none", pulse.size,
                         int(radar.get("taylor_nbar", 5) or 5),
                         float(radar.get("taylor_sidelobe_db", 35.0) or 35.0))
    samples = compressed_extent(pulse, w * pulse, level_db)
    return azimuth, samples * C0 / (2.0 * fs)


def earth_radius(ds) -> float:
    """The radius the run's geometry used [m]: k a on a spherical Earth
    (``[propagation] earth = "spherical"``), infinite on a flat one."""
    prop = json.loads(ds.attrs.get("scene_json", "{}") or "{}").get("propagation") or {}
    if prop.get("earth") == "spherical":
        k = prop.get("earth_radius_factor")
        return effective_radius(float(k)) if k else effective_radius()
    return float("inf")


def _boresight(axes: NDArray) -> NDArray:
    """The antenna boresights in the world, (pulse, xyz, axis) -> (pulse, 3)."""
    return np.asarray(axes, dtype=float)[:, :, 0]


def profile_frames(run, channel: str | None = None,
                   truth: ObjectTruth | None = None) -> list[Frame]:
    """The run's range profiles (pulse x range) as one frame (module docstring)."""
    ch = _channel(run, channel)
    if "compressed" not in run:
        raise ValueError("not a run of `seaecho run`: no 'compressed' pulses")
    z = run["compressed"].sel(channel=ch).values
    power = np.abs(z) ** 2
    rng = np.asarray(run["range"].values, dtype=float)
    t = np.asarray(run["time"].values, dtype=float)
    pulses = np.asarray(run["pulse"].values, dtype=np.int64)
    tx = np.asarray(run["tx_position"].values, dtype=float)
    rx = np.asarray(run["rx_position"].values, dtype=float)
    u = _boresight(run["rx_antenna_axes"].values)
    truth = run_truth(run) if truth is None else truth
    where = truth.at(t)  # (pulse, object, 3)
    r_obj = half_path(where, tx[:, None], rx[:, None])[..., None]
    res = _range_resolution(run)
    gate = 0.5 * np.asarray(truth.extent_m, dtype=float) + res
    cols = np.arange(rng.size, dtype=float)
    # the sea each gate covers (eq F1), monostatic only: a bistatic cell is the
    # intersection of two beams with the path's ellipse (not computed)
    monostatic = bool(np.allclose(tx, rx, atol=1e-6))
    theta = antenna_beamwidth(run, "rx") if monostatic else float("nan")
    radius = earth_radius(run)
    dr_gate = float(np.median(np.diff(rng))) if rng.size > 1 else res
    # the antenna's height above the sea: above the sphere of radius k a whose tangent
    # plane at the origin is the scene's frame (docs/scanning.md), or above z = 0
    h = rx[:, 2] if not np.isfinite(radius) else \
        np.sqrt(rx[:, 0] ** 2 + rx[:, 1] ** 2 + (rx[:, 2] + radius) ** 2) - radius
    area = clutter_cell_area(rng[None, :], dr_gate, theta,
                             grazing_angle(h[:, None], rng[None, :], radius))

    def locate(row, col):
        k = np.clip(np.rint(row).astype(np.int64), 0, pulses.size - 1)
        r = np.interp(col, cols, rng)
        p = ground_point(tx[k], rx[k], u[k], r)
        cell = clutter_cell_area(r, res, theta, grazing_angle(h[k], r, radius))
        return {"pulse": pulses[k], "range_m": r, "x_m": p[:, 0], "y_m": p[:, 1],
                "cell_area_m2": cell}

    return [Frame("profile", power, pulses.copy(), t, rng[None, :, None], r_obj, gate,
                  locate, where, ndim=1, cell_area_m2=area, truth_visible=truth.visible_at(t),
                  extra={"position_sigma_m": res, "channel": ch,
                         "beamwidth_deg": float(np.rad2deg(theta))})]


def sweep_frames(power: list[NDArray], azimuth_deg: list[NDArray], time_s: list[NDArray],
                 range_m: NDArray, tx_position_m: list[NDArray],
                 rx_position_m: list[NDArray] | None = None,
                 truth: ObjectTruth | None = None, azimuth_gate_deg: float | None = None,
                 range_resolution_m: float | None = None,
                 beamwidth_deg: float | None = None) -> list[Frame]:
    """PPI sweeps as frames, one per sweep (plain arrays; module docstring).

    Parameters
    ----------
    power : list of ndarray
        Per sweep, (azimuth, range) power [W].
    azimuth_deg : list of ndarray
        Per sweep, (azimuth,) ray azimuths clockwise from north (+y) [deg].
    time_s : list of ndarray
        Per sweep, (azimuth,) ray times [s].
    range_m : ndarray
        (range,) half bistatic path of the gates [m].
    tx_position_m, rx_position_m : list of ndarray
        Per sweep, (azimuth, 3) or (3,) transmitter / receiver positions [m]
        (receiver default: the transmitter's, monostatic).
    truth : ObjectTruth, optional
        The objects (default none).
    azimuth_gate_deg : float, optional
        Azimuth part of the gates [deg] (default three ray spacings).
    range_resolution_m : float, optional
        Range part of the gates [m] (default the gate spacing).
    beamwidth_deg : float, optional
        One-way half-power azimuth width of the beam [deg] (default the azimuth gate):
        with the range resolution, the plots' spread for a tracker (``extra``:
        ``range_sigma_m`` and ``azimuth_sigma_deg``, a resolution cell's uniform spread,
        width / sqrt(12)).
    """
    truth = ObjectTruth.empty() if truth is None else truth
    rng = np.asarray(range_m, dtype=float)
    dr = float(np.median(np.diff(rng))) if rng.size > 1 else 1.0
    res = dr if range_resolution_m is None else max(float(range_resolution_m), dr)
    rx_position_m = tx_position_m if rx_position_m is None else rx_position_m
    frames = []
    for i, (p, az, t, tx, rx) in enumerate(zip(power, azimuth_deg, time_s, tx_position_m,
                                               rx_position_m, strict=True)):
        p = np.asarray(p, dtype=float)
        az = np.asarray(az, dtype=float)
        t = np.asarray(t, dtype=float)
        n_az = az.size
        if p.shape != (n_az, rng.size):
            raise ValueError(f"sweep {i}: power of shape {p.shape}, expected (azimuth "
                             f"{n_az}, range {rng.size})")
        tx = np.broadcast_to(np.asarray(tx, dtype=float), (n_az, 3))
        rx = np.broadcast_to(np.asarray(rx, dtype=float), (n_az, 3))
        a = np.deg2rad(az)
        u = np.stack([np.sin(a), np.cos(a)], axis=-1)  # clockwise from north
        step = float(np.median(np.abs(np.diff(np.unwrap(a))))) if n_az > 1 else np.pi
        span = float(np.ptp(np.unwrap(a))) + step
        circular = span >= 2.0 * np.pi - 0.5 * step
        gate_az = np.deg2rad(azimuth_gate_deg) if azimuth_gate_deg is not None else 3 * step
        ground = ground_point(np.repeat(tx, rng.size, 0), np.repeat(rx, rng.size, 0),
                              np.repeat(u, rng.size, 0), np.tile(rng, n_az))
        cell = ground[:, :2].reshape(n_az, rng.size, 2)
        where = truth.at(t)
        seen = truth.visible_at(t)
        r_obj = np.linalg.norm(where[..., :2] - rx[:, None, :2], axis=-1)
        gate = 0.5 * np.asarray(truth.extent_m, dtype=float) + np.maximum(
            res, np.nanmedian(r_obj, axis=0) * gate_az if where.shape[1] else res)
        r_ground = np.linalg.norm(cell - rx[:, None, :2], axis=-1)
        cell_area = np.nan_to_num(r_ground * min(step, 2 * np.pi) * dr)

        def locate(row, col, az=az, tx=tx, rx=rx, u=u, i=i):
            k = np.clip(np.rint(row).astype(np.int64), 0, az.size - 1)
            r = np.interp(col, np.arange(rng.size, dtype=float), rng)
            # the centroid's azimuth: interpolated along the (unwrapped) rays
            a_un = np.unwrap(np.deg2rad(az))
            a_c = np.interp(row, np.arange(az.size, dtype=float), a_un)
            uc = np.stack([np.sin(a_c), np.cos(a_c)], axis=-1)
            q = ground_point(tx[k], rx[k], uc, r)
            return {"sweep": np.full(k.size, i), "azimuth_deg": np.rad2deg(a_c) % 360.0,
                    "range_m": r, "x_m": q[:, 0], "y_m": q[:, 1],
                    "radar_x_m": rx[k, 0], "radar_y_m": rx[k, 1]}

        frames.append(Frame("ppi", p, np.full(n_az, i), t, np.nan_to_num(cell, nan=1e30),
                            where[..., :2], np.atleast_1d(gate), locate, where, ndim=2,
                            cell_area_m2=cell_area, extra={
                                "circular": circular, "azimuth_step_deg": np.rad2deg(step),
                                "range_step_m": dr, "position_sigma_m": max(
                                    res, float(np.median(rng)) * step),
                                "range_sigma_m": res / np.sqrt(12.0),
                                "azimuth_sigma_deg": float(np.rad2deg(
                                    np.deg2rad(beamwidth_deg) if beamwidth_deg is not None
                                    and np.isfinite(beamwidth_deg) else gate_az)
                                    / np.sqrt(12.0))}, truth_visible=seen))
    return frames


def run_sweeps(run, channel: str | None = None, truth: ObjectTruth | None = None,
               azimuth_gate_deg: float | None = None) -> list[Frame]:
    """A scanning run (with a ``sweep`` per pulse) cut into PPI frames."""
    ch = _channel(run, channel)
    sweep = np.asarray(run["sweep"].values)
    axes = np.asarray(run["tx_antenna_axes"].values, dtype=float)
    az = np.rad2deg(np.arctan2(axes[:, 0, 0], axes[:, 1, 0])) % 360.0
    z = run["compressed"].sel(channel=ch).values
    t = np.asarray(run["time"].values, dtype=float)
    tx = np.asarray(run["tx_position"].values, dtype=float)
    rx = np.asarray(run["rx_position"].values, dtype=float)
    groups = [np.flatnonzero(sweep == k) for k in dict.fromkeys(sweep.tolist())]
    frames = sweep_frames([np.abs(z[g]) ** 2 for g in groups], [az[g] for g in groups],
                        [t[g] for g in groups], run["range"].values,
                        [tx[g] for g in groups], [rx[g] for g in groups],
                        truth=run_truth(run) if truth is None else truth,
                        azimuth_gate_deg=azimuth_gate_deg,
                        range_resolution_m=_range_resolution(run),
                        beamwidth_deg=float(np.rad2deg(antenna_beamwidth(run, "tx")))
                        if "tx_antenna_pattern" in run else None)
    for f in frames:
        f.extra["channel"] = ch
    return frames


def run_land_outlines(run) -> list[NDArray]:
    """The shore polygons of a run's ``[[land]]`` (``land_outline``, in the scene's
    coordinates), one (k, 2) array [m] per piece; empty without land."""
    if "land_outline" not in run:
        return []
    xy = np.asarray(run["land_outline"].values, dtype=float)
    which = np.asarray(run["land_outline_land"].values)
    return [xy[which == i] for i in np.unique(which) if (which == i).sum() >= 3]


def cfradial_sweeps(path: str | os.PathLike, channel: str | None = None,
                    radar_position_m=None, truth: ObjectTruth | None = None,
                    azimuth_gate_deg: float | None = None) -> list[Frame]:
    """The ``sweep_N`` groups of a CfRadial 2 file as PPI frames (power from the
    ``{channel}_re``/``_im`` samples, else from ``{channel}_power`` in dB re 1 W).

    ``radar_position_m`` (3,) is the radar in the scene frame (default (0, 0,
    altitude)): CfRadial's x, y are relative to the radar.
    """
    import xarray as xr

    tree = xr.open_datatree(path, engine="h5netcdf")
    try:
        names = [n for n in tree.children if n.startswith("sweep_")]
        if not names:
            raise ValueError(f"{os.fspath(path)}: no sweep_N group (not a CfRadial 2 file)")
        names.sort(key=lambda n: int(n.split("_")[1]))
        first = tree[names[0]].to_dataset()
        chans = sorted({v.rsplit("_", 1)[0] for v in first.data_vars
                        if v.endswith(("_power", "_re"))})
        ch = channel or (chans[0] if chans else None)
        if ch not in chans:
            raise ValueError(f"channel = {channel!r}: the sweeps have {', '.join(chans)}")
        alt = float(tree.to_dataset().get("altitude", first.get("altitude", 0.0)))
        pos = np.asarray(radar_position_m if radar_position_m is not None
                         else (0.0, 0.0, alt), dtype=float)
        power, az, t = [], [], []
        for n in names:
            s = tree[n].to_dataset()
            if f"{ch}_re" in s:
                power.append(s[f"{ch}_re"].values.astype(float) ** 2
                             + s[f"{ch}_im"].values.astype(float) ** 2)
            else:
                power.append(10.0 ** (s[f"{ch}_power"].values.astype(float) / 10.0))
            az.append(s["azimuth"].values.astype(float))
            tt = s["time"].values
            t.append(tt.astype("datetime64[ns]").astype(np.int64) * 1e-9
                     if np.issubdtype(tt.dtype, np.datetime64) else tt.astype(float))
        rng = first["range"].values.astype(float)
    finally:
        tree.close()
    frames = sweep_frames(power, az, t, rng, [pos] * len(names), truth=truth,
                          azimuth_gate_deg=azimuth_gate_deg)
    for f in frames:
        f.extra["channel"] = ch
    return frames


def image_truth(img) -> tuple[ObjectTruth, float]:
    """The image's point targets at the aperture's middle time, and that time [s]."""
    n = int(img.attrs.get("n_pulses", 1))
    prf = float(img.attrs.get("prf_hz", 1.0))
    radar = json.loads(img.attrs.get("scene_json", "{}") or "{}").get("radar") or {}
    t_mid = float(radar.get("start_time_s", 0.0) or 0.0) + 0.5 * (n - 1) / prf
    if "target_position" not in img:
        return ObjectTruth(np.array([t_mid]), np.zeros((1, 0, 3)), (), np.zeros(0)), t_mid
    p = (np.asarray(img["target_position"].values, dtype=float)
         + t_mid * np.asarray(img["target_velocity"].values, dtype=float))
    names = tuple(str(x) for x in img["target"].values)
    listed = [t.get("name") for t in json.loads(img.attrs.get("scene_json", "{}") or "{}")
              .get("targets") or []]
    if "target" not in img.coords and len(listed) == len(names) and all(listed):
        names = tuple(str(x) for x in listed)  # an image keeps the targets' order
    return ObjectTruth(np.array([t_mid]), p[None], names, np.zeros(len(names))), t_mid


def image_frames(img, channel: str | None = None,
                 truth: ObjectTruth | None = None) -> list[Frame]:
    """A SAR image (y x x) as one frame (module docstring)."""
    ch = _channel(img, channel)
    power = np.abs(img["image"].sel(channel=ch).values.astype(np.complex128)) ** 2
    if "valid" in img:
        power = np.where(np.asarray(img["valid"].values) > 0, power, np.nan)
    x = np.asarray(img["x"].values, dtype=float)
    y = np.asarray(img["y"].values, dtype=float)
    own, t_mid = image_truth(img)
    truth = own if truth is None else truth
    pixel = float(img.attrs.get("pixel_m", abs(x[1] - x[0]) if x.size > 1 else 1.0))
    bw = float(json.loads(img.attrs.get("scene_json", "{}")).get("radar", {})
               .get("waveform", {}).get("bandwidth_hz", 0.0) or 0.0)
    res = max(2.0 * pixel, C0 / bw if bw > 0 else 0.0)
    where = truth.at(np.full(y.size, t_mid))
    gate = 0.5 * np.asarray(truth.extent_m, dtype=float) + res
    cell = np.stack(np.broadcast_arrays(x[None, :], y[:, None]), axis=-1)
    tx = np.asarray(img["tx_position_used"].values, dtype=float) \
        if "tx_position_used" in img else None
    rx = np.asarray(img["rx_position_used"].values, dtype=float) \
        if "rx_position_used" in img else None

    def locate(row, col):
        xs = np.interp(col, np.arange(x.size, dtype=float), x)
        ys = np.interp(row, np.arange(y.size, dtype=float), y)
        out = {"x_m": xs, "y_m": ys}
        if tx is not None and rx is not None:
            m = tx.shape[0] // 2
            p = np.stack([xs, ys, np.zeros_like(xs)], axis=-1)
            out["range_m"] = half_path(p, tx[m], rx[m])
        return out

    return [Frame("image", power, np.zeros(y.size, np.int64), np.full(y.size, t_mid), cell,
                  where[..., :2], gate, locate, where, ndim=2, cell_area_m2=pixel * pixel,
                  truth_visible=truth.visible_at(np.full(y.size, t_mid)),
                  extra={"position_sigma_m": res / 2.0, "channel": ch})]


def image_stack_frames(images: list, channel: str | None = None,
                       truth: ObjectTruth | None = None) -> list[Frame]:
    """Several SAR images of one grid (same x, y) as frames, look k = the k-th image.

    What a clutter map (scan-to-scan) takes: repeated images of the same ground cells
    (repeat passes, successive apertures of a staring or circular collection, or
    realisations of one scene over seeds), in the order given. Each image keeps its own
    objects at its aperture's middle time unless ``truth`` is given.
    """
    if len(images) < 2:
        raise ValueError(f"{len(images)} image: a stack needs at least two")
    frames = []
    x0 = y0 = None
    for k, img in enumerate(images):
        x = np.asarray(img["x"].values, dtype=float)
        y = np.asarray(img["y"].values, dtype=float)
        if x0 is None:
            x0, y0 = x, y
        elif x.shape != x0.shape or y.shape != y0.shape or not (
                np.allclose(x, x0) and np.allclose(y, y0)):
            raise ValueError(f"image {k}: its grid ({y.size} x {x.size} pixels from x = "
                             f"{x[0]:g}, y = {y[0]:g} m) differs from the first image's "
                             f"({y0.size} x {x0.size} from x = {x0[0]:g}, y = {y0[0]:g} "
                             "m): a clutter map needs the same cells in every image")
        (f,) = image_frames(img, channel, truth)
        f.look = np.full(y.size, k, np.int64)
        frames.append(f)
    return frames


def _format(v) -> str:
    if isinstance(v, float | np.floating):
        return repr(float(v)) if np.isfinite(v) else ""
    return str(v)


def write_table(path: str | os.PathLike, columns: Mapping[str, NDArray],
                header: Mapping[str, object] | None = None) -> Path:
    """Write a table as CSV atomically: ``# key = value`` lines, then a header row and
    one row per entry. NaN is written as an empty field (no data)."""
    import csv
    import io

    from .dataset import atomic_path

    names = list(columns)
    cols = [np.asarray(columns[k]) for k in names]
    n = cols[0].size if cols else 0
    buf = io.StringIO()
    for k, v in (header or {}).items():
        buf.write(f"# {k} = {' '.join(_format(v).split())}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(names)

    def cell(v):
        if isinstance(v, float | np.floating):
            return "" if not np.isfinite(v) else repr(float(v))
        return str(v)

    for i in range(n):  # rows of a table of plots, not cells
        w.writerow([cell(c[i]) for c in cols])
    path = Path(path)
    with atomic_path(path) as tmp:
        tmp.write_text(buf.getvalue(), encoding="utf-8")
    return path


def read_table(path: str | os.PathLike) -> tuple[dict[str, NDArray], dict[str, str]]:
    """Read :func:`write_table`'s CSV: (columns, header). Numbers as float or int,
    other fields as str; an empty field is NaN in a number column."""
    import csv

    header: dict[str, str] = {}
    body = []
    try:
        with open(path, encoding="utf-8", newline="") as f:
            for line in f:
                if line.startswith("#"):
                    k, _, v = line[1:].partition("=")
                    header[k.strip()] = v.strip()
                else:
                    body.append(line)
    except UnicodeDecodeError:
        raise ValueError("not a CSV table (not UTF-8 text)") from None
    rows = list(csv.reader(body))
    if not rows:
        raise ValueError(f"{os.fspath(path)}: no header row")
    names, data = rows[0], rows[1:]
    out = {}
    for j, name in enumerate(names):
        raw = [r[j] for r in data]
        try:
            vals = np.array([float(v) if v != "" else np.nan for v in raw])
            if vals.size and np.all(np.isfinite(vals)) and np.all(vals == np.round(vals)) \
                    and all("." not in v and "e" not in v.lower() for v in raw):
                vals = vals.astype(np.int64)
            out[name] = vals
        except ValueError:
            out[name] = np.array(raw, dtype=object)
    return out, header


def write_stonesoup(directory: str | os.PathLike, detections: Mapping[str, NDArray],
                    truth: Mapping[str, NDArray], noise_m: tuple[float, float],
                    bearing_range_noise: tuple[float, float] | None = None) -> dict:
    """The detections and the ground truth as Stone Soup reads them.

    ``detections.csv``: ``time`` (seconds since the scene's t = 0, read with
    ``timestamp=True`` as seconds since 1970-01-01 UTC), ``x``, ``y`` [m] (the state
    vector fields), then metadata (``range_m``, ``snr_db``, ``power``, ``object``...).
    PPI plots (with ``azimuth_deg`` and the radar's ``radar_x_m``, ``radar_y_m``) also
    get the measurement of a scanning radar in Stone Soup's convention: ``bearing_rad``,
    phi = pi/2 - azimuth (counter-clockwise from east, as
    ``CartesianToBearingRange``'s atan2(y, x); the PPI's azimuth is clockwise from
    north), wrapped to [-pi, pi), and ``ground_range_m``, the horizontal distance from
    the radar to the plot's point of the sea.
    ``truth.csv``: ``time``, ``object`` (the path id), ``x``, ``vx``, ``y``, ``vy`` [m,
    m/s] (a constant-velocity state). Both sorted by time. ``stonesoup.json``: the field
    names and the measurement noise standard deviations: [m] for a linear Gaussian model
    on x, y, and ([rad], [m]) for the bearing-range model (``bearing_range_noise``).

    Returns
    -------
    dict
        The paths written.
    """
    from .dataset import atomic_path

    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    det = {k: np.asarray(v) for k, v in detections.items()}
    ok = np.isfinite(det["x_m"]) & np.isfinite(det["y_m"])
    order = np.argsort(det["time_s"][ok], kind="stable")
    sel = {k: v[ok][order] for k, v in det.items()}
    cols = {"time": sel["time_s"], "x": sel["x_m"], "y": sel["y_m"]}
    polar = all(k in sel for k in ("azimuth_deg", "radar_x_m", "radar_y_m"))
    if polar:
        cols["bearing_rad"] = bearing_from_azimuth(sel["azimuth_deg"])
        cols["ground_range_m"] = np.hypot(sel["x_m"] - sel["radar_x_m"],
                                          sel["y_m"] - sel["radar_y_m"])
    cols.update({k: v for k, v in sel.items() if k not in ("time_s", "x_m", "y_m")})
    p_det = write_table(d / STONESOUP_FILES["detections"], cols)
    tr = {k: np.asarray(v) for k, v in truth.items()}
    order = np.lexsort((tr["object"].astype(str), tr["time_s"]))
    tcols = {"time": tr["time_s"][order], "object": tr["object"][order],
             "x": tr["x_m"][order], "vx": tr["vx_m_s"][order], "y": tr["y_m"][order],
             "vy": tr["vy_m_s"][order]}
    p_truth = write_table(d / STONESOUP_FILES["truth"], tcols)
    settings = {"detections": STONESOUP_FILES["detections"],
                "truth": STONESOUP_FILES["truth"], "time_field": "time", "timestamp": True,
                "detection_fields": ["x", "y"], "truth_fields": ["x", "vx", "y", "vy"],
                "path_id_field": "object",
                "measurement_noise_m": [float(noise_m[0]), float(noise_m[1])],
                "state_mapping": [0, 2], "measurement": "cartesian"}
    if polar:
        if bearing_range_noise is None:
            raise ValueError("PPI plots: give bearing_range_noise (bearing [rad], range "
                             "[m]) for the bearing-range model")
        settings.update(measurement="bearing-range",
                        bearing_range_fields=["bearing_rad", "ground_range_m"],
                        sensor_fields=["radar_x_m", "radar_y_m"],
                        bearing_range_noise=[float(v) for v in bearing_range_noise])
    p_set = d / STONESOUP_FILES["settings"]
    with atomic_path(p_set) as tmp:
        tmp.write_text(json.dumps(settings, indent=1) + "\n", encoding="utf-8")
    return {"detections": p_det, "truth": p_truth, "settings": p_set}


def bearing_from_azimuth(azimuth_deg: NDArray) -> NDArray:
    """Stone Soup's bearing phi [rad], counter-clockwise from east (+x) in [-pi, pi), of
    azimuths clockwise from north (+y) [deg]: phi = pi/2 - azimuth."""
    phi = 0.5 * np.pi - np.deg2rad(np.asarray(azimuth_deg, dtype=float))
    return (phi + np.pi) % (2.0 * np.pi) - np.pi


#: Measurement models :func:`stonesoup_readers` attaches.
MEASUREMENTS = ("auto", "cartesian", "bearing-range")


def stonesoup_readers(directory: str | os.PathLike, measurement: str = "auto",
                      noise: tuple[float, float] | None = None) -> tuple:
    """Stone Soup readers of a :func:`write_stonesoup` export.

    Parameters
    ----------
    directory : path
        The export (``stonesoup.json`` and the two CSV files).
    measurement : {'auto', 'cartesian', 'bearing-range'}
        'cartesian': every detection is (x, y) [m] with a
        :class:`~stonesoup.models.measurement.linear.LinearGaussian` model on the
        constant-velocity state (x, vx, y, vy). 'bearing-range' (PPI sweeps only): every
        detection is (phi [rad], ground range [m]) with a
        :class:`~stonesoup.models.measurement.nonlinear.CartesianToBearingRange` model
        whose ``translation_offset`` is the radar's x, y at that plot (a moving radar
        gives each plot its own). 'auto': bearing-range where the export has it.
    noise : (float, float), optional
        The model's standard deviations in place of the export's: (sigma_x, sigma_y) [m]
        or (sigma_phi [rad], sigma_r [m]).

    Returns
    -------
    (CSVDetectionReader, CSVGroundTruthReader)
        Times are seconds since the scene's t = 0 read as seconds since 1970-01-01 UTC.
    """
    s = json.loads((Path(directory) / STONESOUP_FILES["settings"]).read_text(
        encoding="utf-8"))
    if measurement not in MEASUREMENTS:
        raise ValueError(f"measurement = {measurement!r}: allowed "
                         f"{', '.join(MEASUREMENTS)}")
    has_polar = s.get("measurement") == "bearing-range"
    if measurement == "bearing-range" and not has_polar:
        raise ValueError("measurement = 'bearing-range': the export has no bearing and "
                         "ground range (PPI sweeps only)")
    polar = has_polar if measurement == "auto" else measurement == "bearing-range"
    try:
        from stonesoup.reader.generic import CSVGroundTruthReader
    except ImportError as exc:  # pragma: no cover - the tracking extra
        raise ImportError("Stone Soup is needed: pip install 'seaecho[tracking]'") from exc

    d = Path(directory)
    if polar:
        sb, sr = noise if noise is not None else s["bearing_range_noise"]
        det = _stonesoup_reader_class()(
            path=d / s["detections"], state_vector_fields=s["bearing_range_fields"],
            time_field=s["time_field"], timestamp=s["timestamp"],
            noise_covar=np.diag([sb * sb, sr * sr]), sensor_fields=s["sensor_fields"],
            mapping=tuple(s["state_mapping"]), csv_options={"dialect": "excel"})
    else:
        sx, sy = noise if noise is not None else s["measurement_noise_m"]
        det = _stonesoup_reader_class()(
            path=d / s["detections"], state_vector_fields=s["detection_fields"],
            time_field=s["time_field"], timestamp=s["timestamp"],
            noise_covar=np.diag([sx * sx, sy * sy]), mapping=tuple(s["state_mapping"]),
            csv_options={"dialect": "excel"})
    truth = CSVGroundTruthReader(
        path=d / s["truth"], state_vector_fields=s["truth_fields"],
        time_field=s["time_field"], timestamp=s["timestamp"],
        path_id_field=s["path_id_field"])
    return det, truth


@functools.cache
def _stonesoup_reader_class():
    """A CSVDetectionReader whose detections carry a measurement model (built on first
    use: Stone Soup is an optional dependency)."""
    from stonesoup.base import Property
    from stonesoup.buffered_generator import BufferedGenerator
    from stonesoup.models.measurement.linear import LinearGaussian
    from stonesoup.models.measurement.nonlinear import CartesianToBearingRange
    from stonesoup.reader.generic import CSVDetectionReader
    from stonesoup.types.angle import Bearing
    from stonesoup.types.array import StateVector

    class SeaechoCSVDetectionReader(CSVDetectionReader):
        """:class:`~stonesoup.reader.generic.CSVDetectionReader` that gives every
        detection a measurement model on the state (x, vx, y, vy): linear on (x, y),
        or bearing-range from the radar's position in ``sensor_fields``."""

        noise_covar: np.ndarray = Property(doc="Measurement noise covariance")
        mapping: tuple = Property(default=(0, 2), doc="State indices of x and y")
        sensor_fields: list = Property(
            default=None, doc="Fields of the radar's x, y: a bearing-range model")

        @BufferedGenerator.generator_method
        def detections_gen(self):
            linear = LinearGaussian(ndim_state=4, mapping=self.mapping,
                                    noise_covar=self.noise_covar)
            models = {}
            for time, dets in super().detections_gen():
                for d in dets:
                    if self.sensor_fields is None:
                        d.measurement_model = linear
                        continue
                    key = tuple(float(d.metadata[f]) for f in self.sensor_fields)
                    if key not in models:  # one model per radar position
                        models[key] = CartesianToBearingRange(
                            ndim_state=4, mapping=self.mapping,
                            noise_covar=self.noise_covar,
                            translation_offset=StateVector(list(key)))
                    d.measurement_model = models[key]
                    d.state_vector = StateVector([Bearing(float(d.state_vector[0, 0])),
                                                  float(d.state_vector[1, 0])])
                yield time, dets

    return SeaechoCSVDetectionReader
