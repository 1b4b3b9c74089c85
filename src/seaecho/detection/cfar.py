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

References
----------
Richards, M. A. (2014). *Fundamentals of Radar Signal Processing*, 2nd ed., ch. 7.
Rohling, H. (1983). IEEE Trans. Aerosp. Electron. Syst. AES-19(4), 608-621.
Gandhi, P. P. and Kassam, S. A. (1988). IEEE Trans. Aerosp. Electron. Syst. 24(4),
427-445.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import ndimage

from . import theory

__all__ = ["CFAR", "KINDS", "RatioDetector"]

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

