"""Benchmark of the echo accumulation (eq E2): run as ``python benchmarks/bench_accumulate.py``.

Per-pulse time of ``seaecho.radar.echo.accumulate`` (NUFFT + inverse FFT) for K scatterers
(``--points``, default 1e5, 5e5, 1e6), C channels (``--channels``, default 4, quad-pol)
and a period of N modes (``--modes``, default 512 and 2048), against the method it
replaced ("before": the points folded with ``np.mod`` on the calling thread, then one
``finufft.nufft1d1`` per channel, each making and freeing its plan, the channels on worker
threads). Each line gives the wall time and the CPU time (``time.process_time``: every
thread of the process) per pulse, the median over ``--repeat`` runs (the minimum in
brackets), with a new set of delays at every run as in a pulse sequence; the load
average is printed with them (timings on a shared machine are indicative). "1 thread" is
the new method with ``workers=1`` (its CPU time is the work). The relative l2 difference
of each result from the exact direct sum of eq (E2) is printed beside it (on a 20 000
point subset of the scatterers for speed).

``--sim2`` adds the sea echo of one pulse of Simulation 2 (its 520 840 facets, 210 modes;
the error against the exact direct sum of eq E2) and the time of finufft's options on it:
a plan per call or kept, ``spread_sort``, ``upsampfac``, ``spread_kerevalmeth``, one
batched plan (``n_trans``), the tolerance, float32.

Delays are uniform over the receive window (the echo of a sea that fills the beam), the
amplitudes circular Gaussian (speckle); the "VH = -HV" lines give the third channel the
negative of the second to rounding, as monostatic reciprocity does in the FSA bases
(the accumulation then transforms three channels).
"""

from __future__ import annotations

import argparse
import os
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from _smoke import add_option

from seaecho.radar.echo import GUARD, ReceiveWindow, accumulate, accumulate_direct

FS = 90e6  # [Hz]
PULSE = 32  # pulse samples


def _before(tau, rows, spec, window, pool, eps=1e-9):
    """The accumulation before this change (kept here as the benchmark's reference)."""
    import finufft

    n = spec.size
    x = 2.0 * np.pi * ((tau - window.t0) * window.sampling_rate / n)
    x = np.mod(x + np.pi, 2.0 * np.pi) - np.pi

    def run(a):
        return finufft.nufft1d1(x, a, n_modes=n, eps=eps, isign=-1, modeord=1, nthreads=1)

    phasors = np.stack(list(pool.map(run, rows)))
    return np.fft.ifft(phasors * spec, axis=-1)[:, :window.n_samples]


def _time(fn, make, repeat):
    """Median and minimum (wall, CPU) [s] of fn(*make(i)) over repeat runs, and the last
    result."""
    walls, cpus, out = [], [], None
    for i in range(repeat + 1):
        args = make(i)
        w0, c0 = time.perf_counter(), time.process_time()
        out = fn(*args)
        w, c = time.perf_counter() - w0, time.process_time() - c0
        if i:  # the first run makes plans and threads: not timed
            walls.append(w)
            cpus.append(c)
    return (np.median(walls), np.min(walls), np.median(cpus), np.min(cpus)), out


