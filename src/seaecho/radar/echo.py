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

Evaluation. :func:`accumulate` sums the phasors of eq (E2) directly when there are few
terms (scatterers x modes <= :data:`DIRECT_TERMS`: point targets), and otherwise by
finufft, each channel a single-threaded transform, the channels spread over worker
threads: the numbers are then those of the single-threaded library whatever the number
of cores (bit for bit), and the work parallelises over the channels (finufft's own
threads contend for the few hundred grid points of a pulse and cost twice the CPU time,
``docs/performance.md``). :func:`accumulate_cuda` does the same sum on a GPU with
cufinufft (imported only there) from arrays that never leave the device.

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

import functools
import os
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.fft import next_fast_len

from ..constants import C0

#: Guard samples on each side of the window in the NUFFT period.
GUARD = 32

#: Scatterers x modes up to which eq (E2) is summed directly (exact; a handful of point
#: targets takes microseconds, where a NUFFT's set-up takes milliseconds).
DIRECT_TERMS = 1 << 16


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

    def bounds(self, pulse_samples: int) -> tuple[float, float]:
        """Delays (lo, hi) [s] strictly between which an echo overlaps the window (with
        the guards)."""
        lo = self.t0 - (pulse_samples + GUARD // 2) / self.sampling_rate
        hi = self.t0 + (self.n_samples + GUARD // 2) / self.sampling_rate
        return lo, hi

    def keep(self, tau: NDArray[np.float64], pulse_samples: int) -> NDArray[np.bool_]:
        """Scatterers whose echo overlaps the window (with the guards)."""
        lo, hi = self.bounds(pulse_samples)
        return (tau > lo) & (tau < hi)


def accumulate(tau: ArrayLike, amplitudes: ArrayLike, pulse_spectrum: ArrayLike,
               window: ReceiveWindow, eps: float = 1e-9, *, method: str = "auto",
               workers: int | None = None) -> NDArray[np.complex128]:
    """Sum of delayed pulse copies on the window's samples, eq (E2).

    Parameters
    ----------
    tau : array_like (K,)
        Delays [s] (float64), all within ``window.keep``.
    amplitudes : array_like (C, K) or (K,) complex, or a list of C (K,) arrays
        Complex amplitudes a_k per channel [sqrt(W)], carrier phase included.
    pulse_spectrum : array_like (N,) complex
        DFT of the pulse zero-padded to the period N (``Waveform.spectrum(N)``).
    window : ReceiveWindow
        Fast-time sampling.
    eps : float
        NUFFT relative tolerance.
    method : {"auto", "nufft", "direct"}
        finufft type 1, the direct sum of the phasors (exact, O(K N)), or the direct sum
        when K N <= :data:`DIRECT_TERMS` and the NUFFT otherwise.
    workers : int, optional
        Threads over which the channels are spread (default: the CPUs this process may
        use, at most C). The result does not depend on it.

    Returns
    -------
    ndarray (C, n_samples) or (n_samples,) complex
        r_m [sqrt(W)].
    """
    if method not in ("auto", "nufft", "direct"):
        raise ValueError(f"method = {method!r}: allowed 'auto', 'nufft', 'direct'")
    tau = np.ascontiguousarray(tau, dtype=np.float64)
    if isinstance(amplitudes, list | tuple):  # one (K,) array per channel
        squeeze = False
        rows = [np.ascontiguousarray(a, dtype=np.complex128) for a in amplitudes]
    else:
        a = np.asarray(amplitudes, dtype=np.complex128)
        squeeze = a.ndim == 1
        a = np.ascontiguousarray(np.atleast_2d(a))
        rows = list(a)
    spec = np.asarray(pulse_spectrum)
    n = spec.size
    if tau.size == 0:
        out = np.zeros((len(rows), window.n_samples), dtype=np.complex128)
        return out[0] if squeeze else out
    # Eq (E2): phasor points x_k = 2 pi (tau_k - t0) f_s / N folded into [-pi, pi)
    x = 2.0 * np.pi * ((tau - window.t0) * window.sampling_rate / n)
    x = np.mod(x + np.pi, 2.0 * np.pi) - np.pi
    if method == "direct" or (method == "auto" and tau.size * n <= DIRECT_TERMS):
        phasors = _phasors_direct(x, np.stack(rows), n)
    else:
        phasors = _phasors_nufft(x, rows, n, eps, workers)
    out = np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]
    return out[0] if squeeze else out


def _phasors_direct(x: NDArray, a: NDArray, n: int) -> NDArray[np.complex128]:
    """sum_k a_ck exp(-j l x_k) for the N integer modes l in FFT order, (C, N)."""
    modes = np.fft.fftfreq(n, 1.0 / n)
    return a @ np.exp(-1j * np.outer(x, modes))


def _phasors_nufft(x: NDArray, rows: list[NDArray], n: int, eps: float,
                   workers: int | None) -> NDArray[np.complex128]:
    """The same sums by finufft type 1: one single-threaded transform per channel, the
    channels on worker threads (finufft releases the GIL)."""
    import finufft

    c = len(rows)
    if workers is None:
        workers = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
            os.cpu_count() or 1)
    workers = max(1, min(int(workers), c))

    def run(a: NDArray) -> NDArray[np.complex128]:
        return finufft.nufft1d1(x, a, n_modes=n, eps=eps, isign=-1, modeord=1, nthreads=1)

    if workers == 1:
        return np.stack([run(a) for a in rows])
    return np.stack(list(_pool(workers).map(run, rows)))


