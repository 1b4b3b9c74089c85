"""Clutter-map (scan-to-scan) CFAR and M-of-N binary integration.

A clutter map keeps, per resolution cell, an exponentially weighted mean of its power over
past scans, q_n = (1 - w) q_{n-1} + w x_n, and detects scan n where x_n > alpha q_{n-1}
(Nitzberg 1986): the noise estimate of a cell comes from the same cell at earlier times,
not from its neighbours, which suits fixed clutter (land, a coast) whose level changes
from cell to cell. Its P_FA in steady state is :func:`seaecho.detection.theory.pfa_clutter_map`;
the first ``warmup`` scans build the map and are not tested.

M-of-N integration declares a cell where at least M of N consecutive looks (pulses or
scans) crossed; each look independent of probability p gives
:func:`seaecho.detection.theory.pfa_m_of_n` (Richards 2014, ch. 6).

References
----------
Nitzberg, R. (1986). Clutter map CFAR analysis. *IEEE Trans. Aerosp. Electron. Syst.*
AES-22(4), 419-421.
Richards, M. A. (2014). *Fundamentals of Radar Signal Processing*, 2nd ed., ch. 6-7.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import theory
from .cfar import RatioDetector

__all__ = ["ClutterMap", "m_of_n"]


@dataclass(frozen=True)
class ClutterMap(RatioDetector):
    """Exponentially weighted clutter-map CFAR (a callable: power -> statistic, the power
    over the map; NaN during the warm-up).

    Parameters
    ----------
    weight : float
        w, the weight of the newest scan, 0 < w <= 1 (memory about 1 / w scans).
    warmup : int, optional
        Scans that build the map before the first test (default ceil(5 / w): the first
        scan's weight in the map is then below e^-5).
    """

    weight: float = 0.125
    warmup: int | None = None

    def __post_init__(self):
        if not 0.0 < self.weight <= 1.0:
            raise ValueError(f"weight = {self.weight}: the clutter map's weight must be in "
                             "(0, 1]")
        if self.warmup is None:
            object.__setattr__(self, "warmup", int(np.ceil(5.0 / self.weight)))
        if int(self.warmup) != self.warmup or self.warmup < 1:
            raise ValueError(f"warmup = {self.warmup}: scans >= 1")

    def pfa(self, alpha: ArrayLike) -> NDArray:
        """Steady-state false-alarm probability (Nitzberg 1986)."""
        return theory.pfa_clutter_map(alpha, self.weight)

    def pd_swerling1(self, alpha: ArrayLike, snr: ArrayLike) -> NDArray:
        """P_D of a Swerling 1/2 target of mean SNR ``snr`` (linear) [-]."""
        return theory.pd_swerling1(theory.pfa_clutter_map, alpha, snr, self.weight)

    def scale(self, pfa: float) -> float:
        """Threshold multiplier for the design false-alarm probability."""
        return theory.scale_for_pfa(theory.pfa_clutter_map, pfa, self.weight)

    def noise(self, power: ArrayLike) -> NDArray:
        """The map before each scan, q_{n-1}; NaN during the warm-up.

        Parameters
        ----------
        power : array_like
            ``(scan, ...cells)`` power [any power unit].
        """
        power = np.asarray(power, dtype=float)
        if power.ndim < 1 or power.shape[0] <= self.warmup:
            raise ValueError(f"power of shape {power.shape}: a clutter map needs more "
                             f"scans than its warm-up ({self.warmup})")
        w = self.weight
        out = np.full(power.shape, np.nan)
        q = power[0].copy()
        for n in range(1, power.shape[0]):  # a recursion over scans, every cell at once
            if n >= self.warmup:
                out[n] = q
            q = (1.0 - w) * q + w * power[n]
        return out


def m_of_n(hits: ArrayLike, m: int, n: int, axis: int = 0) -> NDArray:
    """M-of-N binary integration along ``axis`` (pulses or scans).

    Parameters
    ----------
    hits : array_like of bool
        Single-look detections.
    m, n : int
        At least ``m`` crossings among ``n`` consecutive looks (1 <= m <= n).
    axis : int
        The look axis.

    Returns
    -------
    ndarray of bool
        ``hits`` shape with ``n - 1`` fewer looks: entry i covers looks i .. i + n - 1
        (a sliding window, from integer cumulative sums: exact).
    """
    hits = np.asarray(hits, dtype=bool)
    if int(n) != n or int(m) != m or not 1 <= m <= n:
        raise ValueError(f"M = {m}, N = {n}: need whole numbers 1 <= M <= N")
    if hits.shape[axis] < n:
        raise ValueError(f"{hits.shape[axis]} looks: fewer than N = {n}")
    c = np.cumsum(np.moveaxis(hits, axis, 0), axis=0, dtype=np.int64)
    c = np.concatenate([np.zeros((1,) + c.shape[1:], np.int64), c])
    return np.moveaxis(c[n:] - c[:-n] >= m, 0, axis)