def bench_case(k: int, n: int, c: int, repeat: int, pool, rng) -> None:
    """Print the lines of K points, N modes, C channels."""
    w = ReceiveWindow(t0=20e-6, n_samples=n - PULSE - 2 * GUARD, sampling_rate=FS)
    spec = np.fft.fft(np.exp(1j * np.pi * np.linspace(-1, 1, PULSE) ** 2 * 8), n)
    lo, hi = w.bounds(PULSE)
    taus = [rng.uniform(lo, hi, k) for _ in range(3)]
    rows = [rng.standard_normal(k) + 1j * rng.standard_normal(k) for _ in range(c)]
    mirrored = list(rows)
    if c == 4:  # monostatic reciprocity: VH = -HV to rounding (the fused kernel's output)
        mirrored[2] = -rows[1] * (1.0 + 1e-15 * rng.standard_normal(k))
    sub = slice(0, 20000)
    ref = accumulate_direct(taus[-1][sub], np.stack([r[sub] for r in rows]), spec, w)

    def make(i):
        return taus[i % 3], rows

    def make_mirrored(i):
        return taus[i % 3], mirrored

    cases = [
        ("before (per channel)", lambda t, r: _before(t, r, spec, w, pool)),
        ("new, double", lambda t, r: accumulate(t, r, spec, w)),
        ("new, double, 1 thread", lambda t, r: accumulate(t, r, spec, w, workers=1)),
        ("new, single (float32)", lambda t, r: accumulate(t, r, spec, w, precision="single")),
        ("new, double, VH = -HV", lambda t, r: accumulate(t, r, spec, w)),
        ("new, single, VH = -HV", lambda t, r: accumulate(t, r, spec, w, precision="single")),
    ]
    if c != 4:
        cases = cases[:4]
    ref_m = accumulate_direct(taus[-1][sub], np.stack([r[sub] for r in mirrored]), spec, w)
    base = None
    for name, fn in cases:
        m = "VH" in name
        (wm, wmin, cm, cmin), _ = _time(fn, make_mirrored if m else make, repeat)
        # the same method on the subset, against the direct sum
        err = np.linalg.norm(fn(taus[-1][sub], [r[sub] for r in (mirrored if m else rows)])
                             - (ref_m if m else ref))
        base = base or wm
        print(f"  {k:8d} {n:5d}  {name:22s} {1e3 * wm:7.1f} ({1e3 * wmin:5.1f}) "
              f"{1e3 * cm:7.1f} ({1e3 * cmin:5.1f})  {err / np.linalg.norm(ref):11.1e}"
              + (f"   x{base / wm:.2f} wall" if name != cases[0][0] else ""))


def sim2_pulse(path=None, pulse: int = 40):
    """(tau, per-channel amplitudes, pulse spectrum, window) of the sea echo (the largest
    scatterer set) of one pulse of a scene, Simulation 2 by default (the fused kernel's
    output, as ``RadarSystem.receive`` gets it)."""
    import warnings
    from pathlib import Path

    import seaecho.radar.system as system
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    if path is None:
        path = Path(__file__).resolve().parents[1] / "scenes" / \
            "paper_sim2_sar_128m_wind55.toml"
    got = []
    inner = system.accumulate

    def grab(tau, amplitudes, spec, window, *args, **kwargs):
        got.append((np.array(tau), [np.array(a) for a in amplitudes], np.asarray(spec),
                    window))
        return inner(tau, amplitudes, spec, window, *args, **kwargs)

    system.accumulate = grab
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            Simulation(load_scene(path), base_dir=path.parent).pulse(pulse)
    finally:
        system.accumulate = inner
    return max(got, key=lambda g: g[0].size)  # the sea (the other set: the hull)


