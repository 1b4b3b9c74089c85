"""The scans of a scanning radar as CfRadial 2 / WMO FM 301 sweeps (the xradar layout).

A run whose antenna scans (``[transmitter.antenna.scan]``, or the receiver's) has, per
pulse, the boresight in the world (``tx_antenna_axes``, ``rx_antenna_axes``: the
scanning one's is used, the transmitter's if both scan) and the sweep index (``sweep``:
a revolution or one pass of a sector). :func:`ppi_tree` regroups its range-compressed
pulses into the CfRadial 2 tree that xradar reads and writes:

- root: the global attributes (``Conventions = "Cf/Radial"``, ``version = "2.0"``,
  ``instrument_name``, ``time_coverage_start``/``_end``...), the variables
  ``volume_number``, ``platform_type``, ``instrument_type``, ``time_coverage_start``,
  ``time_coverage_end``, ``sweep_group_name`` and ``sweep_fixed_angle``, and the
  radar's ``latitude``/``longitude``/``altitude``;
- one group ``sweep_N`` per sweep, in time order, with dims ``azimuth`` (one ray per
  pulse, no averaging) x ``range``: coordinates ``azimuth`` [deg] clockwise from north
  as CfRadial defines it (here grid north, the scene's +y; 0 to 360), ``elevation``
  [deg] of the boresight above the local horizontal (negative: depressed), ``time``
  per ray (the pulse's emission time, ``seconds since`` an epoch that stands for the
  scene's t = 0) and ``range`` [m] to the centre of each gate (c tau / 2, half the
  bistatic path); data variables, per channel c of the run, ``{c}_re`` and ``{c}_im``
  (the range-compressed complex samples, float32, [sqrt(W)] as the run's
  ``compressed``) and ``{c}_power`` = 10 log10 |compressed|^2 [dB re 1 W]; and the
  sweep's ``sweep_number``, ``sweep_mode`` ('azimuth_surveillance' or 'sector'),
  ``fixed_angle`` [deg] (the antenna's depression as an elevation), ``follow_mode``,
  ``prt_mode``, ``polarization_mode``.

seaecho has no geodetic anchor: ``latitude`` and ``longitude`` are 0 and 0, and the
Cartesian ``x`` (east) and ``y`` (north) that xradar's ``georeference`` computes are
metres from the radar. The azimuth of a ray is that of the boresight in the world:
on a rolling, yawing ship it includes the attitude (the product is "north-up").

References
----------
.. [1] NCAR/EOL, *CfRadial Data File Format*, version 2.0 (2020), chapters 4-6; WMO,
   *Manual on Codes*, WMO-No. 306, Vol. I.2, FM 301 (the same layout).
.. [2] xradar documentation, "Data Model" (the DataTree with ``sweep_N`` groups,
   dims ``azimuth`` x ``range``).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

#: Epoch that stands for the scene's t = 0 in the product's time units.
EPOCH = "1970-01-01T00:00:00Z"
#: A power floor [W] below which 10 log10 is clipped (no -inf in the file).
POWER_FLOOR_W = 1.0e-30


def boresight_angles(axes) -> tuple[np.ndarray, np.ndarray]:
    """(azimuth clockwise from north in [0, 360), elevation) [deg] of the boresight
    columns of antenna axes (..., 3, 3) in the world (x east, y north, z up)."""
    b = np.asarray(axes, dtype=float)[..., :, 0]
    az = np.mod(np.degrees(np.arctan2(b[..., 0], b[..., 1])), 360.0)
    el = np.degrees(np.arcsin(np.clip(b[..., 2], -1.0, 1.0)))
    return az, el


def ppi_tree(run):
    """The CfRadial 2 tree of a scanning run's sweeps (module docstring).

    Parameters
    ----------
    run : xarray.Dataset
        A run of ``seaecho run`` whose antenna scans (it has ``sweep``).

    Returns
    -------
    xarray.DataTree
    """
    import xarray as xr

    if "sweep" not in run:
        raise ValueError("the run's antenna does not scan (no 'sweep' variable): a PPI "
                         "product needs [transmitter.antenna.scan] mode 'rotating' or "
                         "'sector'")
    sweep = np.asarray(run["sweep"].values)
    t = np.asarray(run["time"].values, dtype=float)
    # the scanning antenna's boresight (the transmitter's, else the receiver's)
    scanner = run["sweep"].attrs.get("scan_antenna", "tx")
    az, el = boresight_angles(run[f"{scanner}_antenna_axes"].values)
    rng = np.asarray(run["range"].values, dtype=float)
    channels = [str(c) for c in run["channel"].values]
    position = np.asarray(run[f"{scanner}_position"].values, dtype=float)
    mode = run["sweep"].attrs.get("scan_mode", "rotating")
    sweep_mode = "sector" if mode == "sector" else "azimuth_surveillance"
    time_attrs = {"units": f"seconds since {EPOCH}", "standard_name": "time",
                  "long_name": "emission time of the ray's pulse; the epoch stands for "
                  "the scene's t = 0"}
    numbers = list(dict.fromkeys(sweep.tolist()))  # in order of appearance (time)
    groups, fixed = {}, []
    for i, k in enumerate(numbers):
        rows = np.flatnonzero(sweep == k)
        data = run["compressed"].isel(pulse=rows).values  # (ray, channel, range)
        fixed_angle = float(np.median(el[rows]))
        fixed.append(fixed_angle)
        variables = {}
        for c, name in enumerate(channels):
            z = data[:, c, :]
            p = np.maximum(np.abs(z) ** 2, POWER_FLOOR_W)
            variables[f"{name}_power"] = (("azimuth", "range"), (10.0 * np.log10(p))
                                          .astype(np.float32), {
                "units": "dB", "long_name": f"range-compressed power, channel {name} "
                "(receive port, transmit port), 10 log10 |s|^2 re 1 W",
                "coordinates": "elevation azimuth range"})
            for part, f in (("re", np.real), ("im", np.imag)):
                variables[f"{name}_{part}"] = (("azimuth", "range"),
                                               f(z).astype(np.float32), {
                    "units": "sqrt(W)", "long_name": f"range-compressed sample, channel "
                    f"{name}, {'real' if part == 're' else 'imaginary'} part",
                    "coordinates": "elevation azimuth range"})
        variables.update({
            "sweep_number": ((), np.int32(i), {"long_name": "sweep index in the volume"}),
            "sweep_mode": ((), sweep_mode, {"long_name": "scan mode of the sweep"}),
            "fixed_angle": ((), np.float32(fixed_angle),
                            {"units": "degrees", "long_name": "target fixed angle "
                             "(elevation of the boresight)"}),
            "follow_mode": ((), "none", {}),
            "prt_mode": ((), "fixed", {}),
            "polarization_mode": ((), "not_set" if len(channels) > 1 else "horizontal"
                                  if channels[0] == "HH" else "vertical"
                                  if channels[0] == "VV" else "not_set", {}),
        })
        coords = {
            "azimuth": ("azimuth", az[rows], {
                "units": "degrees", "standard_name": "ray_azimuth_angle",
                "long_name": "azimuth of the boresight, clockwise from grid north (+y)",
                "axis": "radial_azimuth_coordinate"}),
            "elevation": ("azimuth", el[rows], {
                "units": "degrees", "standard_name": "ray_elevation_angle",
                "long_name": "elevation of the boresight above the horizontal",
                "axis": "radial_elevation_coordinate"}),
            "time": ("azimuth", t[rows], time_attrs),
            "range": ("range", rng, {
                "units": "meters", "standard_name": "projection_range_coordinate",
                "long_name": "range to the centre of the gate (c tau / 2)",
                "axis": "radial_range_coordinate", "meters_to_center_of_first_gate":
                float(rng[0]), "meters_between_gates": float(rng[1] - rng[0])
                if rng.size > 1 else 0.0}),
            "latitude": ((), 0.0, {"units": "degrees_north", "standard_name": "latitude",
                                   "long_name": "no geodetic anchor: 0"}),
            "longitude": ((), 0.0, {"units": "degrees_east", "standard_name": "longitude",
                                    "long_name": "no geodetic anchor: 0"}),
            "altitude": ((), float(position[rows[0], 2]), {
                "units": "meters", "standard_name": "altitude",
                "long_name": "antenna height above the mean sea surface"}),
        }
        groups[f"sweep_{i}"] = xr.Dataset(variables, coords=coords)
    names = list(groups)
    start, end = float(t.min()), float(t.max())

    def iso(seconds: float) -> str:
        return str(np.datetime64(EPOCH.rstrip("Z")) + np.timedelta64(
            int(round(seconds * 1e9)), "ns")) + "Z"

    root = xr.Dataset(
        {"volume_number": ((), np.int32(0)),
         "platform_type": ((), "fixed" if np.ptp(position[:, :2], axis=0).max() == 0
                           else "ship"),
         "instrument_type": ((), "radar"),
         "time_coverage_start": ((), iso(start)),
         "time_coverage_end": ((), iso(end)),
         "sweep_group_name": (("sweep",), np.array(names)),
         "sweep_fixed_angle": (("sweep",), np.array(fixed, dtype=np.float32),
                               {"units": "degrees"})},
        coords={"latitude": ((), 0.0, {"units": "degrees_north"}),
                "longitude": ((), 0.0, {"units": "degrees_east"}),
                "altitude": ((), float(position[0, 2]), {"units": "meters"})},
        attrs={"Conventions": "Cf/Radial", "version": "2.0",
               "title": _scene_name(run) or "seaecho scanning radar",
               "instrument_name": "seaecho",
               "source": f"seaecho {run.attrs.get('seaecho_version', '')}".strip(),
               "institution": "", "references": "doi:10.1109/RADAR.2006.1631862",
               "comment": "simulated; azimuth clockwise from grid north (+y of the scene); "
               "latitude/longitude 0: no geodetic anchor, x/y from georeference are "
               "metres east/north of the radar",
               "time_coverage_start": iso(start), "time_coverage_end": iso(end),
               "carrier_frequency_hz": float(run.attrs.get("carrier_frequency_hz", 0.0)),
               "prf_hz": float(run.attrs.get("prf_hz", 0.0))})
    return xr.DataTree.from_dict({"/": root, **{f"/{k}": v for k, v in groups.items()}})


def write_ppi(run, path: str | os.PathLike) -> Path:
    """Write :func:`ppi_tree` of a scanning run to a netCDF-4 file (atomically)."""
    from .dataset import atomic_path

    tree = ppi_tree(run)
    path = Path(path)
    with atomic_path(path) as tmp:
        tree.to_netcdf(tmp, engine="h5netcdf")
    return path


def _scene_name(run) -> str:
    """The scene's name from the run's ``scene_json`` attribute ('' without one)."""
    import json

    try:
        return str(json.loads(run.attrs.get("scene_json", "{}")).get("name", ""))
    except ValueError:
        return ""


def ppi_figures(run, stem: str | os.PathLike, dynamic_range_db: float = 60.0,
                max_sweeps: int = 8) -> list[Path]:
    """A PPI figure per sweep, ``<stem>_ppi_sweep<N>.png`` (the first ``max_sweeps``).

    Range-compressed power [dB] of the run's first channel, drawn on the plane: x east
    and y north of the radar, x = r sin(az), y = r cos(az) with az the ray's azimuth
    clockwise from north and r its range (the slant range, as a radar's PPI draws it).
    Truth from the run at the sweep's middle time, relative to the radar's position:
    every ship (triangle) and target (circle) of ``truth_position`` with its name, or,
    in a file without it, the point targets and the ship's hull centre.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .dataset import atomic_savefig

    tree = ppi_tree(run)
    stem = Path(stem)
    t_run = np.asarray(run["time"].values, dtype=float)
    out = []
    channel = str(run["channel"].values[0])
    for name in list(tree.children)[:max_sweeps]:
        sw = tree[name].to_dataset()
        # the rays in time order, unwrapped: a sweep turns one way (a sector crossing
        # north, a revolution from its start back to it)
        az = np.unwrap(np.radians(sw["azimuth"].values))
        r = sw["range"].values
        p = sw[f"{channel}_power"].values.astype(float)
        if az.size > 1 and az[-1] < az[0]:
            az, p = az[::-1], p[::-1]
        # cell edges: half-way between rays (a ray's own width at the ends) and gates
        if az.size > 1:
            mid = 0.5 * (az[1:] + az[:-1])
            a_edges = np.concatenate([[2 * az[0] - mid[0]], mid, [2 * az[-1] - mid[-1]]])
        else:
            a_edges = az[0] + np.array([-0.5, 0.5]) * np.radians(0.5)
        dr = r[1] - r[0] if r.size > 1 else 1.0
        r_edges = np.concatenate([r - 0.5 * dr, [r[-1] + 0.5 * dr]])
        x = r_edges[None, :] * np.sin(a_edges)[:, None]
        y = r_edges[None, :] * np.cos(a_edges)[:, None]
        top = float(p.max())
        fig, ax = plt.subplots(figsize=(6.6, 5.8), constrained_layout=True)
        im = ax.pcolormesh(x / 1e3, y / 1e3, p, shading="flat", cmap="viridis",
                           vmin=top - dynamic_range_db, vmax=top, rasterized=True)
        fig.colorbar(im, ax=ax, label=f"{channel} range-compressed power [dB re 1 W]")
        rows = np.flatnonzero(run["sweep"].values == int(name.split("_")[1])
                              + int(run["sweep"].values[0]))
        mid = rows[len(rows) // 2] if rows.size else 0
        scanner = run["sweep"].attrs.get("scan_antenna", "tx")
        radar = np.asarray(run[f"{scanner}_position"].values[mid], dtype=float)
        t_mid = t_run[mid]
        if "truth_position" in run:  # every ship and target of the run, named
            tp = np.asarray(run["truth_position"].values[mid], dtype=float)
            kinds = np.asarray(run["object_kind"].values).astype(str)
            names = np.asarray(run["object"].values).astype(str)
            for kind, mark, colour in (("ship", "^", "orange"), ("target", "o", "r")):
                sel = kinds == kind
                if np.any(sel):
                    ax.plot((tp[sel, 0] - radar[0]) / 1e3, (tp[sel, 1] - radar[1]) / 1e3,
                            mark, ms=9, mfc="none", mec=colour, mew=1.3,
                            label=f"{kind}s (truth)")
            for n, q in zip(names, tp, strict=True):
                ax.annotate(n, ((q[0] - radar[0]) / 1e3, (q[1] - radar[1]) / 1e3),
                            xytext=(5, 4), textcoords="offset points", fontsize=6,
                            color="w")
            ax.legend(loc="upper right", fontsize=8)
        elif "target_position" in run:
            tp = (run["target_position"].values + t_mid * run["target_velocity"].values)
            ax.plot((tp[:, 0] - radar[0]) / 1e3, (tp[:, 1] - radar[1]) / 1e3, "o", ms=9,
                    mfc="none", mec="r", mew=1.2, label="targets (truth)")
        if "ship_position" in run and "truth_position" not in run:
            sp = np.asarray(run["ship_position"].values[mid], dtype=float)
            ax.plot((sp[0] - radar[0]) / 1e3, (sp[1] - radar[1]) / 1e3, "^", ms=9,
                    mfc="none", mec="orange", mew=1.5, label="ship (truth)")
        if "target_position" in run or "ship_position" in run:
            ax.legend(loc="upper right", fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlabel("x east of the radar [km]")
        ax.set_ylabel("y north of the radar [km]")
        ax.set_title(f"{_scene_name(run)} PPI, {name} "
                     f"({str(sw['sweep_mode'].values)}), t = {t_mid:.2f} s", fontsize=9)
        out.append(atomic_savefig(fig, stem.with_name(f"{stem.name}_ppi_{name}.png"),
                                  dpi=110))
        plt.close(fig)
    return out


__all__ = ["EPOCH", "boresight_angles", "ppi_figures", "ppi_tree", "write_ppi"]