@functools.cache
def _pool(workers: int) -> ThreadPoolExecutor:
    return ThreadPoolExecutor(workers, thread_name_prefix="seaecho-nufft")


if hasattr(os, "register_at_fork"):  # a forked worker process gets pools of its own
    os.register_at_fork(after_in_child=_pool.cache_clear)


def accumulate_cuda(xp, tau: object, amplitudes: tuple, pulse_spectrum: ArrayLike,
                    window: ReceiveWindow, eps: float = 1e-9) -> NDArray[np.complex128]:
    """Eq (E2) on a GPU: cufinufft type 1 on arrays that stay on the device.

    Parameters
    ----------
    xp : seaecho.backend.DrJitNamespace
        The ``drjit.cuda`` namespace holding the inputs.
    tau : Dr.Jit Float64 (K,)
        Delays [s], all within ``window.keep``.
    amplitudes : tuple of C Dr.Jit Float64 (2 K,)
        Complex amplitudes [sqrt(W)] per channel, interleaved (re, im): the memory of a
        complex (K,) array each.
    pulse_spectrum : array_like (N,) complex
        As :func:`accumulate`.
    window : ReceiveWindow
    eps : float
        NUFFT relative tolerance.

    Returns
    -------
    ndarray (C, n_samples) complex
        r_m [sqrt(W)]; only the C x N mode sums come back to the host.

    Notes
    -----
    cufinufft accumulates with atomic additions: the last bits of the sums depend on
    the order in which the GPU's threads run (results agree with :func:`accumulate` to
    the NUFFT tolerance, not bit for bit).
    """
    import cufinufft

    from ..backend import cuda_array, cuda_synchronize

    spec = np.asarray(pulse_spectrum)
    n, c = spec.size, len(amplitudes)
    k = xp.width(tau)
    if k == 0:
        return np.zeros((c, window.n_samples), dtype=np.complex128)
    # Eq (E2): the phasor points, folded into [-pi, pi)
    u = (tau - xp.const(window.t0)) * (window.sampling_rate / n) + 0.5
    x = (2.0 * np.pi) * (u - xp.floor(u)) - np.pi
    out = [xp.empty(2 * n) for _ in range(c)]
    xp.eval(x, *amplitudes, *out)
    cuda_synchronize()
    plan = _cuda_plan(cufinufft, n, float(eps))
    plan.setpts(cuda_array(x, np.float64, (k,)))
    for a, o in zip(amplitudes, out, strict=True):
        plan.execute(cuda_array(a, np.complex128, (k,)), out=cuda_array(o, np.complex128, (n,)))
    cuda_synchronize()
    phasors = np.stack([np.asarray(xp.host(o)).view(np.complex128) for o in out])
    return np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]


_CUDA_PLANS: dict[tuple[int, float], object] = {}


def _cuda_plan(cufinufft, n: int, eps: float):
    """A cufinufft type-1 plan for N modes (made once, reused by every pulse and channel)."""
    key = (n, eps)
    if key not in _CUDA_PLANS:
        _CUDA_PLANS[key] = cufinufft.Plan(1, (n,), n_trans=1, eps=eps, isign=-1,
                                          dtype="complex128", modeord=1)
    return _CUDA_PLANS[key]


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
    "DIRECT_TERMS",
    "accumulate",
    "accumulate_cuda",
    "accumulate_direct",
    "accumulate_pulse_write",
]
