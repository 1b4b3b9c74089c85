"""Echo accumulation by NUFFT against the direct sum and the per-facet pulse write.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.radar import echo
from seaecho.radar.echo import (
    ReceiveWindow,
    accumulate,
    accumulate_direct,
    accumulate_pulse_write,
)
from seaecho.radar.waveform import lfm_chirp, plain_pulse

FS = 100e6
B, T = 40e6, 1.0e-6


def _setup():
    s = lfm_chirp(B, T, FS)
    w = ReceiveWindow(t0=12e-6, n_samples=500, sampling_rate=FS)
    return s, w, np.fft.fft(s, w.n_fft(s.size))


def test_nufft_equals_direct_sum():
    # Eq (E2) by finufft type 1 against the explicit O(K N) sum: the peak error within 1e-8
    # of the peak at the default eps = 1e-9 (docs/radar.md; measured 2e-10)
    s, w, spec = _setup()
    rng = np.random.default_rng(0)
    k = 2000
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((4, k)) + 1j * rng.standard_normal((4, k))
    fast = accumulate(tau, a, spec, w)
    ref = accumulate_direct(tau, a, spec, w)
    assert np.abs(fast - ref).max() <= 1e-8 * np.abs(ref).max()


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 400))
def test_integer_delay_reproduces_the_pulse(m0):
    # At an integer-sample delay the band-limited echo is the pulse samples themselves
    s, w, spec = _setup()
    r = accumulate(np.array([w.t0 + m0 / FS]), np.array([1.0 + 0j]), spec, w)
    expected = np.zeros(w.n_samples, complex)
    end = min(m0 + s.size, w.n_samples)
    expected[m0:end] = s[:end - m0]
    np.testing.assert_allclose(r, expected, atol=1e-8)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.0, 1.0), st.floats(0.0, 1.0))
def test_fractional_delays_compose(f1, f2):
    # Delaying by f1 then by f2 samples equals delaying by f1 + f2: the fractional delay
    # is the exact shift of the band-limited pulse (a phase ramp), not an approximation.
    s, w, spec = _setup()
    d1 = 100 + f1
    r1 = accumulate(np.array([w.t0 + d1 / FS]), np.array([1.0 + 0j]), spec, w)
    spec1 = np.fft.fft(r1, spec.size)
    w2 = ReceiveWindow(w.t0, w.n_samples, FS)
    r12 = accumulate(np.array([w.t0 + f2 / FS]), np.array([1.0 + 0j]), spec1, w2)
    r_direct = accumulate(np.array([w.t0 + (d1 + f2) / FS]), np.array([1.0 + 0j]), spec, w)
    # tails of the first echo wrapped out of the window limit this to ~1e-3
    assert np.abs(r12 - r_direct)[150:300].max() < 2e-3


def test_pulse_write_agrees_in_the_pulse_interior():
    # The paper's per-scatterer write with the analytic chirp and the NUFFT sum of the
    # band-limited chirp agree away from the pulse edges (where the rectangular
    # envelope is not band-limited), here to 3 % of the amplitude.
    s, w, spec = _setup()
    rng = np.random.default_rng(2)
    tau = w.t0 + 100 / FS + rng.uniform(0, 1, 5) / FS
    a = np.exp(2j * np.pi * rng.uniform(size=5))
    fast = accumulate(tau, a, spec, w)
    k = B / T

    def env(t):
        return np.exp(1j * np.pi * k * (t - T / 2) ** 2)

    slow = accumulate_pulse_write(tau, a, env, T, w)
    inner = slice(120, 180)
    assert np.abs(fast[inner] - slow[inner]).max() < 0.03 * np.abs(a).sum()


def test_echo_outside_window_is_not_wrapped():
    # keep() drops what cannot reach the window; kept echoes never wrap around
    s, w, spec = _setup()
    tau = np.array([w.t0 + w.duration + 1e-6, w.t0 - 2 * T])
    assert not w.keep(tau, s.size).any()
    near = np.array([w.t0 + w.duration - 1 / FS])
    r = accumulate(near, np.array([1.0 + 0j]), spec, w)
    assert np.abs(r[:400]).max() < 1e-2


def test_plain_pulse_and_window_from_ranges():
    p = plain_pulse(1e-6, FS)
    assert p.size == 100 and np.all(p == 1)
    w = ReceiveWindow.from_ranges(1500.0, 1800.0, FS, 1e-6)
    assert w.t0 == pytest.approx(1e-5, rel=1e-3)
    # covers the round-trip extent plus one pulse
    assert w.duration >= 2 * 300.0 / 299_792_458.0 + 1e-6


def _scatterers(w, k, c=4, seed=3):
    rng = np.random.default_rng(seed)
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((c, k)) + 1j * rng.standard_normal((c, k))
    return tau, a


def _rel_l2(a, b):
    return np.linalg.norm(a - b) / np.linalg.norm(b)


@pytest.fixture
def small_chunks(monkeypatch):
    # Chunks of a few hundred points, so that a few thousand scatterers (a direct sum that
    # takes milliseconds) already run as echo.NUFFT_CHUNKS chunks.
    monkeypatch.setattr(echo, "MIN_CHUNK_POINTS", 256)


@pytest.mark.parametrize("precision, tol", [("double", 5e-9), ("single", 5e-5)])
def test_chunked_nufft_equals_the_direct_sum(small_chunks, precision, tol):
    # Eq (E2) in 8 point chunks against the explicit O(K N) sum (accumulate_direct, its own
    # phases, no folding): finufft's tolerance is a relative l2 error over the modes
    # (Barnett, Magland & af Klinteberg 2019; here 2e-10 at the default eps = 1e-9, 1.5e-5
    # in float32). A chunk dropped or added twice (an error of 1/8 of the signal), or a
    # wrong sign of the exponent, fails.
    s, w, spec = _setup()
    tau, a = _scatterers(w, 3000)
    assert len(echo._chunk_bounds(tau.size)) - 1 == echo.NUFFT_CHUNKS
    ref = accumulate_direct(tau, a, spec, w)
    fast = accumulate(tau, a, spec, w, precision=precision)
    for got, want in zip(fast, ref, strict=True):  # each channel against its own norm
        assert _rel_l2(got, want) <= tol
    if precision == "single":  # really float32: its rounding of the points is the floor
        # (1.3e-5 here), where the float64 library at the same eps = 1e-6 gives 4e-8
        fine = accumulate(tau, a, spec, w, eps=1e-6, precision="single")
        assert _rel_l2(fine, ref) > 2e-6


def test_chunks_and_worker_threads_give_the_same_bytes(small_chunks):
    # The partial sums of the chunks are added in chunk order whatever thread finished
    # first: 1, 2, 3 or 8 workers, the channels as an array or as a list of per-channel
    # arrays, and a second call on the threads' kept plans give the same bytes (a result
    # that depended on the machine's core count would not be reproducible).
    s, w, spec = _setup()
    tau, a = _scatterers(w, 5000)
    one = accumulate(tau, a, spec, w, workers=1)
    others = [accumulate(tau, a, spec, w, workers=m) for m in (2, 3, 8)]
    others.append(accumulate(tau, list(a), spec, w, workers=2))
    accumulate(tau[:100], a[:, :100], spec[:300], w, method="nufft")  # other plans between
    others.append(accumulate(tau, a, spec, w, workers=2))
    for other in others:
        assert other.tobytes() == one.tobytes()


def test_chunked_and_unchunked_sums_agree(small_chunks, monkeypatch):
    # One chunk against eight: the NUFFT is linear, so they differ by rounding only
    # (a chunk lost or counted twice would be an error of about 1/8).
    s, w, spec = _setup()
    tau, a = _scatterers(w, 4000)
    chunked = accumulate(tau, a, spec, w)
    monkeypatch.setattr(echo, "NUFFT_CHUNKS", 1)
    whole = accumulate(tau, a, spec, w)
    assert _rel_l2(chunked, whole) <= 1e-12


@pytest.mark.parametrize("k", [1, 3, 5, 9])
def test_fewer_points_than_chunks(monkeypatch, k):
    # Chunks of one point each (k < NUFFT_CHUNKS) or eight of one or two: every chunk
    # non-empty, each scatterer in exactly one, against the direct sum.
    monkeypatch.setattr(echo, "MIN_CHUNK_POINTS", 1)
    bounds = echo._chunk_bounds(k)
    assert bounds[0] == 0 and bounds[-1] == k and np.all(np.diff(bounds) >= 1)
    assert len(bounds) - 1 == min(k, echo.NUFFT_CHUNKS)
    s, w, spec = _setup()
    tau, a = _scatterers(w, k, seed=k)
    fast = accumulate(tau, a, spec, w, method="nufft")
    assert _rel_l2(fast, accumulate_direct(tau, a, spec, w)) <= 1e-8


def test_chunk_bounds_depend_on_the_points_only():
    # The chunking is a function of K (never of the cores): contiguous, covering, and at
    # most NUFFT_CHUNKS chunks of at least MIN_CHUNK_POINTS (one chunk below that).
    for k in (0, 1, echo.MIN_CHUNK_POINTS, 3 * echo.MIN_CHUNK_POINTS + 7, 10**7 + 3):
        b = echo._chunk_bounds(k)
        m = len(b) - 1
        assert b[0] == 0 and b[-1] == k and np.all(np.diff(b) >= 0)
        assert m == max(1, min(echo.NUFFT_CHUNKS, k // echo.MIN_CHUNK_POINTS))
        if m > 1:
            assert min(np.diff(b)) >= echo.MIN_CHUNK_POINTS


def test_mirrored_channel_is_the_earlier_sum_within_the_bound(small_chunks):
    # Monostatic reciprocity in the FSA bases: VH = -HV (to rounding, 1e-15 here). The VH
    # sum is then -1 times the HV sum (bit for bit: the transform was skipped), and both
    # agree with the direct sum of eq (E2) to the tolerance; any number of workers gives
    # the same bytes.
    s, w, spec = _setup()
    tau, a = _scatterers(w, 4000, seed=7)
    a[2] = -a[1] * (1.0 + 1e-15 * np.random.default_rng(8).standard_normal(a.shape[1]))
    assert not np.array_equal(a[2], -a[1])
    ref = accumulate_direct(tau, a, spec, w)
    fast = accumulate(tau, a, spec, w, workers=1)
    assert fast[2].tobytes() == (-fast[1]).tobytes()
    for got, want in zip(fast, ref, strict=True):
        assert _rel_l2(got, want) <= 5e-9
    assert accumulate(tau, list(a), spec, w, workers=3).tobytes() == fast.tobytes()


def test_channel_mirrored_only_at_its_start_is_transformed(small_chunks):
    # VH = -HV on the first scatterers (the probe) but not beyond: the bound on the whole
    # channel refuses the shortcut and VH gets its own transform (taking -HV for it would
    # be an error of order 1 on the perturbed scatterers).
    s, w, spec = _setup()
    tau, a = _scatterers(w, 4000, seed=9)
    a[2] = -a[1]
    a[2, echo.MIRROR_PROBE:] *= 1.0 + 1e-6
    fast = accumulate(tau, a, spec, w)
    ref = accumulate_direct(tau, a, spec, w)
    assert fast[2].tobytes() != (-fast[1]).tobytes()
    for got, want in zip(fast, ref, strict=True):
        assert _rel_l2(got, want) <= 5e-9


def test_kept_plans_are_bounded_and_remade_plans_give_the_same_bytes():
    # Each thread keeps at most MAX_PLANS finufft plans (one per period, tolerance and
    # precision); a plan evicted and made again gives the same bytes.
    s, w, spec = _setup()
    tau, a = _scatterers(w, 3000)
    first = accumulate(tau, a, spec, w, method="nufft", workers=1)
    for extra in range(echo.MAX_PLANS + 2):  # other periods in between
        accumulate(tau, a, np.fft.fft(s, spec.size + 1 + extra), w, method="nufft", workers=1)
    assert len(echo._PLANS.plans) == echo.MAX_PLANS
    assert accumulate(tau, a, spec, w, method="nufft", workers=1).tobytes() == first.tobytes()


def test_single_channel_and_empty_input():
    # A (K,) row gives a (n_samples,) trace equal to that channel of the (C, K) call; no
    # scatterers give zeros of the right shapes; both precisions.
    s, w, spec = _setup()
    tau, a = _scatterers(w, 30000)  # above DIRECT_TERMS: the NUFFT
    for precision in ("double", "single"):
        both = accumulate(tau, a, spec, w, precision=precision)
        one = accumulate(tau, a[2], spec, w, precision=precision)
        assert one.shape == (w.n_samples,)
        assert one.tobytes() == both[2].tobytes()
    assert accumulate(tau[:0], a[:, :0], spec, w).shape == (4, w.n_samples)
    empty = accumulate(tau[:0], a[0, :0], spec, w)
    assert empty.shape == (w.n_samples,) and not empty.any()


def test_bad_precision_tolerance_or_shapes_are_refused():
    s, w, spec = _setup()
    tau, a = _scatterers(w, 100)
    with pytest.raises(ValueError, match="precision = 'half'"):
        accumulate(tau, a, spec, w, precision="half")
    with pytest.raises(ValueError, match="eps = 1e-09 with precision 'single'"):
        accumulate(tau, a, spec, w, eps=1e-9, precision="single")
    with pytest.raises(ValueError, match="eps = 0.0"):
        accumulate(tau, a, spec, w, eps=0.0)
    with pytest.raises(ValueError, match="amplitudes"):
        accumulate(tau, [a[0], a[1, :99]], spec, w)


def test_direct_sum_of_few_scatterers_equals_the_nufft():
    # A handful of point targets takes the direct phasor sum (exact): the NUFFT agrees
    # to its tolerance, and an explicit method gives the same as the automatic choice.
    from seaecho.radar.echo import DIRECT_TERMS

    s, w, spec = _setup()
    rng = np.random.default_rng(4)
    tau = w.t0 + rng.uniform(-T, w.duration, 3)
    a = rng.standard_normal((4, 3)) + 1j * rng.standard_normal((4, 3))
    assert tau.size * spec.size <= DIRECT_TERMS
    auto = accumulate(tau, a, spec, w)
    direct = accumulate(tau, a, spec, w, method="direct")
    nufft = accumulate(tau, a, spec, w, method="nufft")
    assert auto.tobytes() == direct.tobytes()
    assert np.abs(nufft - direct).max() <= 1e-8 * np.abs(direct).max()
    np.testing.assert_allclose(direct, accumulate_direct(tau, a, spec, w), rtol=0,
                               atol=1e-12 * np.abs(direct).max())
    with pytest.raises(ValueError, match="method"):
        accumulate(tau, a, spec, w, method="fast")


@pytest.mark.skipif(not hasattr(__import__("os"), "fork"), reason="needs fork")
def test_accumulation_in_a_forked_process_after_one_in_the_parent():
    # The worker threads of the parent do not exist in a forked child (distributed runs):
    # the child must make its own instead of waiting on them forever, and its copies of
    # the parent's finufft plans must still work.
    import multiprocessing as mp

    s, w, spec = _setup()
    rng = np.random.default_rng(5)
    k = 2 * echo.MIN_CHUNK_POINTS + 100  # two chunks: on the pool
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((4, k)) + 1j * rng.standard_normal((4, k))
    here = accumulate(tau, a, spec, w, workers=2)
    assert accumulate(tau, a, spec, w, workers=1).tobytes() == here.tobytes()  # main's plans
    with mp.get_context("fork").Pool(1) as pool:
        there = pool.apply_async(accumulate, (tau, a, spec, w), {"workers": 2}).get(timeout=60)
    assert there.tobytes() == here.tobytes()


def test_one_pool_per_worker_count_whatever_the_chunk_count(small_chunks):
    # Pulses whose scatterer counts give 2, 5 and 8 chunks run on the same pool (its
    # threads keep their plans and buffers between pulses): a pool per chunk count would
    # start new threads, each planning and faulting in its buffers again.
    s, w, spec = _setup()
    echo._pool.cache_clear()
    for k in (2 * echo.MIN_CHUNK_POINTS, 5 * echo.MIN_CHUNK_POINTS, 9 * echo.MIN_CHUNK_POINTS):
        tau, a = _scatterers(w, k)
        accumulate(tau, a, spec, w, method="nufft", workers=3)
    assert echo._pool.cache_info().currsize == 1
