"""A detector run over frames of cells, with detections and opportunities as tables.

A :class:`Frame` is what every product becomes for detection: a 2-D array of power
``(rows, cols)`` whose rows belong to looks (a pulse of range profiles, a sweep of a PPI,
one image), the time of each row, where each cell is in the space where objects are
gated (range for range profiles, x and y for PPI sweeps and images), the objects'
positions in that space at each row's time, their gates, and a function from fractional
cell indices to positions. :func:`detect_frames` runs a detector on each frame, extracts
plots, associates them with objects and lists the opportunities (one object in one look)
with their SNR: the inputs of :func:`seaecho.detection.scoring.score_tables`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from .association import interpolate_truth, nearest_object
from .cfar import Censored
from .clutter_map import m_of_n
from .plots import extract_plots

__all__ = ["Frame", "ObjectTruth", "detect_frames", "opportunity_groups",
           "opportunity_visible"]


@dataclass(frozen=True)
class ObjectTruth:
    """Where the objects are: positions per time (the one input of the association).

    Attributes
    ----------
    time_s : ndarray
        (t,) increasing times [s].
    position_m : ndarray
        (t, object, 3) positions [m] (NaN where an object does not exist).
    names : tuple of str
        (object,) names.
    extent_m : ndarray
        (object,) largest dimension of each object [m] (0 for a point target).
    visible : ndarray of bool, optional
        (t, object): whether the radar can see each object at each time (the run's
        ``truth_visible``: in the window, above the horizon, not behind the land or a
        crest); None: always. An opportunity of a hidden object is scored apart
        (:func:`seaecho.detection.scoring.score_tables`).
    """

    time_s: NDArray
    position_m: NDArray
    names: tuple[str, ...]
    extent_m: NDArray
    visible: NDArray | None = None

    def __post_init__(self):
        pos = np.asarray(self.position_m, dtype=float)
        t = np.asarray(self.time_s, dtype=float)
        if pos.ndim != 3 or pos.shape[0] != t.size or pos.shape[2] != 3:
            raise ValueError(f"position_m of shape {pos.shape}: must be (time, object, 3) "
                             f"with {t.size} times")
        if t.size > 1 and np.any(np.diff(t) <= 0):
            raise ValueError("time_s: the truth's times must increase")
        if len(self.names) != pos.shape[1] or np.shape(self.extent_m) != (pos.shape[1],):
            raise ValueError(f"names ({len(self.names)}) and extent_m "
                             f"{np.shape(self.extent_m)}: one per object ({pos.shape[1]})")
        if self.visible is not None and np.shape(self.visible) != pos.shape[:2]:
            raise ValueError(f"visible of shape {np.shape(self.visible)}: must be (time, "
                             f"object) = {pos.shape[:2]}")

    def at(self, time_s: NDArray) -> NDArray:
        """(n, object, 3) positions at ``time_s`` [m] (linear in time)."""
        return interpolate_truth(self.time_s, self.position_m, time_s)

    def visible_at(self, time_s: NDArray) -> NDArray:
        """(n, object) visibility at ``time_s``: that of the latest truth time at or
        before each (the first before the truth starts); all True without ``visible``."""
        t = np.asarray(time_s, dtype=float)
        if self.visible is None:
            return np.ones((t.size, len(self.names)), bool)
        k = np.clip(np.searchsorted(np.asarray(self.time_s, dtype=float), t, side="right")
                    - 1, 0, len(self.time_s) - 1)
        return np.asarray(self.visible, dtype=bool)[k]

    @classmethod
    def empty(cls) -> ObjectTruth:
        """No object."""
        return cls(np.zeros(1), np.zeros((1, 0, 3)), (), np.zeros(0))


@dataclass
class Frame:
    """One array of cells for a detector.

    Attributes
    ----------
    kind : {'profile', 'ppi', 'image'}
    power : ndarray
        (rows, cols) power [W] (profiles, sweeps) or RCS [m^2] (images).
    look : ndarray of int
        (rows,) look of each row (profiles: the pulse; a sweep or an image: one look).
    time_s : ndarray
        (rows,) time of each row [s].
    cell_coord : ndarray
        Broadcastable to (rows, cols, d): each cell in the gating space [m].
    truth_coord : ndarray
        (rows, object, d): the objects in the gating space at each row's time [m] (NaN:
        absent).
    gate_m : ndarray
        (object,) gate of each object [m].
    locate : callable
        ``(row, col) -> dict of columns`` for fractional indices (n,) each: ``x_m``,
        ``y_m``, ``range_m`` and the kind's own (``pulse``; ``sweep``, ``azimuth_deg``).
    truth_xyz : ndarray
        (rows, object, 3) object positions at each row's time [m].
    ndim : int
        1: cells join along columns only (range profiles); 2: over both axes.
    cell_area_m2 : float or ndarray
        Area of each cell [m^2], broadcastable to (rows, cols) (NaN when unknown): the
        sum over the tested cells that have one, per look, is the area a look covers.
    truth_visible : ndarray of bool, optional
        (rows, object): whether the radar can see each object at each row's time
        (:meth:`ObjectTruth.visible_at`); None: always.
    blanked : ndarray of bool, optional
        Broadcastable to (rows, cols): cells left untested whatever the detector (the
        land mask, :func:`seaecho.detection.landmask.land_mask`), and kept out of the
        training windows by a censored detector (:func:`detect_frames`' ``censored``).
    """

    kind: str
    power: NDArray
    look: NDArray
    time_s: NDArray
    cell_coord: NDArray
    truth_coord: NDArray
    gate_m: NDArray
    locate: Callable[[NDArray, NDArray], dict]
    truth_xyz: NDArray
    ndim: int = 1
    cell_area_m2: float | NDArray = float("nan")
    extra: dict = field(default_factory=dict)
    truth_visible: NDArray | None = None
    blanked: NDArray | None = None


def opportunity_groups(frame: Frame, tested: NDArray, first_group: int = 0,
                       exclusion: float = 1.0) -> tuple[NDArray, dict[str, NDArray]]:
    """Label each cell with its opportunity (look, object) when inside the object's gate.

    Parameters
    ----------
    frame : Frame
    tested : ndarray of bool
        (rows, cols) cells the detector tests.
    first_group : int
        Label of the frame's first opportunity (labels run on across frames).
    exclusion : float
        Cells beyond an object's gate but within ``exclusion`` gates of it are labelled
        -2: neither the object nor the background (its own range sidelobes and spread,
        which a ROC should not count as false alarms of the background).

    Returns
    -------
    groups : ndarray of int
        (rows, cols): opportunity label, -1 for the background, -2 in an exclusion zone.
    table : dict
        Per opportunity: ``look``, ``object``, ``row`` (the first row of the look
        where the object is inside the tested cells).
    """
    rows, cols = frame.power.shape
    n_obj = frame.truth_coord.shape[1]
    groups = -np.ones((rows, cols), np.int64)
    looks = np.unique(frame.look)
    look_index = np.searchsorted(looks, frame.look)
    rec_look, rec_obj, rec_row = [], [], []
    cell = np.broadcast_to(frame.cell_coord, (rows, cols, frame.cell_coord.shape[-1]))
    label = first_group
    for o in range(n_obj):  # a few objects; every cell at once
        d = np.sqrt(((cell - frame.truth_coord[:, o, None, :]) ** 2).sum(-1))
        inside = (d <= frame.gate_m[o]) & tested
        if exclusion > 1.0:
            near = (d <= exclusion * frame.gate_m[o]) & ~inside & (groups == -1)
            groups = np.where(near, -2, groups)
        seen = np.zeros(looks.size, bool)
        seen[np.unique(look_index[inside.any(axis=1)])] = True
        ids = np.full(looks.size, -1, np.int64)
        ids[seen] = label + np.arange(seen.sum())
        label += int(seen.sum())
        g = ids[look_index][:, None]
        groups = np.where(inside & (groups < 0), g, groups)  # an exclusion gives way
        # the opportunity's row: the first of its look where the object is in the cells
        any_row = np.flatnonzero(inside.any(axis=1))
        first = np.full(looks.size, rows, np.int64)
        np.minimum.at(first, look_index[any_row], any_row)
        rec_look.append(looks[seen])
        rec_obj.append(np.full(int(seen.sum()), o))
        rec_row.append(first[seen])

    def cat(v):
        return np.concatenate(v) if v else np.zeros(0, np.int64)

    return groups, {"look": cat(rec_look), "object": cat(rec_obj), "row": cat(rec_row)}


def opportunity_visible(frame: Frame, table: dict[str, NDArray]) -> NDArray:
    """Whether the truth lets the radar see each opportunity of
    :func:`opportunity_groups`'s ``table``: the frame's ``truth_visible`` at the
    opportunity's first row (the row that first puts the object in the tested cells);
    all True without it. The one rule for every product: an opportunity the truth hides
    is scored apart (:func:`seaecho.detection.scoring.score_tables`, and the ROC's P_D
    leaves it out)."""
    n = table["look"].size
    if frame.truth_visible is None or not n:
        return np.ones(n, bool)
    return np.asarray(frame.truth_visible, dtype=bool)[table["row"], table["object"]]


def detect_frames(frames: list[Frame], noise: Callable[[NDArray], NDArray],
                  alpha: float, *, integrate: tuple[int, int] | None = None,
                  censored: Callable[[NDArray, NDArray], Censored] | None = None
                  ) -> tuple[dict[str, NDArray], dict[str, NDArray], dict]:
    """Run a detector on frames: plots, their objects, and the opportunities.

    Parameters
    ----------
    frames : list of Frame
    noise : callable
        ``power (rows, cols) -> noise estimate`` (NaN where not tested), e.g.
        :meth:`seaecho.detection.cfar.CFAR.noise`.
    alpha : float
        Threshold multiplier: a cell is detected where power > alpha x noise.
    integrate : (M, N), optional
        M-of-N over consecutive rows (pulses) before the plots: a cell of row i is
        declared when it crossed in at least M of rows i - N + 1 .. i.
    censored : callable, optional
        ``(power, exclude) -> Censored``: for frames with ``blanked`` cells, the
        estimate and per-cell alpha with those cells left out of the training windows
        (:meth:`seaecho.detection.cfar.CFAR.censored` at the design P_FA); without it
        the blanked cells are only left untested.

    Returns
    -------
    detections : dict
        Per plot: ``look``, ``time_s``, ``object`` (-1: false alarm), ``power``,
        ``snr`` (linear), ``n_cells`` and the columns of ``Frame.locate``.
    opportunities : dict
        Per (look, object): ``look``, ``object``, ``time_s``, ``x_m``, ``y_m``,
        ``snr`` (largest power / noise - 1 in the gate, linear), ``group``,
        ``visible`` (the truth's, at the opportunity's first row:
        :func:`opportunity_visible`).
    totals : dict
        ``cells_tested``, ``n_looks``, ``area_m2`` (per look), ``cells_censored``
        (tested with a window that lost cells) and ``cells_short`` (left untested: too
        few cells kept), and ``groups`` / ``statistic`` per frame for ROC curves.
    """
    det: dict[str, list] = {}
    opp: dict[str, list] = {}
    cells, looks, areas, next_group = 0, 0, [], 0
    n_censored = n_short = 0
    for fr in frames:
        thr = alpha
        if fr.blanked is not None and censored is not None:  # land kept out of windows
            c = censored(fr.power, fr.blanked)
            est, thr = c.noise, c.alpha
            n_censored += c.n_censored
            n_short += int(c.short.sum())
        else:
            est = noise(fr.power)
            if fr.blanked is not None:  # the land mask: never tested
                est = np.where(np.broadcast_to(fr.blanked, est.shape), np.nan, est)
        with np.errstate(divide="ignore", invalid="ignore"):
            stat = fr.power / est
        tested = np.isfinite(stat) & np.isfinite(thr)
        with np.errstate(invalid="ignore"):
            hits = stat > thr  # the statistic CFAR.detect and the ROC compare, bit for bit
        if integrate is not None:
            m, n = integrate
            mofn = m_of_n(hits, m, n, axis=0)
            hits = np.zeros_like(hits)
            hits[n - 1:] = mofn
            tested[:n - 1] = False
        cells += int(tested.sum())
        looks += int(np.unique(fr.look[tested.any(axis=1)]).size)
        n_fr = max(int(np.unique(fr.look[tested.any(axis=1)]).size), 1)
        # the sea a look covers: its tested cells with an area (a range profile's gates
        # nearer than the radar's height or beyond the horizon have none)
        cell_area = np.broadcast_to(fr.cell_area_m2, tested.shape)[tested]
        finite = np.isfinite(cell_area)
        areas.append(float(cell_area[finite].sum()) / n_fr if finite.any() else np.nan)
        p = extract_plots(fr.power, hits, np.where(tested, est, np.nan), ndim=fr.ndim)
        row, col = p["centroid"][:, 0], p["centroid"][:, 1]
        peak_row = p["peak_index"][:, 0]
        cols = fr.locate(row, col)
        coord = np.broadcast_to(fr.cell_coord, fr.power.shape + (fr.cell_coord.shape[-1],))
        # the plot's position in the gating space: interpolated at its centroid
        r0 = np.clip(np.floor(row).astype(np.int64), 0, fr.power.shape[0] - 1)
        c0 = np.clip(np.floor(col).astype(np.int64), 0, fr.power.shape[1] - 2)
        f = (col - c0)[:, None]
        where = (1.0 - f) * coord[r0, c0] + f * coord[r0, c0 + 1]
        # the objects where they are at the plot's peak row
        obj = nearest_object(where, fr.truth_coord[peak_row], fr.gate_m)
        cols.update(look=fr.look[peak_row], time_s=fr.time_s[peak_row], object=obj,
                    power=p["peak_power"], snr=p["snr"], n_cells=p["n_cells"])
        for k, v in cols.items():
            det.setdefault(k, []).append(np.asarray(v))
        groups, table = opportunity_groups(fr, tested, next_group)
        n_g = table["look"].size
        peak = np.full(n_g, -np.inf)
        sel = groups >= 0
        with np.errstate(invalid="ignore"):
            np.maximum.at(peak, groups[sel] - next_group, stat[sel])
        rows_ = table["row"]
        xyz = fr.truth_xyz[rows_, table["object"]] if n_g else np.zeros((0, 3))
        opp_cols = {"look": table["look"], "object": table["object"],
                    "time_s": fr.time_s[rows_], "x_m": xyz[:, 0], "y_m": xyz[:, 1],
                    "snr": np.maximum(peak - 1.0, 1e-12),
                    "group": next_group + np.arange(n_g),
                    "visible": opportunity_visible(fr, table)}
        for k, v in opp_cols.items():
            opp.setdefault(k, []).append(np.asarray(v))
        fr.extra["groups"], fr.extra["statistic"] = groups, stat
        next_group += n_g
    detections = {k: np.concatenate(v) for k, v in det.items()}
    opportunities = {k: np.concatenate(v) for k, v in opp.items()}
    order = np.lexsort((detections.get("x_m", np.zeros(0)), detections["time_s"])) \
        if detections else np.zeros(0, np.int64)
    detections = {k: v[order] for k, v in detections.items()}
    finite = [a for a in areas if np.isfinite(a)]
    totals = {"cells_tested": cells, "n_looks": looks,
              "area_m2": float(np.mean(finite)) if finite else float("nan"),
              "cells_censored": n_censored, "cells_short": n_short}
    return detections, opportunities, totals