def bench_sim2(repeat: int, pool) -> None:
    """The accumulation of a Simulation 2 pulse: methods, and finufft's options."""
    import finufft

    tau, rows, spec, w = sim2_pulse()
    n, k = spec.size, tau.size
    x = 2.0 * np.pi * ((tau - w.t0) * w.sampling_rate / n)
    x = np.mod(x + np.pi, 2.0 * np.pi) - np.pi
    exact = np.zeros((len(rows), n), dtype=complex)  # eq (E2) summed directly, in blocks
    modes = np.fft.fftfreq(n, 1.0 / n)
    for i in range(0, k, 20000):
        exact += np.stack([r[i:i + 20000] for r in rows]) @ np.exp(
            -1j * np.outer(x[i:i + 20000], modes))
    ref = np.fft.ifft(exact * spec, axis=-1)[:, :w.n_samples]
    mirrored = np.abs(rows[2] + rows[1]).max() / np.abs(rows[1]).max()
    print(f"\nSimulation 2 pulse: {k} facets, {len(rows)} channels, N = {n} modes "
          f"(max |VH + HV| / max |HV| = {mirrored:.1e}); load {os.getloadavg()[0]:.2f}")
    cases = [
        ("before (per channel)", lambda: _before(tau, rows, spec, w, pool)),
        ("new, double", lambda: accumulate(tau, rows, spec, w)),
        ("new, double, 1 thread", lambda: accumulate(tau, rows, spec, w, workers=1)),
        ("new, single (float32)", lambda: accumulate(tau, rows, spec, w, precision="single")),
    ]
    for name, fn in cases:
        (wm, wmin, cm, cmin), out = _time(fn, lambda i: (), repeat)
        err = np.linalg.norm(out - ref, axis=1) / np.linalg.norm(ref, axis=1)
        print(f"  {name:22s} wall {1e3 * wm:6.1f} ({1e3 * wmin:5.1f}) CPU {1e3 * cm:6.1f} "
              f"({1e3 * cmin:5.1f}) ms; rel. l2 err per channel "
              + " ".join(f"{e:.1e}" for e in err))

    print(f"  finufft options, one thread, the {len(rows)} channels (CPU ms, median; "
          f"rel. l2 err of the phasor sums):")

    def plan(**kw):
        opts = {"eps": 1e-9, "isign": -1, "modeord": 1, "nthreads": 1, **kw}
        return finufft.Plan(1, (n,), **opts)

    x32 = x.astype(np.float32)
    rows32 = [r.astype(np.complex64) for r in rows]
    stacked = np.stack(rows)
    fresh = ("nufft1d1 per call (plan made and freed)",
             lambda: [finufft.nufft1d1(x, r, n_modes=n, eps=1e-9, isign=-1, modeord=1,
                                       nthreads=1) for r in rows])
    variants = [fresh, ("np.mod fold of the points", lambda: np.mod(x + np.pi, 2 * np.pi))]
    for label, kw, data, pts in [
            ("kept plan, spread_sort auto", {}, rows, x),
            ("kept plan, spread_sort 0", {"spread_sort": 0}, rows, x),
            ("kept plan, spread_sort 1", {"spread_sort": 1}, rows, x),
            ("kept plan, upsampfac 1.25", {"upsampfac": 1.25}, rows, x),
            ("kept plan, spread_kerevalmeth 0", {"spread_kerevalmeth": 0}, rows, x),
            ("n_trans = C (stacked channels)", {"n_trans": len(rows)}, [stacked], x),
            *[(f"kept plan, eps {e:g}", {"eps": e}, rows, x)
              for e in (1e-8, 1e-7, 1e-6, 1e-5)],
            ("float32, eps 1e-5", {"eps": 1e-5, "dtype": "complex64"}, rows32, x32)]:
        p = plan(**kw)
        p.setpts(pts)
        variants.append((label, lambda p=p, data=data: [p.execute(d) for d in data]))
    for label, fn in variants:
        (_, _, cm, _), out = _time(fn, lambda i: (), repeat)
        err = ""
        if label != "np.mod fold of the points":
            got = np.concatenate([np.atleast_2d(o) for o in out])
            err = f"{np.linalg.norm(got - exact) / np.linalg.norm(exact):9.1e}"
        print(f"    {label:42s} {1e3 * cm:7.1f} {err}")
    print(f"  load at the end {os.getloadavg()[0]:.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=float, nargs="+", default=[1e5, 5e5, 1e6])
    ap.add_argument("--modes", type=int, nargs="+", default=[512, 2048])
    ap.add_argument("--channels", type=int, default=4)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--sim2", action="store_true",
                    help="also a pulse of Simulation 2 (its facets, 210 modes) and finufft's "
                         "options on it")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:
        args.points, args.modes, args.repeat = [1e4], [64], 1

    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    pool = ThreadPoolExecutor(max(1, min(cpus, args.channels)))
    rng = np.random.default_rng(0)
    c = args.channels
    print(f"bench_accumulate: {c} channels, {cpus} CPUs, median (min) of {args.repeat} "
          f"pulses, load {os.getloadavg()[0]:.2f}")
    print(f"  {'K':>8s} {'N':>5s}  {'method':22s} {'wall [ms]':>15s} {'CPU [ms]':>15s}"
          f"  {'rel. l2 err':>11s}")
    for k in (int(p) for p in args.points):
        for n in args.modes:
            bench_case(k, n, c, args.repeat, pool, rng)
    print(f"  load at the end {os.getloadavg()[0]:.2f}")
    if args.sim2:
        bench_sim2(args.repeat, pool)


if __name__ == "__main__":
    main()
