"""Doppler processing of a pulse train: range-Doppler maps, Doppler spectra, moments.

For range-compressed pulses ``x[p, c, s]`` (pulse p at ``t_p = p / PRF``, channel c,
range sample s), the Doppler spectrum of each range cell is the periodogram over
pulses, averaged over coherent processing intervals (CPIs) of ``N`` pulses overlapping
by half (Welch 1967):

.. math::
    P_c(f_l, s) = \\frac{1}{M}\\sum_{m=1}^{M}
    \\frac{\\left|\\sum_{p} w_p\\, x[p_m + p, c, s]\\, e^{-j 2\\pi l p / N}\\right|^2}
    {\\mathrm{PRF}\\sum_p w_p^2},\\qquad f_l = \\frac{l\\,\\mathrm{PRF}}{N}
    \\quad (l = -N/2 \\ldots N/2 - 1)                                            (DP1)

a power spectral density [W/Hz] whose sum over the Doppler bins times ``PRF / N`` is the
mean power of the cell. The time convention ``exp(+j omega t)`` of the echo model makes an
approaching scatterer (range decreasing) a positive Doppler frequency,
``f_D = -(1 / lambda) d(r_T + r_R)/dt``. The Doppler spectrum of the clutter is DP1
summed over the range cells that hold clutter; its centroid and rms width are its first
moment and the square root of its second central moment (DP2):

.. math::
    \\bar f = \\frac{\\sum_l f_l S(f_l)}{\\sum_l S(f_l)},\\qquad
    \\sigma_f = \\sqrt{\\frac{\\sum_l (f_l - \\bar f)^2 S(f_l)}{\\sum_l S(f_l)}}  (DP2)

References
----------
.. [1] Welch, P. D. (1967). The use of fast Fourier transform for the estimation of power
   spectra. *IEEE Trans. Audio Electroacoust.* 15(2), 70-73.
.. [2] Richards, M. A. (2014). *Fundamentals of Radar Signal Processing*, 2nd ed.,
   McGraw-Hill, ch. 5 (pulse-Doppler spectra) and ch. 17 (range-Doppler maps).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .windows import sampled_window

WINDOWS = ("hann", "hamming", "none")


def _taper(n: int, window: str) -> NDArray:
    """The taper over the pulses of a CPI: every sample inside the window (no zero end
    point), :func:`seaecho.processing.windows.sampled_window`."""
    if window not in WINDOWS:
        raise ValueError(f"window = {window!r}: allowed {', '.join(map(repr, WINDOWS))}")
    return sampled_window(window, n, open_ends=True)


def range_doppler(compressed: ArrayLike, prf: float, cpi: int | None = None,
                  window: str = "hann") -> tuple[NDArray, NDArray]:
    """Eq DP1: Doppler power spectral density of every range cell, per channel.

    Parameters
    ----------
    compressed : array_like, shape (P, C, S) complex
        Range-compressed pulses [sqrt(W)] (pulse, channel, range sample).
    prf : float
        Pulse repetition frequency [Hz].
    cpi : int, optional
        Pulses per coherent processing interval N (default all pulses; CPIs overlap by
        half and their periodograms are averaged).
    window : {"hann", "hamming", "none"}
        Taper over the pulses of a CPI.

    Returns
    -------
    freq : ndarray (N,)
        Doppler frequencies [Hz], ascending, ``-PRF/2 <= f < PRF/2``.
    psd : ndarray (C, N, S)
        Power spectral density [W/Hz].
    """
    x = np.asarray(compressed)
    if x.ndim != 3:
        raise ValueError(f"compressed of shape {x.shape}: need (pulse, channel, sample)")
    if not (np.isfinite(prf) and prf > 0):
        raise ValueError(f"prf = {prf!r} Hz: must be > 0")
    n_p = x.shape[0]
    n = n_p if cpi is None else int(cpi)
    if not 2 <= n <= n_p:
        raise ValueError(f"cpi = {cpi}: must be between 2 and the {n_p} pulses")
    w = _taper(n, window)
    step = max(n // 2, 1)
    starts = range(0, n_p - n + 1, step)
    acc = None
    for p0 in starts:
        seg = x[p0:p0 + n] * w[:, None, None]
        spec = np.fft.fftshift(np.fft.fft(seg, axis=0), axes=0)
        pw = spec.real**2 + spec.imag**2
        acc = pw if acc is None else acc + pw
    psd = acc / (len(starts) * prf * np.sum(w**2))  # eq DP1
    freq = np.fft.fftshift(np.fft.fftfreq(n, 1.0 / prf))
    return freq, np.moveaxis(psd, 0, 1)


def clutter_cells(psd: ArrayLike, floor_db: float = 20.0) -> NDArray:
    """Range cells within ``floor_db`` of the strongest cell's power (all channels), (S,)."""
    p = np.asarray(psd).sum(axis=(0, 1))
    if not np.any(p > 0):
        return np.ones(p.shape, dtype=bool)
    return p >= p.max() * 10.0 ** (-floor_db / 10.0)


def doppler_spectrum(freq: ArrayLike, psd: ArrayLike, cells: ArrayLike | None = None
                     ) -> NDArray:
    """The clutter's Doppler spectrum: eq DP1 summed over range cells, (C, N) [W/Hz]."""
    psd = np.asarray(psd)
    if cells is None:
        cells = clutter_cells(psd)
    return psd[..., np.asarray(cells, dtype=bool)].sum(axis=-1)


def doppler_moments(freq: ArrayLike, spectrum: ArrayLike) -> tuple[NDArray, NDArray]:
    """Eq DP2: centroid and rms width [Hz] of Doppler spectra (..., N) -> (...,) each."""
    f = np.asarray(freq, dtype=float)
    s = np.asarray(spectrum, dtype=float)
    tot = s.sum(axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        c = (s * f).sum(axis=-1) / tot
        w = np.sqrt((s * (f - c[..., None]) ** 2).sum(axis=-1) / tot)
    return c, w


def autocorrelation(compressed: ArrayLike, max_lag: int, cells: ArrayLike | None = None
                    ) -> NDArray:
    """Normalised temporal autocorrelation of range-compressed clutter, per channel.

    ``rho_c(m) = sum_{p, s} x[p + m, c, s] x*[p, c, s] / sum_{p, s} |x[p, c, s]|^2`` over
    the clutter cells, for lags ``m = 0 .. max_lag`` pulses; complex, shape
    (C, max_lag + 1). Its magnitude falls with the clutter's coherence time.
    """
    x = np.asarray(compressed)
    if cells is not None:
        x = x[..., np.asarray(cells, dtype=bool)]
    n_p = x.shape[0]
    if not 0 <= max_lag < n_p:
        raise ValueError(f"max_lag = {max_lag}: must be in [0, {n_p})")
    out = np.empty((x.shape[1], max_lag + 1), dtype=complex)
    for m in range(max_lag + 1):
        a, b = x[m:], x[:n_p - m]
        out[:, m] = (a * b.conj()).sum(axis=(0, 2)) / (
            np.sqrt((np.abs(a) ** 2).sum(axis=(0, 2)) * (np.abs(b) ** 2).sum(axis=(0, 2))))
    return out


__all__ = ["WINDOWS", "autocorrelation", "clutter_cells", "doppler_moments",
           "doppler_spectrum", "range_doppler"]
