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
finufft. The scatterers are cut into at most :data:`NUFFT_CHUNKS` contiguous chunks (a
constant, not the number of cores; chunks of at least :data:`MIN_CHUNK_POINTS`); each
chunk folds its points x_k and runs one single-threaded type-1 transform per channel on
worker threads (finufft releases the GIL), with a plan per thread that is kept between
pulses (``setpts`` per chunk: the plan's memory is not allocated and faulted in again at
every call). The chunks' partial sums are added in chunk order, so that the numbers are
the same bytes on any number of cores and worker threads. finufft's own threads would
contend for the few hundred grid points of a pulse (twice the CPU time), and a batch of
transforms (``n_trans``) evaluates the spreading kernel once per transform anyway, so it
saves nothing here while needing a stacked copy of the channels (``docs/performance.md``).
A channel that is +-1 times an earlier one (monostatic backscatter: S_vh = -S_hv in the
FSA bases by reciprocity, here to rounding) is not transformed when the bound
||F(a_c - s a_c')||_2 <= sqrt(N) ||a_c - s a_c'||_1 shows that reusing the earlier sum adds
at most :data:`MIRROR_TOLERANCE` x eps to its error: a quarter of the work of a monostatic
quad-pol pulse.
``precision="single"`` runs the float32 library (x_k and a_k rounded to float32, the
partial sums added in float64) at about half the CPU time and a relative error of about
1e-5 instead of 5e-10 (:func:`accumulate` gives the accuracy budget).
:func:`accumulate_cuda` does the same sum on a GPU with cufinufft (imported only there)
from arrays that never leave the device.

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
import threading
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

#: Most point chunks of one NUFFT accumulation: a constant, so that the partial sums (added
#: in chunk order) and hence the bytes do not depend on the machine's cores.
NUFFT_CHUNKS = 8

#: Fewest scatterers per chunk (a smaller set is cut into fewer chunks).
MIN_CHUNK_POINTS = 32768

#: A channel equal to +-1 times an earlier one (monostatic reciprocity) is not transformed
#: when its difference adds at most this fraction of eps to its error.
MIRROR_TOLERANCE = 0.01

#: Scatterers compared to find such channels before the whole channels are bounded.
MIRROR_PROBE = 16

#: Default NUFFT tolerance per precision, and the smallest one allowed.
EPS_DEFAULT = {"double": 1e-9, "single": 1e-5}
EPS_MIN = {"double": 1e-15, "single": 1e-6}


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

    def keeps_all(self, tau: NDArray[np.float64], pulse_samples: int) -> bool:
        """Whether :meth:`keep` is true for every scatterer (by the least and the greatest
        delay: two reductions instead of a mask; a NaN delay makes it False)."""
        if np.size(tau) == 0:
            return True
        lo, hi = self.bounds(pulse_samples)
        return bool(np.min(tau) > lo) and bool(np.max(tau) < hi)


def accumulate(tau: ArrayLike, amplitudes: ArrayLike, pulse_spectrum: ArrayLike,
               window: ReceiveWindow, eps: float | None = None, *, method: str = "auto",
               workers: int | None = None, precision: str = "double"
               ) -> NDArray[np.complex128]:
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
    eps : float, optional
        NUFFT relative tolerance (l2 over the modes, per channel); default 1e-9 in double
        precision, 1e-5 in single. Allowed: >= 1e-15 (double), >= 1e-6 (single: float32
        rounding of the points bounds the error at about 1e-5 whatever eps).
    method : {"auto", "nufft", "direct"}
        finufft type 1, the direct sum of the phasors (exact, O(K N)), or the direct sum
        when K N <= :data:`DIRECT_TERMS` and the NUFFT otherwise.
    workers : int, optional
        Threads over which the point chunks are spread (default: the CPUs this process
        may use, at most the number of chunks). The result does not depend on it (bit for
        bit).
    precision : {"double", "single"}
        The NUFFT in float64 (default) or float32 (about half the CPU time; see Notes).
        The direct sum is always float64.

    Returns
    -------
    ndarray (C, n_samples) or (n_samples,) complex
        r_m [sqrt(W)].

    Notes
    -----
    Accuracy. finufft's tolerance bounds the relative l2 error of the C x N phasor sums of
    each channel; by Parseval the error of r_m has the same ratio to the channel's echo
    (its power eps^2 times the echo power, spread over the window). Measured on a
    Simulation 2 pulse (520 840 facets, N = 210, against the exact sum): 4.5e-10 to 5e-10
    (-186 dB) at the default eps = 1e-9 in double precision, 1.2e-5 (-98 dB) in single
    precision. The single-precision floor sits below the 98 dB dynamic range of an ideal
    16-bit converter and far below the thermal noise whenever the clutter-to-noise ratio is
    under about 80 dB; it is *not* below the float64 rounding that the rest of the
    pipeline keeps (noise-free runs, shadowed range cells 100 dB under the clutter, tests
    at 1e-9), which is why double precision is the default (``docs/performance.md``).
    """
    if method not in ("auto", "nufft", "direct"):
        raise ValueError(f"method = {method!r}: allowed 'auto', 'nufft', 'direct'")
    if precision not in EPS_DEFAULT:
        raise ValueError(f"precision = {precision!r}: allowed 'double', 'single'")
    if eps is None:
        eps = EPS_DEFAULT[precision]
    elif not (EPS_MIN[precision] <= eps < 1.0):
        raise ValueError(f"eps = {eps!r} with precision {precision!r}: allowed "
                         f"{EPS_MIN[precision]:g} <= eps < 1")
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
    if any(r.shape != tau.shape for r in rows):
        raise ValueError(f"amplitudes: {len(rows)} channels of shapes "
                         f"{sorted({r.shape for r in rows})}, need {tau.shape} each (tau)")
    if method == "direct" or (method == "auto" and tau.size * n <= DIRECT_TERMS):
        phasors = _phasors_direct(_points(tau, window, n), np.stack(rows), n)
    else:
        phasors = _phasors_nufft(tau, rows, window, n, float(eps), workers, precision)
    out = np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]
    return out[0] if squeeze else out


def _points(tau: NDArray, window: ReceiveWindow, n: int,
            out: NDArray | None = None) -> NDArray[np.float64]:
    """Eq (E2): phasor points x_k = 2 pi (tau_k - t0) f_s / N [rad] folded into [-pi, pi)
    (written into ``out`` if given; no temporaries of the points' size), from the delays
    tau [s], the window's start t0 [s] and sampling rate f_s [Hz], and the period N
    [samples]."""
    u = np.subtract(tau, window.t0, out=out)
    u *= window.sampling_rate / n  # periods
    tmp = np.empty(min(_BLOCK, u.size))
    for i in range(0, u.size, _BLOCK):  # u -= floor(u + 1/2), block by block
        seg = u[i:i + _BLOCK]
        t = tmp[:seg.size]
        np.add(seg, 0.5, out=t)
        seg -= np.floor(t, out=t)
    u *= 2.0 * np.pi
    return u


#: Elements per block of the element-wise passes over a chunk (a small buffer that stays
#: in the cache; temporaries of a chunk's size cost page faults at every pulse).
_BLOCK = 8192


def _scratch(name: str, size: int, dtype: type) -> NDArray:
    """This thread's buffer ``name`` of at least ``size`` elements (kept between calls)."""
    bufs = getattr(_PLANS, "scratch", None)
    if bufs is None:
        bufs = _PLANS.scratch = {}
    buf = bufs.get(name)
    if buf is None or buf.size < size or buf.dtype != dtype:
        buf = bufs[name] = np.empty(size, dtype=dtype)
    return buf[:size]


def _chunk_bounds(k: int) -> list[int]:
    """Bounds of the contiguous point chunks: a function of K only (never of the cores)."""
    m = max(1, min(NUFFT_CHUNKS, k // MIN_CHUNK_POINTS))
    return [(i * k) // m for i in range(m + 1)]


def _phasors_direct(x: NDArray, a: NDArray, n: int) -> NDArray[np.complex128]:
    """sum_k a_ck exp(-j l x_k) for the N integer modes l in FFT order, (C, N)."""
    modes = np.fft.fftfreq(n, 1.0 / n)
    return a @ np.exp(-1j * np.outer(x, modes))


def _phasors_nufft(tau: NDArray, rows: list[NDArray], window: ReceiveWindow, n: int,
                   eps: float, workers: int | None, precision: str
                   ) -> NDArray[np.complex128]:
    """The same sums by finufft type 1: the points in :func:`_chunk_bounds` chunks, each
    chunk one single-threaded transform per channel on a worker thread (finufft releases
    the GIL), the partial sums added in chunk order (the same bytes for any workers).

    A channel that :func:`_mirror_candidates` finds to be +-1 times an earlier one
    (monostatic reciprocity: VH = -HV in the FSA bases) is not transformed: its sum is
    that of the earlier channel times +-1 when the whole channel's difference d adds at
    most :data:`MIRROR_TOLERANCE` x eps to its error (||F(d)||_2 <= sqrt(N) ||d||_1),
    and is transformed after all otherwise.
    """
    bounds = _chunk_bounds(tau.size)
    m = len(bounds) - 1
    if workers is None:
        workers = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
            os.cpu_count() or 1)
    # one pool per worker count asked, whatever the pulse's chunk count: its threads keep
    # their plans and buffers from pulse to pulse (a pool per chunk count would not)
    pool_size = max(1, min(int(workers), NUFFT_CHUNKS))
    workers = min(pool_size, m)
    dtype = np.complex128 if precision == "double" else np.complex64
    mirrors = _mirror_candidates(rows)

    def run(i: int, channels: list[int], skip: dict) -> tuple[NDArray, NDArray]:
        lo, hi = bounds[i], bounds[i + 1]
        x = _points(tau[lo:hi], window, n, out=_scratch("x", hi - lo, np.float64))
        if dtype is not np.complex128:
            x32 = _scratch("x32", hi - lo, np.float32)
            np.copyto(x32, x, casting="same_kind")
            x = x32
        plan = _plan(n, eps, dtype)
        plan.setpts(x)  # the plan reads x at each execute: this thread's buffer
        part = np.zeros((len(rows), n), dtype=dtype)
        l1 = np.zeros(len(rows))  # bounds of ||a_c - s a_src||_1 of the skipped channels
        for c in channels:  # a handful of channels
            if c in skip:
                src, sign = skip[c]
                l1[c] = _l1_difference(rows[c][lo:hi], rows[src][lo:hi], sign)
                continue
            a = rows[c][lo:hi]
            if dtype is not np.complex128:
                a32 = _scratch("a32", hi - lo, dtype)
                np.copyto(a32, a, casting="same_kind")
                a = a32
            plan.execute(a, out=part[c])
        return part, l1

    def gather(channels: list[int], skip: dict) -> tuple[NDArray, NDArray]:
        jobs = [functools.partial(run, i, channels, skip) for i in range(m)]
        parts = [j() for j in jobs] if workers == 1 else list(
            _pool(pool_size).map(lambda j: j(), jobs))
        total = parts[0][0].astype(np.complex128)
        l1 = parts[0][1]
        for p, d in parts[1:]:  # in chunk order, whichever thread finished first
            total += p
            l1 = l1 + d
        return total, l1

    total, l1 = gather(list(range(len(rows))), mirrors)
    redo = []
    for c, (src, sign) in mirrors.items():
        # the skipped sum's error: ||F(d)||_2 <= sqrt(N) ||d||_1 for d = a_c - s a_src
        norm = np.sqrt(np.sum(total[src].real ** 2 + total[src].imag ** 2))
        if np.sqrt(n) * l1[c] <= MIRROR_TOLERANCE * eps * norm:
            total[c] = sign * total[src]
        else:
            redo.append(c)
    if redo:  # not mirrored after all (the probe of _mirror_candidates was misled)
        again, _ = gather(redo, {})
        total[redo] = again[redo]
    return total


def _l1_difference(a: NDArray, b: NDArray, sign: float, block: int = _BLOCK) -> float:
    """sum_k |Re d_k| + |Im d_k| >= ||d||_1 for d = a - sign b, in blocks of a small
    buffer (no temporaries of the chunk's size: their page faults cost more than the sum).
    """
    buf = np.empty(min(block, a.size), dtype=np.complex128)
    op = np.subtract if sign > 0 else np.add
    total = 0.0
    for i in range(0, a.size, block):
        d = buf[:min(block, a.size - i)]
        op(a[i:i + block], b[i:i + block], out=d)
        v = d.view(np.float64)
        total += float(np.abs(v, out=v).sum())
    return total


def _mirror_candidates(rows: list[NDArray]) -> dict[int, tuple[int, float]]:
    """Channels c -> (earlier channel, sign s) with a_c = s a_earlier on the first
    :data:`MIRROR_PROBE` scatterers to 1e-12 (the whole channel is checked by the bound of
    :func:`_phasors_nufft`)."""
    out: dict[int, tuple[int, float]] = {}
    for c in range(1, len(rows)):
        b = rows[c][:MIRROR_PROBE]
        for src in range(c):
            if src in out:
                continue
            a = rows[src][:MIRROR_PROBE]
            sign = next((s for s in (1.0, -1.0)
                         if np.all(np.abs(b - s * a) <= 1e-12 * np.abs(a))), None)
            if sign is not None:
                out[c] = (src, sign)
                break
    return out


_PLANS = threading.local()

#: finufft plans kept per thread (periods N, tolerances and precisions in use).
MAX_PLANS = 4


def _plan(n: int, eps: float, dtype: type):
    """This thread's finufft type-1 plan for N modes (made once per thread, reused by
    every pulse, chunk and channel; a plan is never shared between threads)."""
    import finufft

    plans = getattr(_PLANS, "plans", None)
    if plans is None:
        plans = _PLANS.plans = {}
    key = (n, eps, np.dtype(dtype).name)
    if key not in plans:
        if len(plans) >= MAX_PLANS:  # the oldest goes (a run uses one or two)
            del plans[next(iter(plans))]
        # spread_sort=0: the fine grid of a pulse (2 N points) stays in the cache, and
        # sorting a chunk's points costs more than it saves (docs/performance.md)
        plans[key] = finufft.Plan(1, (n,), n_trans=1, eps=eps, isign=-1,
                                  dtype=np.dtype(dtype).name, modeord=1, nthreads=1,
                                  spread_sort=0)
    return plans[key]


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
    return accumulate_cuda_sets(xp, [(tau, amplitudes)], pulse_spectrum, window, eps)


def accumulate_cuda_sets(xp, sets: list, pulse_spectrum: ArrayLike, window: ReceiveWindow,
                         eps: float = 1e-9) -> NDArray[np.complex128]:
    """:func:`accumulate_cuda` of several point sets of one pulse (the sea's facets, a
    hull's centres) as one transform.

    Eq (E2) is a sum over scatterers, so the sets' points are concatenated on the device
    (their folded phasor points into one (K,) buffer, their channels into one (C, K)
    buffer, in the kernel that folds them) and go through one ``setpts``, one cufinufft
    call (``n_trans = C``), one pair of context synchronisations, one copy of the (C, N)
    sums and one inverse FFT on the host: the host work of a pulse, not of each set.

    Parameters
    ----------
    xp : seaecho.backend.DrJitNamespace
    sets : list of (tau, amplitudes)
        Each as :func:`accumulate_cuda`'s ``tau`` and ``amplitudes`` (the same C).
    pulse_spectrum, window, eps
        As :func:`accumulate_cuda`.

    Returns
    -------
    ndarray (C, n_samples) complex
        The sum of the sets' r_m [sqrt(W)], to the NUFFT tolerance.
    """
    import cufinufft

    from ..backend import cuda_array, cuda_synchronize

    spec = np.asarray(pulse_spectrum)
    n = spec.size
    c = len(sets[0][1])
    sets = [(t, a) for t, a in sets if xp.width(t) > 0]
    widths = [xp.width(t) for t, _ in sets]
    k = sum(widths)
    if k == 0:
        return np.zeros((c, window.n_samples), dtype=np.complex128)

    def fold(tau):  # eq (E2): the phasor points, folded into [-pi, pi)
        u = (tau - xp.const(window.t0)) * (window.sampling_rate / n) + 0.5
        return (2.0 * np.pi) * (u - xp.floor(u)) - np.pi

    if len(sets) == 1:
        x = fold(sets[0][0])
    else:  # the sets' points one after the other
        x, off = xp.empty(k), 0
        for (t, _), w in zip(sets, widths, strict=True):
            xp.scatter(x, fold(t), xp.arange(w) + off)
            off += w
    if CUDA_BATCH_CHANNELS and c > 1:
        # the channels stacked into one (C, K) buffer on the device (one kernel), one
        # cufinufft call with n_trans = C, one copy of the (C, N) sums to the host
        stacked, off = xp.empty(2 * c * k), 0
        for (_, amps), w in zip(sets, widths, strict=True):
            idx = xp.arange(2 * w) + 2 * off
            for j, a in enumerate(amps):
                xp.scatter(stacked, a, idx + 2 * k * j)
            off += w
        sums = xp.empty(2 * c * n)
        xp.eval(x, stacked, sums)
        cuda_synchronize()
        plan = _cuda_plan(cufinufft, n, float(eps), c)
        plan.setpts(cuda_array(x, np.float64, (k,)))
        plan.execute(cuda_array(stacked, np.complex128, (c, k)),
                     out=cuda_array(sums, np.complex128, (c, n)))
        cuda_synchronize()
        phasors = np.asarray(xp.host(sums)).view(np.complex128).reshape(c, n)
        return np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]
    if len(sets) == 1:
        channels = list(sets[0][1])
    else:  # each channel's sets one after the other
        channels, off = [xp.empty(2 * k) for _ in range(c)], 0
        for (_, amps), w in zip(sets, widths, strict=True):
            idx = xp.arange(2 * w) + 2 * off
            for buf, a in zip(channels, amps, strict=True):
                xp.scatter(buf, a, idx)
            off += w
    out = [xp.empty(2 * n) for _ in range(c)]
    xp.eval(x, *channels, *out)
    cuda_synchronize()
    plan = _cuda_plan(cufinufft, n, float(eps))
    plan.setpts(cuda_array(x, np.float64, (k,)))
    for a, o in zip(channels, out, strict=True):
        plan.execute(cuda_array(a, np.complex128, (k,)), out=cuda_array(o, np.complex128, (n,)))
    cuda_synchronize()
    phasors = np.stack([np.asarray(xp.host(o)).view(np.complex128) for o in out])
    return np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]


#: :func:`accumulate_cuda` transforms a point set's C channels in one cufinufft call
#: (``n_trans = C``, the channels stacked on the device) instead of one call per channel.
CUDA_BATCH_CHANNELS = True

_CUDA_PLANS: dict[tuple[int, float, int], object] = {}


def _cuda_plan(cufinufft, n: int, eps: float, n_trans: int = 1):
    """A cufinufft type-1 plan for N modes and ``n_trans`` channels at once (made once,
    reused by every pulse and point set)."""
    key = (n, eps, n_trans)
    if key not in _CUDA_PLANS:
        _CUDA_PLANS[key] = cufinufft.Plan(1, (n,), n_trans=n_trans, eps=eps, isign=-1,
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
    "MIN_CHUNK_POINTS",
    "MIRROR_PROBE",
    "MIRROR_TOLERANCE",
    "NUFFT_CHUNKS",
    "accumulate",
    "accumulate_cuda_sets",
    "accumulate_cuda",
    "accumulate_direct",
    "accumulate_pulse_write",
]
