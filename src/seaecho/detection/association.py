"""Detections to ground truth: which object (if any) each detection belongs to, and where
the objects are seen from the radar.

The truth is the objects' positions per time (``truth_position (time, object, d)``), as a
run records them (point targets, the ship's track, per-pulse truth of several ships); a
detection belongs to the nearest object whose distance, at the detection's time, is within
that object's gate (its half extent plus the cell size), else to none (a false alarm).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["associate", "ground_point", "half_path", "interpolate_truth", "nearest_object"]


def interpolate_truth(truth_time_s: ArrayLike, truth_position: ArrayLike,
                      time_s: ArrayLike) -> NDArray:
    """Object positions at given times, linear between the truth's times (held beyond).

    Parameters
    ----------
    truth_time_s : array_like
        (t,) increasing times of the truth [s].
    truth_position : array_like
        (t, object, d) positions [m] (NaN where an object does not exist).
    time_s : array_like
        (n,) times wanted [s].

    Returns
    -------
    ndarray
        (n, object, d) [m].
    """
    tt = np.asarray(truth_time_s, dtype=float)
    tp = np.asarray(truth_position, dtype=float)
    t = np.asarray(time_s, dtype=float)
    if tp.ndim != 3 or tp.shape[0] != tt.size:
        raise ValueError(f"truth_position of shape {tp.shape}: must be (time, object, d) "
                         f"with {tt.size} times")
    if tt.size == 1:
        return np.broadcast_to(tp, (t.size,) + tp.shape[1:]).copy()
    i = np.clip(np.searchsorted(tt, t, side="right") - 1, 0, tt.size - 2)
    f = np.clip((t - tt[i]) / (tt[i + 1] - tt[i]), 0.0, 1.0)[:, None, None]
    return (1.0 - f) * tp[i] + f * tp[i + 1]


def associate(time_s: ArrayLike, position: ArrayLike, truth_time_s: ArrayLike,
              truth_position: ArrayLike, gate: ArrayLike) -> NDArray:
    """The object each detection belongs to.

    Parameters
    ----------
    time_s : array_like
        (n,) detection times [s].
    position : array_like
        (n, d) detection positions [m] (d = 1 for range, 2 for x, y).
    truth_time_s, truth_position
        As :func:`interpolate_truth`: (t,) [s] and (t, object, d) [m].
    gate : array_like
        (object,) or scalar: the largest distance [m] at which a detection belongs to
        the object (half its extent plus the cell size).

    Returns
    -------
    ndarray of int
        (n,) object index, -1 for none (a false alarm).
    """
    pos = np.asarray(position, dtype=float)
    pos = pos.reshape(pos.shape[0], -1) if pos.ndim else pos.reshape(0, 1)
    n_obj = np.asarray(truth_position).shape[1]
    if pos.shape[0] == 0 or n_obj == 0:
        return np.full(pos.shape[0], -1, np.int64)
    return nearest_object(pos, interpolate_truth(truth_time_s, truth_position, time_s), gate)


def nearest_object(position: ArrayLike, where: ArrayLike, gate: ArrayLike) -> NDArray:
    """The nearest object within its gate, for positions and objects at the same times.

    Parameters
    ----------
    position : array_like
        (n, d) detection positions [m].
    where : array_like
        (n, object, d) object positions at each detection's time [m] (NaN: absent).
    gate : array_like
        (object,) or scalar gate [m].

    Returns
    -------
    ndarray of int
        (n,) object index, -1 for none.
    """
    pos = np.asarray(position, dtype=float)
    where = np.asarray(where, dtype=float)
    n_obj = where.shape[1]
    if pos.shape[0] == 0 or n_obj == 0:
        return np.full(pos.shape[0], -1, np.int64)
    dist = np.sqrt(((where - pos[:, None, :]) ** 2).sum(axis=-1))  # (n, object)
    gate = np.broadcast_to(np.asarray(gate, dtype=float), (n_obj,))
    with np.errstate(invalid="ignore"):
        inside = dist <= gate[None, :]
    score = np.where(inside, dist, np.inf)
    best = np.argmin(score, axis=1)
    return np.where(inside.any(axis=1), best, -1).astype(np.int64)


def half_path(point: ArrayLike, tx: ArrayLike, rx: ArrayLike) -> NDArray:
    """Half the bistatic path (|p - tx| + |p - rx|) / 2 [m]: the run's ``range``
    coordinate (c times the delay over two).

    Parameters
    ----------
    point, tx, rx : array_like
        (..., 3) positions [m], broadcast together.
    """
    p, t, r = (np.asarray(a, dtype=float) for a in (point, tx, rx))
    return 0.5 * (np.linalg.norm(p - t, axis=-1) + np.linalg.norm(p - r, axis=-1))


def ground_point(tx: ArrayLike, rx: ArrayLike, direction: ArrayLike,
                 half_path_m: ArrayLike) -> NDArray:
    """The point on the sea plane z = 0, along a horizontal direction from below the
    receiver, whose half bistatic path is ``half_path_m``.

    With p = rx_xy + s u (z = 0), a = |p - rx| = sqrt(s^2 + h_r^2) and the path
    L = 2 r = a + |p - tx|: squaring L - a = |p - tx| gives
    2 L a = K - 2 s (d . u), K = L^2 + h_r^2 - h_t^2 - |d|^2, d = rx_xy - tx_xy, so
    s solves (4 (d . u)^2 - 4 L^2) s^2 - 4 K (d . u) s + K^2 - 4 L^2 h_r^2 = 0 (the
    root in front of the receiver with a > 0). Monostatic: s = sqrt(r^2 - h^2).

    Parameters
    ----------
    tx, rx : array_like
        (n, 3) transmitter and receiver positions [m].
    direction : array_like
        (n, 2) horizontal unit vectors (the receive antenna's azimuth), or (n, 3)
        boresights: then, where the ray meets the path's ellipse twice (a receiver
        outside it, as in a bistatic geometry), the point nearer the boresight's
        direction.
    half_path_m : array_like
        (n,) half bistatic paths [m].

    Returns
    -------
    ndarray
        (n, 3) points [m]; NaN where no point of the sea along the direction has that
        path (inside the direct path, or behind the receiver).
    """
    tx, rx = np.asarray(tx, dtype=float), np.asarray(rx, dtype=float)
    boresight = np.asarray(direction, dtype=float)
    u = boresight[..., :2] / np.linalg.norm(boresight[..., :2], axis=-1, keepdims=True)
    big_l = 2.0 * np.asarray(half_path_m, dtype=float)
    d = rx[..., :2] - tx[..., :2]
    du = (d * u).sum(axis=-1)
    hr2, ht2 = rx[..., 2] ** 2, tx[..., 2] ** 2
    k = big_l ** 2 + hr2 - ht2 - (d * d).sum(axis=-1)
    a2 = 4.0 * du ** 2 - 4.0 * big_l ** 2
    b = -4.0 * k * du
    c = k ** 2 - 4.0 * big_l ** 2 * hr2
    with np.errstate(invalid="ignore", divide="ignore"):
        disc = np.sqrt(b * b - 4.0 * a2 * c)
        roots = np.stack([(-b + disc) / (2.0 * a2), (-b - disc) / (2.0 * a2)], axis=-1)
        a_len = (k[..., None] - 2.0 * roots * du[..., None]) / (2.0 * big_l[..., None])
    # the squarings hold only with 0 < a <= L: the other roots are spurious
    ok = (roots >= 0) & (a_len > 0) & (a_len <= big_l[..., None]) & np.isfinite(roots)
    if boresight.shape[-1] == 3:  # the root seen nearest the boresight
        p = rx[..., None, :2] + roots[..., None] * u[..., None, :]
        los = np.concatenate([p - rx[..., None, :2],
                              np.broadcast_to(-rx[..., None, 2:], p.shape[:-1] + (1,))], -1)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = (los * boresight[..., None, :]).sum(-1) / np.linalg.norm(los, axis=-1)
        cos = np.where(ok, cos, -np.inf)
        pick = np.argmax(cos, axis=-1)[..., None]
        s = np.where(ok.any(axis=-1), np.take_along_axis(roots, pick, -1)[..., 0], np.inf)
    else:
        s = np.where(ok, roots, np.inf).min(axis=-1)
    s = np.where(np.isfinite(s), s, np.nan)
    xy = rx[..., :2] + s[..., None] * u
    return np.concatenate([xy, np.where(np.isnan(s), np.nan, 0.0)[..., None]], axis=-1)
