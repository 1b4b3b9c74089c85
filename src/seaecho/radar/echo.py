"""Echo accumulation: the sum of delayed pulse copies, by a non-uniform FFT.

The received complex baseband signal of one pulse, on one channel, is

.. math::

    r(t) = \\sum_k a_k\\, s(t - \\tau_k)                                                (E1)

with a_k the complex amplitude of scatterer k (radar equation, carrier phase
e^{-j 2 pi f_c tau_k} included) and s the band-limited transmitted envelope. Sampled at
t_m = t_0 + m / f_s on a period of N samples (N f_s^-1 longer than the receive window
plus the pulse), its DFT is the pulse spectrum times a sum of phasors at non-uniform
delays,

.. math::

    R_l = S_l \\sum_k a_k\\, e^{-j 2\\pi l (\\tau_k - t_0) f_s / N},\\qquad
    r_m = \\frac1N \\sum_l R_l\\, e^{+j 2\\pi l m / N}                                  (E2)

(l over -N/2 .. N/2-1, S_l the DFT of the pulse samples). The inner sum is a type-1
non-uniform FFT of the points x_k = 2 pi (tau_k - t_0) f_s / N with strengths a_k
(Dutt & Rokhlin 1993; finufft, Barnett et al. 2019): O(N_k + N log N) instead of the
O(N_k N_p) of writing each scatterer's pulse into the array (the paper's section V-B
bottleneck), and exact for fractional delays, within the NUFFT tolerance.

Scatterers whose echo cannot reach the window (tau outside
[t_0 - T - guard, t_0 + T_w + guard]) are dropped before the sum; the period N leaves
``guard`` samples on both sides so that no kept echo wraps around into the window.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] A. Dutt and V. Rokhlin, "Fast Fourier transforms for nonequispaced data",
   SIAM J. Sci. Comput. 14(6), 1368-1393, 1993.
.. [2] A. H. Barnett, J. Magland and L. af Klinteberg, "A parallel nonuniform fast
   Fourier transform library based on an 'exponential of semicircle' kernel",
   SIAM J. Sci. Comput. 41(5), C479-C504, 2019.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.fft import next_fast_len

from ..constants import C0

#: Guard samples on each side of the window in the NUFFT period.
GUARD = 32


@dataclass(frozen=True)
class ReceiveWindow:
    """Fast-time sampling of one pulse's echo.

    Attributes
    ----------
    t0 : float
        Delay of the first sample after the pulse's emission [s].
    n_samples : int
        Samples per pulse and channel.
    sampling_rate : float
        f_s [Hz].
    """

    t0: float
    n_samples: int
    sampling_rate: float

    @classmethod
    def from_ranges(cls, start_m: float, end_m: float, sampling_rate: float,
                    pulse_duration: float) -> ReceiveWindow:
        """Window covering ranges c tau / 2 in [start_m, end_m] plus one pulse length.

        Parameters
        ----------
        start_m, end_m : float
            Ranges (half the bistatic path length) [m].
        sampling_rate : float
            f_s [Hz].
        pulse_duration : float
            T [s]; the echo of the farthest range lasts T after its delay.
        """
        if not (0 <= start_m < end_m):
            raise ValueError(f"window [{start_m}, {end_m}] m: need 0 <= start < end")
        t0 = 2.0 * start_m / C0
        n = int(np.ceil((2.0 * (end_m - start_m) / C0 + pulse_duration) * sampling_rate)) + 1
        return cls(t0, n, sampling_rate)

    @property
    def fast_time(self) -> NDArray[np.float64]:
        """Delays of the samples after emission [s], shape (n_samples,)."""
        return self.t0 + np.arange(self.n_samples) / self.sampling_rate

    @property
    def duration(self) -> float:
        """Length of the window [s]."""
        return self.n_samples / self.sampling_rate

    def n_fft(self, pulse_samples: int) -> int:
        """NUFFT period N: window + pulse + 2 guards, rounded up to a fast FFT size."""
        return int(next_fast_len(self.n_samples + pulse_samples + 2 * GUARD))

    def keep(self, tau: NDArray[np.float64], pulse_samples: int) -> NDArray[np.bool_]:
        """Scatterers whose echo overlaps the window (with the guards)."""
        lo = self.t0 - (pulse_samples + GUARD // 2) / self.sampling_rate
        hi = self.t0 + (self.n_samples + GUARD // 2) / self.sampling_rate
        return (tau > lo) & (tau < hi)


def accumulate(tau: ArrayLike, amplitudes: ArrayLike, pulse_spectrum: ArrayLike,
               window: ReceiveWindow, eps: float = 1e-9) -> NDArray[np.complex128]:
    """Sum of delayed pulse copies on the window's samples, eq (E2), by finufft type 1.

    Parameters
    ----------
    tau : array_like (K,)
        Delays [s] (float64), all within ``window.keep``.
    amplitudes : array_like (C, K) or (K,) complex
        Complex amplitudes a_k per channel [sqrt(W)], carrier phase included.
    pulse_spectrum : array_like (N,) complex
        DFT of the pulse zero-padded to the period N (``Waveform.spectrum(N)``).
    window : ReceiveWindow
        Fast-time sampling.
    eps : float
        NUFFT relative tolerance.

    Returns
    -------
    ndarray (C, n_samples) or (n_samples,) complex
        r_m [sqrt(W)].
    """
    import finufft

    tau = np.ascontiguousarray(tau, dtype=np.float64)
    a = np.asarray(amplitudes, dtype=np.complex128)
    squeeze = a.ndim == 1
    a = np.ascontiguousarray(np.atleast_2d(a))
    spec = np.asarray(pulse_spectrum)
    n = spec.size
    if tau.size == 0:
        out = np.zeros((a.shape[0], window.n_samples), dtype=np.complex128)
        return out[0] if squeeze else out
    # Eq (E2): phasor points x_k = 2 pi (tau_k - t0) f_s / N folded into [-pi, pi)
    x = 2.0 * np.pi * ((tau - window.t0) * window.sampling_rate / n)
    x = np.mod(x + np.pi, 2.0 * np.pi) - np.pi
    # One thread: finufft's multithreaded spreading adds its sub-grids in an order that
    # depends on the thread count, so the bytes would depend on the machine (the same
    # scene and seed must give the same bytes on one core or a cluster)
    phasors = finufft.nufft1d1(x, a, n_modes=n, eps=eps, isign=-1, modeord=1,
                               nthreads=1)
    out = np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]
    return out[0] if squeeze else out


def accumulate_direct(tau: ArrayLike, amplitudes: ArrayLike, pulse_spectrum: ArrayLike,
                      window: ReceiveWindow) -> NDArray[np.complex128]:
    """Eq (E2) by the direct sum over scatterers and frequencies (reference, O(K N))."""
    tau = np.asarray(tau, dtype=np.float64)
    a = np.atleast_2d(np.asarray(amplitudes, dtype=np.complex128))
    spec = np.asarray(pulse_spectrum)
    n = spec.size
    l_idx = np.fft.fftfreq(n, 1.0 / n)  # integer bins in FFT order
    phase = np.exp(-2j * np.pi * np.outer(l_idx, (tau - window.t0) * window.sampling_rate / n))
    out = np.fft.ifft((a @ phase.T) * spec, axis=-1)[:, :window.n_samples]
    return out[0] if np.ndim(amplitudes) == 1 else out


def accumulate_pulse_write(tau: ArrayLike, amplitudes: ArrayLike,
                           envelope: Callable[[NDArray], NDArray], duration: float,
                           window: ReceiveWindow, chunk: int = 16384) -> NDArray[np.complex128]:
    """Eq (E1) the paper's way: write each scatterer's delayed pulse into the array.

    The analytic envelope s(t) is evaluated at t_m - tau_k on the samples it covers and
    added in. O(K N_p); kept as the reference of the benchmark (paper section V-B).

    Parameters
    ----------
    tau : array_like (K,)
        Delays [s].
    amplitudes : array_like (C, K) complex
        Amplitudes [sqrt(W)].
    envelope : callable
        s(t) for t in [0, T) [-].
    duration : float
        T [s].
    window : ReceiveWindow
        Fast-time sampling.
    chunk : int
        Scatterers per vectorised block (bounds the memory).
    """
    tau = np.asarray(tau, dtype=np.float64)
    a = np.atleast_2d(np.asarray(amplitudes, dtype=np.complex128))
    fs = window.sampling_rate
    n_p = int(np.ceil(duration * fs)) + 1
    out = np.zeros((a.shape[0], window.n_samples + n_p + 2), dtype=np.complex128)
    for i in range(0, tau.size, chunk):  # blocks of scatterers, each block vectorised
        t = tau[i:i + chunk]
        first = np.ceil((t - window.t0) * fs).astype(np.int64)  # first sample after tau
        m = first[:, None] + np.arange(n_p)  # (k, n_p) sample indices
        ok = (m >= 0) & (m < window.n_samples)
        dt = window.t0 + m / fs - t[:, None]
        ok &= dt < duration
        vals = envelope(np.where(ok, dt, 0.0)) * ok
        idx = np.where(ok, m, window.n_samples)  # out-of-window writes land in a bin
        for c in range(a.shape[0]):
            np.add.at(out[c], idx, a[c, i:i + chunk, None] * vals)
    out = out[:, :window.n_samples]
    return out[0] if np.ndim(amplitudes) == 1 else out


__all__ = [
    "GUARD",
    "ReceiveWindow",
    "accumulate",
    "accumulate_direct",
    "accumulate_pulse_write",
]
