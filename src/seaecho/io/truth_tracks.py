"""Ground-truth tracks of a run as a tidy table: one row per (pulse, object).

Reads the ``truth_*`` variables that ``seaecho run`` writes (:mod:`seaecho.radar.truth`)
and writes them as CSV, the form trackers and detection scorers read (e.g. Stone Soup's
``CSVGroundTruthReader``: a time column, an id column, state columns).

Columns: ``pulse, time_s, object, kind, x_m, y_m, z_m, vx_m_s, vy_m_s, vz_m_s,
heading_deg, rcs_hh_m2, rcs_hv_m2, rcs_vh_m2, rcs_vv_m2, rcs_known, range_m,
range_cell, in_window, above_horizon, visible, hidden_reason`` (heading
counter-clockwise from east, as every angle of the scene; range_cell -1 outside the
receive window; hidden_reason the name of ``truth_hidden_reason``'s flag: visible,
outside_window, below_horizon, behind_land, behind_waves; empty for a file written
before it).
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from .dataset import atomic_path

COLUMNS = ("pulse", "time_s", "object", "kind", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s",
           "vz_m_s", "heading_deg", "rcs_hh_m2", "rcs_hv_m2", "rcs_vh_m2", "rcs_vv_m2",
           "rcs_known", "range_m", "range_cell", "in_window", "above_horizon", "visible",
           "hidden_reason")


def truth_rows(ds) -> list[tuple]:
    """The rows of :data:`COLUMNS` of a run dataset, pulse-major.

    Raises
    ------
    ValueError
        The dataset has no ground truth (no ship or target, or written before it).
    """
    if "truth_position" not in ds:
        raise ValueError("the dataset has no ground truth (truth_position): a run of a scene "
                         "with ships or targets, written by this version, has it")
    pos = np.asarray(ds["truth_position"].values)
    n_p, n_o = pos.shape[:2]
    pulse = np.repeat(np.asarray(ds["pulse"].values), n_o)
    time = np.repeat(np.asarray(ds["time"].values), n_o)
    # plain str (a Zarr store reads strings back as numpy's StringDType)
    names = [str(v) for v in ds["object"].values] * n_p
    kinds = [str(v) for v in ds["object_kind"].values] * n_p
    vel = np.asarray(ds["truth_velocity"].values).reshape(-1, 3)
    rcs = np.asarray(ds["truth_rcs"].values).reshape(-1, 4)
    known = np.tile(np.asarray(ds["truth_rcs_known"].values), n_p)
    flat = {k: np.asarray(ds[f"truth_{k}"].values).reshape(-1)
            for k in ("heading", "range", "range_cell", "in_window", "above_horizon",
                      "visible")}
    heading = np.rad2deg(flat["heading"])
    reason = [""] * (n_p * n_o)
    if "truth_hidden_reason" in ds:
        meanings = str(ds["truth_hidden_reason"].attrs["flag_meanings"]).split()
        reason = [meanings[int(r)] for r in
                  np.asarray(ds["truth_hidden_reason"].values).reshape(-1)]
    pos = pos.reshape(-1, 3)
    return [(int(pulse[i]), float(time[i]), str(names[i]), str(kinds[i]),
             *map(float, pos[i]), *map(float, vel[i]), float(heading[i]), *map(float, rcs[i]),
             int(known[i]), float(flat["range"][i]), int(flat["range_cell"][i]),
             int(flat["in_window"][i]), int(flat["above_horizon"][i]), int(flat["visible"][i]),
             reason[i])
            for i in range(pos.shape[0])]


def write_truth_csv(ds, path: str | os.PathLike) -> Path:
    """Write :func:`truth_rows` with a header of :data:`COLUMNS` to ``path`` (atomic)."""
    rows = truth_rows(ds)
    path = Path(path)
    with atomic_path(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerows(rows)
    return path


__all__ = ["COLUMNS", "truth_rows", "write_truth_csv"]
