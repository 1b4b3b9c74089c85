"""Scores of a detector against the ground truth: P_D per object and per SNR bin, false
alarms per look and per km^2, P_FA per cell, and ROC curves.

An *opportunity* is one object in one look (a pulse, a sweep or an image) inside the
tested cells; it is detected when at least one detection of that look belongs to the
object (:func:`seaecho.detection.association.associate`). An opportunity whose object the
truth marks hidden (behind the land, below the horizon, behind a crest: the run's
``truth_visible``) is no miss: the P_D leave it out and it is counted apart. A detection
that belongs to no object is a false alarm; P_FA per cell counts its cells over the
tested cells. The ROC
sweeps the threshold over a detector's statistic: a cell of the background (tested, in no
object's gate) crosses with the false-alarm rate, an opportunity is detected when the
largest statistic in its gate crosses. A detector is any callable ``power -> statistic``
(larger = more target-like, NaN where not tested), so a user's detector is benchmarked
like the CFARs of :mod:`seaecho.detection.cfar`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["opportunity_peaks", "pd_at_pfa", "roc", "roc_from_statistic", "score_tables"]


def score_tables(det_look: ArrayLike, det_object: ArrayLike, det_cells: ArrayLike,
                 opp_look: ArrayLike, opp_object: ArrayLike, opp_snr: ArrayLike, *,
                 n_looks: int, cells_tested: int, area_m2: float,
                 snr_bins_db: ArrayLike = (-np.inf, 0, 5, 10, 15, 20, np.inf),
                 opp_visible: ArrayLike | None = None) -> dict:
    """Detection scores from the detection and opportunity tables.

    Parameters
    ----------
    det_look, det_object, det_cells : array_like
        (n,) per detection: look index, object index (-1: none), cells in the plot.
    opp_look, opp_object, opp_snr : array_like
        (m,) per opportunity: look, object, SNR estimate at the object's cells (linear).
    n_looks : int
        Looks tested.
    cells_tested : int
        Cells tested over all looks.
    area_m2 : float
        Area covered by one look [m^2] (NaN when unknown).
    snr_bins_db : array_like
        Edges of the SNR bins [dB]; an opportunity is binned by its object's mean SNR
        over all its looks (the mean, not the look's own SNR, which would bias P_D up).
    opp_visible : array_like of bool, optional
        (m,) whether the truth says the radar can see the object in that look (default
        all): a hidden opportunity is left out of every P_D and counted in
        ``hidden_object``.

    Returns
    -------
    dict
        ``pd_object`` {object: (detected, opportunities, P_D)} over the visible
        opportunities, ``hidden_object`` {object: (detected, hidden opportunities)},
        ``pd_snr`` list of (lo_db, hi_db, detected, opportunities, P_D),
        ``false_alarms``, ``false_alarms_per_look``, ``false_alarms_per_km2`` (per
        look), ``pfa_cell``, ``detections``, ``pd`` (all visible opportunities).
    """
    dl, do, dc = (np.asarray(a) for a in (det_look, det_object, det_cells))
    ol, oo = np.asarray(opp_look, dtype=np.int64), np.asarray(opp_object, dtype=np.int64)
    snr = np.asarray(opp_snr, dtype=float)
    seen = np.ones(ol.size, bool) if opp_visible is None else \
        np.asarray(opp_visible).astype(bool)
    if seen.shape != ol.shape:
        raise ValueError(f"opp_visible of shape {seen.shape}: one per opportunity "
                         f"({ol.size})")
    hit_keys = {(int(a), int(b)) for a, b in zip(dl[do >= 0], do[do >= 0], strict=True)}
    found = np.array([(int(a), int(b)) in hit_keys for a, b in zip(ol, oo, strict=True)],
                     dtype=bool)
    out: dict = {"detections": int(dl.size)}
    out["hidden_object"] = {int(o): (int(found[~seen & (oo == o)].sum()),
                                     int((~seen & (oo == o)).sum()))
                            for o in np.unique(oo[~seen])}
    ol, oo, snr, detected = ol[seen], oo[seen], snr[seen], found[seen]
    objects = np.unique(oo)
    out["pd_object"] = {int(o): (int(detected[oo == o].sum()), int((oo == o).sum()),
                                 float(detected[oo == o].mean())) for o in objects}
    mean_snr = {int(o): float(np.nanmean(snr[oo == o])) for o in objects}
    obj_db = np.array([10.0 * np.log10(max(mean_snr[int(o)], 1e-12)) for o in oo])
    edges = np.asarray(snr_bins_db, dtype=float)
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        sel = (obj_db >= lo) & (obj_db < hi)
        if sel.any():
            rows.append((float(lo), float(hi), int(detected[sel].sum()), int(sel.sum()),
                         float(detected[sel].mean())))
    out["pd_snr"] = rows
    out["object_snr_db"] = {o: 10.0 * np.log10(max(v, 1e-12)) for o, v in mean_snr.items()}
    out["pd"] = float(detected.mean()) if detected.size else float("nan")
    fa = do < 0
    out["false_alarms"] = int(fa.sum())
    out["false_alarms_per_look"] = float(fa.sum() / max(n_looks, 1))
    out["false_alarms_per_km2"] = float(fa.sum() / max(n_looks, 1) / (area_m2 * 1e-6)) \
        if np.isfinite(area_m2) and area_m2 > 0 else float("nan")
    out["pfa_cell"] = float(dc[fa].sum() / cells_tested) if cells_tested else float("nan")
    return out


def opportunity_peaks(statistic: ArrayLike, groups: ArrayLike, n_groups: int) -> NDArray:
    """The largest statistic in each opportunity's gate.

    Parameters
    ----------
    statistic : array_like
        A detector's statistic (NaN where not tested).
    groups : array_like of int
        Same shape: the opportunity of each cell (its look and object), < 0 for none.
    n_groups : int
        Number of opportunities.

    Returns
    -------
    ndarray
        (n_groups,) peak statistic; -inf for an opportunity with no tested cell.
    """
    s = np.asarray(statistic, dtype=float).ravel()
    g = np.asarray(groups).ravel()
    sel = (g >= 0) & np.isfinite(s)
    out = np.full(n_groups, -np.inf)
    np.maximum.at(out, g[sel], s[sel])
    return out


def roc(detector: Callable[[NDArray], NDArray], power: ArrayLike, groups: ArrayLike,
        n_groups: int, thresholds: ArrayLike | None = None,
        visible: ArrayLike | None = None) -> dict[str, NDArray]:
    """Receiver operating characteristic of a detector, by sweeping its threshold.

    Parameters
    ----------
    detector : callable
        ``power -> statistic`` of the same shape (NaN where not tested); a
        :class:`~seaecho.detection.cfar.CFAR` or a user's function.
    power : array_like
        Power of every cell of every look.
    groups : array_like of int
        :func:`opportunity_peaks`'s labels: the opportunity of each cell, -1 outside
        every gate (the background), -2 or less for cells left out of both.
    n_groups : int
        Number of opportunities.
    thresholds : array_like, optional
        Thresholds on the statistic; default 400 quantiles of the background's and the
        opportunities' statistics.
    visible : array_like of bool, optional
        (n_groups,) whether the truth lets the radar see each opportunity (default
        all): a hidden one is left out of P_D (its cells stay out of the background).

    Returns
    -------
    dict
        ``threshold``, ``pfa`` (fraction of background cells above), ``pd`` (fraction of
        the visible opportunities whose peak is above), each sorted by increasing
        threshold.
    """
    stat = np.asarray(detector(np.asarray(power, dtype=float)), dtype=float)
    if stat.shape != np.shape(groups):
        raise ValueError(f"the detector returned shape {stat.shape}, the power has "
                         f"{np.shape(groups)}: a detector maps each cell to one statistic")
    return roc_from_statistic(stat, groups, n_groups, thresholds, visible)


def roc_from_statistic(statistic: ArrayLike, groups: ArrayLike, n_groups: int,
                       thresholds: ArrayLike | None = None,
                       visible: ArrayLike | None = None) -> dict[str, NDArray]:
    """:func:`roc` from a statistic already computed (same arguments, ``statistic`` in
    place of the detector and the power)."""
    stat = np.asarray(statistic, dtype=float)
    g = np.asarray(groups)
    background = np.sort(stat[(g == -1) & np.isfinite(stat)])
    peaks = opportunity_peaks(stat, g, n_groups)
    if visible is not None:
        seen = np.asarray(visible).astype(bool)
        if seen.shape != (n_groups,):
            raise ValueError(f"visible of shape {seen.shape}: one per opportunity "
                             f"({n_groups})")
        peaks = peaks[seen]  # a hidden opportunity is no miss (score_tables' rule)
    peaks = np.sort(peaks)
    if thresholds is None:
        both = np.concatenate([background, peaks[np.isfinite(peaks)]])
        thresholds = np.unique(np.quantile(both, np.linspace(0, 1, 400))) if both.size \
            else np.zeros(1)
        # the tail of the background sets small P_FA: its top cells as thresholds too
        thresholds = np.unique(np.r_[thresholds, background[-200:]])
    t = np.sort(np.asarray(thresholds, dtype=float))
    pfa = (background.size - np.searchsorted(background, t, side="right")) / \
        max(background.size, 1)
    pd = (peaks.size - np.searchsorted(peaks, t, side="right")) / max(peaks.size, 1)
    return {"threshold": t, "pfa": pfa, "pd": pd}


def pd_at_pfa(curve: dict[str, NDArray], pfa: float) -> float:
    """P_D of a ROC at a given P_FA: the highest P_D among thresholds whose P_FA is at
    most ``pfa`` (no interpolation past the measured points; NaN if none)."""
    ok = curve["pfa"] <= pfa
    return float(curve["pd"][ok].max()) if ok.any() else float("nan")
