"""Sliding-window CFAR detectors: cell averaging (CA), greatest-of (GO), smallest-of (SO)
and ordered statistic (OS), along range (1-D) or over the last two axes (2-D).

Input is power (square-law detected, |x|^2) with the tested cells on the last axis (1-D:
``(..., range)``, a range profile per pulse) or the last two axes (2-D: ``(..., azimuth,
range)`` of a PPI sweep or ``(..., y, x)`` of a SAR image); leading axes are independent
(pulses, sweeps, channels). Around each cell under test, ``guard`` cells each side are
skipped and ``train`` cells each side estimate the noise:

- CA: mean of the N training cells; GO / SO: the larger / smaller of the means of the two
  halves, the training cells before and after the cell along the last axis (n = N / 2
  each; in 2-D the column of the cell under test is left out of both halves); OS: the
  k-th smallest training cell (Rohling's k = 3N/4 by default).

The threshold is ``alpha`` times the estimate, with alpha solved from the design P_FA by
the closed forms of :mod:`seaecho.detection.theory`. Window sums and order statistics are
computed by :func:`scipy.ndimage.correlate` and :func:`scipy.ndimage.rank_filter` with the
training footprint (compiled sliding windows, exact sums: no cumulative-sum round-off
next to a strong target). Cells whose window leaves the array are not tested (NaN
statistic), except along an axis declared circular (a PPI's azimuth), which wraps.

Censored windows (:meth:`CFAR.censored`): cells flagged as excluded (the land of a
chart) are left out of every training window; each estimate uses the n cells its window
keeps (CA: their mean; GO / SO: the half means of the m and n kept cells of each half,
the other half's mean alone where one half keeps none; OS: the k(n)-th smallest, k(n) =
round(k n / N), the design's quantile), and each cell's alpha is solved from the same
closed forms with the numbers actually used (eqs D1, D9, D4), once per distinct count.
The sums and counts are the same correlations over the masked power and the mask; the
censored OS sorts the kept cells of the windows that lost some (blocks of cells, no loop
over cells). A cell whose window keeps fewer than a given fraction of its N cells is not
tested (too little sea to estimate the noise) and is counted.

References
----------
Richards, M. A. (2014). *Fundamentals of Radar Signal Processing*, 2nd ed., ch. 7.
Rohling, H. (1983). IEEE Trans. Aerosp. Electron. Syst. AES-19(4), 608-621.
Gandhi, P. P. and Kassam, S. A. (1988). IEEE Trans. Aerosp. Electron. Syst. 24(4),
427-445.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import ndimage

from . import theory

__all__ = ["CFAR", "KINDS", "Censored", "RatioDetector"]

#: cells per block of a censored OS-CFAR's sorted windows (bounds its (cells, N) arrays)
_BLOCK = 1 << 15

#: CFAR kinds and their noise estimate.
KINDS = {"ca": "mean of the training cells", "go": "greater of the two half means",
         "so": "smaller of the two half means", "os": "k-th smallest training cell"}


class RatioDetector:
    """What the CFARs and the clutter map share: a noise estimate per cell (``noise``),
    a threshold multiplier from the design P_FA (``scale``); the statistic is the power
    over the estimate."""

    def noise(self, power: ArrayLike) -> NDArray:  # pragma: no cover - abstract
        raise NotImplementedError

    def scale(self, pfa: float) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    def __call__(self, power: ArrayLike) -> NDArray:
        """The test statistic: power over the noise estimate (NaN where not tested); a
        cell is detected where it exceeds :meth:`scale` (pfa)."""
        power = np.asarray(power, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            return power / self.noise(power)

    def detect(self, power: ArrayLike, pfa: float) -> NDArray:
        """Boolean mask of the cells above the threshold of design ``pfa``."""
        with np.errstate(invalid="ignore"):
            return self(power) > self.scale(pfa)


@dataclass(frozen=True)
class Censored:
    """A CFAR's estimate and threshold from censored windows (:meth:`CFAR.censored`).

    Attributes
    ----------
    noise : ndarray
        Noise estimate from the kept training cells [power unit] (NaN where not tested).
    alpha : ndarray
        Threshold multiplier of each cell for the design P_FA with the cells its window
        kept [-] (NaN where not tested): a cell is detected where power > alpha x noise.
    n_used : ndarray of int
        Training cells each estimate used (0 where not tested).
    short : ndarray of bool
        Cells left untested because their window kept too few training cells.
    n_train : int
        Training cells N of a full window.
    """

    noise: NDArray
    alpha: NDArray
    n_used: NDArray
    short: NDArray
    n_train: int

    @property
    def n_censored(self) -> int:
        """Tested cells whose window lost training cells."""
        return int((np.isfinite(self.alpha) & (self.n_used < self.n_train)).sum())


def _pair(value, name: str) -> tuple[int, ...]:
    vals = (value,) if np.isscalar(value) else tuple(value)
    if not vals or len(vals) > 2:
        raise ValueError(f"{name} = {value!r}: one number (1-D, along range) or two "
                         "(2-D: azimuth or y, then range or x)")
    out = []
    for v in vals:
        if int(v) != v or v < 0:
            raise ValueError(f"{name} = {value!r}: cells must be whole numbers >= 0")
        out.append(int(v))
    return tuple(out)


@dataclass(frozen=True)
class CFAR(RatioDetector):
    """A CFAR detector (a callable: power -> statistic, the power over the noise
    estimate).

    Parameters
    ----------
    kind : {'ca', 'go', 'so', 'os'}
        Noise estimate (:data:`KINDS`).
    train : int or (int, int)
        Training cells on each side of the cell under test: one number for a 1-D CFAR
        along the last axis, two (azimuth or y, range or x) for a 2-D CFAR.
    guard : int or (int, int)
        Guard cells on each side, as ``train``.
    rank : int, optional
        OS only: the rank k of the order statistic (1 = smallest); default round(3N/4)
        (Rohling 1983).
    circular : bool
        2-D only: the first of the two axes wraps around (a full PPI's azimuth).
    """

    kind: str = "ca"
    train: int | tuple[int, ...] = 16
    guard: int | tuple[int, ...] = 2
    rank: int | None = None
    circular: bool = False

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind = {self.kind!r}: allowed {', '.join(KINDS)}")
        train, guard = _pair(self.train, "train"), _pair(self.guard, "guard")
        if len(train) != len(guard):
            raise ValueError(f"train = {self.train!r}, guard = {self.guard!r}: give both "
                             "as one number (1-D) or both as two (2-D)")
        if train[-1] < 1:
            raise ValueError(f"train = {self.train!r}: at least one training cell each "
                             "side along range")
        object.__setattr__(self, "train", train)
        object.__setattr__(self, "guard", guard)
        if self.kind == "os":
            k = self.rank if self.rank is not None else max(1, round(0.75 * self.n_train))
            if int(k) != k or not 1 <= k <= self.n_train:
                raise ValueError(f"rank = {self.rank}: the order statistic must be in "
                                 f"1..{self.n_train} (the training cells)")
            object.__setattr__(self, "rank", int(k))
        elif self.rank is not None:
            raise ValueError(f"rank = {self.rank}: only an OS-CFAR has a rank")

    @property
    def ndim(self) -> int:
        """1 (along range) or 2."""
        return len(self.train)

    @cached_property
    def footprints(self) -> tuple[NDArray, NDArray, NDArray]:
        """Boolean masks of (all training cells, leading half, lagging half), of shape
        (2 (G + T) + 1,) per axis."""
        half = [g + t for g, t in zip(self.guard, self.train, strict=True)]
        grids = np.meshgrid(*[np.arange(-h, h + 1) for h in half], indexing="ij")
        inner = np.ones(grids[0].shape, bool)
        for o, g in zip(grids, self.guard, strict=True):
            inner &= np.abs(o) <= g
        train = ~inner
        return train, train & (grids[-1] < 0), train & (grids[-1] > 0)

    @property
    def n_train(self) -> int:
        """Training cells N."""
        return int(self.footprints[0].sum())

    @property
    def n_half(self) -> int:
        """Training cells n of each half (GO, SO)."""
        return int(self.footprints[1].sum())

    def _law(self):
        return {"ca": (theory.pfa_ca, (self.n_train,)),
                "go": (theory.pfa_go, (self.n_half,)),
                "so": (theory.pfa_so, (self.n_half,)),
                "os": (theory.pfa_os, (self.n_train, self.rank))}[self.kind]

    def pfa(self, alpha: ArrayLike) -> NDArray:
        """False-alarm probability of threshold multiplier ``alpha`` in exponential noise
        (:mod:`seaecho.detection.theory`)."""
        law, args = self._law()
        return law(alpha, *args)

    def pd_swerling1(self, alpha: ArrayLike, snr: ArrayLike) -> NDArray:
        """Probability of detection of a Swerling 1/2 target of mean SNR ``snr``
        (linear) [-]."""
        law, args = self._law()
        return theory.pd_swerling1(law, alpha, snr, *args)

    def scale(self, pfa: float) -> float:
        """Threshold multiplier alpha for the design false-alarm probability ``pfa``."""
        law, args = self._law()
        return theory.scale_for_pfa(law, pfa, *args)

    def _window(self, power: NDArray, fp: NDArray) -> NDArray:
        return fp.reshape((1,) * (power.ndim - fp.ndim) + fp.shape)

    def _pad(self, power: NDArray) -> tuple[NDArray, tuple]:
        """The power, padded circularly along azimuth when ``circular``."""
        if not (self.circular and self.ndim == 2):
            return power, ()
        h = self.guard[0] + self.train[0]
        pad = [(0, 0)] * power.ndim
        pad[-2] = (h, h)
        return np.pad(power, pad, mode="wrap"), (h,)

    def noise(self, power: ArrayLike) -> NDArray:
        """Noise estimate of every cell (NaN where the window leaves the array).

        Parameters
        ----------
        power : array_like
            Power, ``(..., range)`` (1-D) or ``(..., azimuth, range)`` (2-D) [any
            power unit].

        Returns
        -------
        ndarray
            Same shape as ``power`` [power unit].
        """
        power = np.asarray(power, dtype=float)
        if power.ndim < self.ndim:
            raise ValueError(f"power of shape {power.shape}: a {self.ndim}-D CFAR needs "
                             f"at least {self.ndim} axes")
        x, wrap = self._pad(power)
        fp_all, fp_lead, fp_lag = self.footprints
        if self.kind == "os":
            est = ndimage.rank_filter(x, self.rank - 1, footprint=self._window(x, fp_all),
                                      mode="constant", cval=0.0)
        elif self.kind == "ca":
            est = ndimage.correlate(x, self._window(x, fp_all).astype(float),
                                    mode="constant", cval=0.0) / self.n_train
        else:
            lead = ndimage.correlate(x, self._window(x, fp_lead).astype(float),
                                     mode="constant", cval=0.0)
            lag = ndimage.correlate(x, self._window(x, fp_lag).astype(float),
                                    mode="constant", cval=0.0)
            est = (np.maximum if self.kind == "go" else np.minimum)(lead, lag) / self.n_half
        if wrap:
            h = wrap[0]
            est = est[..., h:est.shape[-2] - h, :]
        return np.where(self.tested(power.shape), est, np.nan)

    def rank_of(self, n: ArrayLike) -> NDArray:
        """OS: the rank k(n) = round(k n / N) (>= 1) of a window that kept n cells (the
        design's quantile; k(N) = k)."""
        n = np.asarray(n, dtype=np.int64)
        return np.maximum(1, np.rint(self.rank * n / self.n_train).astype(np.int64))

    def censored(self, power: ArrayLike, exclude: ArrayLike, pfa: float,
                 min_fraction: float = 0.5) -> Censored:
        """Estimate and threshold with the ``exclude`` cells left out of the windows.

        Land-censored CFAR: the cells of the land are not sea clutter, so they are left
        out of every training window; each cell's estimate uses the n cells its window
        keeps, and its alpha gives the design P_FA for those n (module docstring): CA,
        eq D1 with N = n (alpha = n (P_FA^(-1/n) - 1), Richards 2014, ch. 7); GO / SO,
        eq D9 with halves of m and n cells; OS, eq D4 with N = n and k(n)
        (:meth:`rank_of`; Rohling 1983). An excluded cell is not tested itself.

        Parameters
        ----------
        power : array_like
            Power, as :meth:`noise` takes it [any power unit].
        exclude : array_like of bool
            Broadcastable to ``power``: cells kept out of the windows (and untested).
        pfa : float
            Design false-alarm probability per cell, in (0, 1).
        min_fraction : float
            A cell is tested only if its window keeps at least ceil(min_fraction N)
            training cells (in (0, 1]).

        Returns
        -------
        Censored
        """
        if not (isinstance(min_fraction, int | float) and 0.0 < min_fraction <= 1.0):
            raise ValueError(f"min_fraction = {min_fraction!r}: the fraction of a window's "
                             "training cells a censored estimate needs must be in (0, 1]")
        power = np.asarray(power, dtype=float)
        if power.ndim < self.ndim:
            raise ValueError(f"power of shape {power.shape}: a {self.ndim}-D CFAR needs "
                             f"at least {self.ndim} axes")
        try:
            excl = np.broadcast_to(np.asarray(exclude, dtype=bool), power.shape)
        except ValueError:
            raise ValueError(f"exclude of shape {np.shape(exclude)}: must broadcast to the "
                             f"power's {power.shape}") from None
        self.scale(pfa)  # the design P_FA's check
        keep = (~excl).astype(float)
        x, wrap = self._pad(np.where(excl, 0.0, power))
        k, _ = self._pad(keep)
        fp_all, fp_lead, fp_lag = self.footprints

        def window_sum(a, fp):
            out = ndimage.correlate(a, self._window(a, fp).astype(float), mode="constant",
                                    cval=0.0)
            return out[..., wrap[0]:out.shape[-2] - wrap[0], :] if wrap else out

        n_all = np.rint(window_sum(k, fp_all)).astype(np.int64)
        tested = np.asarray(self.tested(power.shape)) & ~excl
        short = tested & (n_all < math.ceil(min_fraction * self.n_train - 1e-9))
        ok = tested & ~short
        est = np.full(power.shape, np.nan)
        alpha = np.full(power.shape, np.nan)
        if self.kind == "ca":
            with np.errstate(invalid="ignore", divide="ignore"):
                est[ok] = (window_sum(x, fp_all) / n_all)[ok]
            keys = n_all[ok][:, None]
        elif self.kind in ("go", "so"):
            n_lead = np.rint(window_sum(k, fp_lead)).astype(np.int64)
            n_lag = np.rint(window_sum(k, fp_lag)).astype(np.int64)
            with np.errstate(invalid="ignore", divide="ignore"):
                lead = window_sum(x, fp_lead) / n_lead
                lag = window_sum(x, fp_lag) / n_lag
            pick = np.maximum if self.kind == "go" else np.minimum
            # a half that kept no cell: the other half's mean alone (a CA estimate)
            both = np.where(n_lead == 0, lag, np.where(n_lag == 0, lead, pick(lead, lag)))
            est[ok] = both[ok]
            keys = np.stack([n_lead[ok], n_lag[ok]], axis=-1)
        else:
            est[ok] = self._censored_order_statistic(power, excl, n_all, ok)
            keys = n_all[ok][:, None]
        # alpha once per distinct count (a code per count or pair of counts), not per cell
        base = self.n_train + 1
        code = keys[:, 0] * base + keys[:, 1] if keys.shape[1] == 2 else keys[:, 0]
        table = np.full(base ** keys.shape[1], np.nan)
        for c in np.flatnonzero(np.bincount(code, minlength=table.size)):
            counts = divmod(int(c), base) if keys.shape[1] == 2 else (int(c),)
            table[c] = self._censored_scale(pfa, counts)
        alpha[ok] = table[code]
        return Censored(est, alpha, np.where(ok, n_all, 0), short, self.n_train)

    def _censored_scale(self, pfa: float, counts: tuple[int, ...]) -> float:
        """alpha for the design P_FA of a window that kept ``counts`` cells ((n,), or
        (m, n) per half for GO / SO)."""
        if self.kind == "ca":
            return theory.scale_for_pfa(theory.pfa_ca, pfa, counts[0])
        if self.kind == "os":
            n = counts[0]
            return theory.scale_for_pfa(theory.pfa_os, pfa, n, int(self.rank_of(n)))
        m, n = counts
        if m == 0 or n == 0:  # one half only: its mean, a CA estimate
            return theory.scale_for_pfa(theory.pfa_ca, pfa, m + n)
        law = theory.pfa_go if self.kind == "go" else theory.pfa_so
        return theory.scale_for_pfa(law, pfa, m, n)

    def _censored_order_statistic(self, power: NDArray, excl: NDArray, n_all: NDArray,
                                  ok: NDArray) -> NDArray:
        """The k(n)-th smallest kept training cell of each ``ok`` cell (in the order of
        ``power[ok]``): the full windows by one rank filter, those that lost cells by
        sorting their kept cells (excluded ones set to +inf), a block at a time."""
        fp_all = self.footprints[0]
        full = ok & (n_all == self.n_train)
        out = np.full(power.shape, np.nan)
        if full.any():  # whole windows: the uncensored estimate's rank filter
            out[full] = self.noise(power)[full]
        part = np.nonzero(ok & ~full)
        if part[0].size:
            vals = np.where(excl, np.inf, power)
            offs = np.argwhere(fp_all) - np.array(fp_all.shape) // 2  # (N, ndim)
            lead, cell = part[:-self.ndim], part[-self.ndim:]
            shape = power.shape[-self.ndim:]
            rank = self.rank_of(n_all[part]) - 1
            res = np.empty(rank.size)
            for s in range(0, rank.size, _BLOCK):  # blocks of cells, the windows at once
                b = slice(s, s + _BLOCK)
                idx = [c[b, None] + offs[None, :, a] for a, c in enumerate(cell)]
                if self.circular and self.ndim == 2:
                    idx[0] = idx[0] % shape[0]
                w = vals[tuple(ix[b, None] for ix in lead) + tuple(idx)]
                w.sort(axis=-1)
                res[b] = np.take_along_axis(w, rank[b, None], axis=-1)[:, 0]
            out[part] = res
        return out[ok]

    def tested(self, shape: tuple[int, ...]) -> NDArray:
        """Cells whose whole window is inside the array (all of a circular axis)."""
        out = np.zeros(shape[-self.ndim:], bool)
        sl = []
        for ax, (g, t) in enumerate(zip(self.guard, self.train, strict=True)):
            h = g + t
            if self.circular and self.ndim == 2 and ax == 0:
                sl.append(slice(None))
            else:
                sl.append(slice(h, max(shape[len(shape) - self.ndim + ax] - h, h)))
        out[tuple(sl)] = True
        return np.broadcast_to(out, shape)

