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
    # Eq (E2) by finufft type 1 against the explicit O(K N) sum: 1e-6 relative (docs/radar.md)
    s, w, spec = _setup()
    rng = np.random.default_rng(0)
    k = 2000
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((4, k)) + 1j * rng.standard_normal((4, k))
    fast = accumulate(tau, a, spec, w)
    ref = accumulate_direct(tau, a, spec, w)
    assert np.abs(fast - ref).max() <= 1e-6 * np.abs(ref).max()


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


def test_channels_on_worker_threads_give_the_same_bytes():
    # Each channel is a single-threaded finufft transform: spreading them over 1, 2 or 3
    # threads, or passing them as a list of per-channel arrays, cannot change a bit (a
    # result that depended on the machine's core count would not be reproducible).
    s, w, spec = _setup()
    rng = np.random.default_rng(3)
    k = 30000  # above DIRECT_TERMS: the NUFFT
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((4, k)) + 1j * rng.standard_normal((4, k))
    one = accumulate(tau, a, spec, w, workers=1)
    for other in (accumulate(tau, a, spec, w, workers=2),
                  accumulate(tau, a, spec, w, workers=3),
                  accumulate(tau, list(a), spec, w)):
        assert other.tobytes() == one.tobytes()


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
    # the child must make its own instead of waiting on them forever.
    import multiprocessing as mp

    s, w, spec = _setup()
    rng = np.random.default_rng(5)
    k = 30000
    tau = w.t0 + rng.uniform(-T, w.duration, k)
    a = rng.standard_normal((4, k)) + 1j * rng.standard_normal((4, k))
    here = accumulate(tau, a, spec, w, workers=2)
    with mp.get_context("fork").Pool(1) as pool:
        there = pool.apply_async(accumulate, (tau, a, spec, w), {"workers": 2}).get(timeout=60)
    assert there.tobytes() == here.tobytes()
