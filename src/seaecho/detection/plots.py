"""Plot extraction: connected detected cells -> one plot with centroid, extent, peak and
SNR estimate.

Cells are connected within the last one (range profiles) or two (PPI sweeps, images) axes,
diagonals included; leading axes (pulses, sweeps) separate plots. A plot's centroid is the
power-weighted mean of its cells' indices (fractional), its extent the first and last
index along each axis, its peak the strongest cell, and its SNR estimate the peak's power
over the detector's noise estimate there, minus one (the cell holds signal plus noise).
Everything by :func:`scipy.ndimage.label` and :func:`numpy.bincount`: no loop over cells
or plots.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import ndimage

__all__ = ["extract_plots"]


def extract_plots(power: ArrayLike, mask: ArrayLike, noise: ArrayLike, ndim: int = 1
                  ) -> dict[str, NDArray]:
    """Plots of the detected cells.

    Parameters
    ----------
    power : array_like
        Power of every cell, ``(..., cells)`` with the last ``ndim`` axes tested.
    mask : array_like of bool
        Detected cells (same shape).
    noise : array_like
        The detector's noise estimate of every cell (same shape and unit as ``power``).
    ndim : int
        1 or 2: axes over which detected cells join into one plot.

    Returns
    -------
    dict
        Per plot (sorted by leading index, then by position): ``centroid`` (n, power.ndim)
        fractional indices, ``peak_index`` (n, power.ndim), ``first`` / ``last`` (n,
        power.ndim) extent in indices, ``n_cells``, ``peak_power``, ``noise`` (at the
        peak), ``snr`` (peak / noise - 1, linear, floored at 1e-12).
    """
    power = np.asarray(power, dtype=float)
    mask = np.asarray(mask, dtype=bool)
    noise = np.asarray(noise, dtype=float)
    if not power.shape == mask.shape == noise.shape:
        raise ValueError(f"power {power.shape}, mask {mask.shape}, noise {noise.shape}: "
                         "must have one shape")
    if ndim not in (1, 2) or power.ndim < ndim:
        raise ValueError(f"ndim = {ndim}: 1 or 2, at most power.ndim = {power.ndim}")
    structure = np.zeros((3,) * power.ndim, bool)
    centre = [slice(1, 2)] * (power.ndim - ndim) + [slice(None)] * ndim
    structure[tuple(centre)] = True
    labels, n = ndimage.label(mask, structure=structure)
    d = power.ndim
    if n == 0:
        z = np.zeros((0, d))
        return {"centroid": z, "peak_index": z.astype(np.int64), "first": z.astype(np.int64),
                "last": z.astype(np.int64), "n_cells": np.zeros(0, np.int64),
                "peak_power": np.zeros(0), "noise": np.zeros(0), "snr": np.zeros(0)}
    where = np.nonzero(labels)
    lab = labels[where] - 1
    p = power[where]
    idx = np.stack(where, axis=-1)  # (cells, d)
    total = np.bincount(lab, weights=p, minlength=n)
    safe = np.where(total > 0, total, 1.0)
    centroid = np.stack([np.bincount(lab, weights=p * idx[:, a], minlength=n) / safe
                         for a in range(d)], axis=-1)
    first = np.full((n, d), np.iinfo(np.int64).max)
    last = np.full((n, d), -1, np.int64)
    np.minimum.at(first, lab, idx)
    np.maximum.at(last, lab, idx)
    # The peak: the last cell of each label after sorting by (label, power)
    order = np.lexsort((p, lab))
    ends = np.r_[np.flatnonzero(np.diff(lab[order])), lab.size - 1]
    peak = order[ends]
    peak_index = idx[peak]
    peak_power = p[peak]
    nz = noise[tuple(peak_index.T)]
    with np.errstate(divide="ignore", invalid="ignore"):
        snr = np.maximum(peak_power / nz - 1.0, 1e-12)
    return {"centroid": centroid, "peak_index": peak_index, "first": first, "last": last,
            "n_cells": np.bincount(lab, minlength=n).astype(np.int64),
            "peak_power": peak_power, "noise": nz, "snr": snr}
