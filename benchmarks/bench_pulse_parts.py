"""Parts of a Simulation 2 pulse timed alone: the numbers of docs/performance.md, section 1,
"Per-pulse overheads, and finufft built for the CPU".

Run: ``python benchmarks/bench_pulse_parts.py [--repeat 20] [--no-ops]``.

On one pulse's own arrays (held sea, quad-pol, with the ship; pulse 40): CPU ms (all
threads, ``time.process_time``) and wall ms per call of

- the finite-output guard on the sea's four channels, stacked (as before) and channel by
  channel (``seaecho.checks.guards``);
- the receive window's all-kept test, by the mask and by the extreme delays
  (``ReceiveWindow.keep(...).all()``, ``ReceiveWindow.keeps_all``);
- the ocean's five float32 inverse FFTs at the grid's size, one batched ``irfft2`` (what
  ``SeaSurface.fields`` does) and one per field (measured, not used: slower in a process
  that runs the simulation, faster in a bare one);
- the travelling waves of one time (eq 12' of ``seaecho.ocean.surface``), which an
  evolving sea's state and kinematics of that time now share;
- the vertex mean of the wake mask per facet (``simulation.wake_damping``), which a sea
  without a ship no longer computes;
- the accumulation of the sea's echo (``radar.echo.accumulate``, four channels, one worker
  thread), with whichever finufft is installed (its path is printed);

and, unless ``--no-ops``, the operations of the pulse's largest Dr.Jit kernel by LLVM IR
instruction (Dr.Jit's trace log of one more pulse): what the fused kernel spends its time
on. The load average is printed.
"""

from __future__ import annotations

import argparse
import collections
import os
import re
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np
import scipy.fft
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def timed(fn, repeat: int) -> tuple[float, float]:
    """(wall, CPU) ms per call, after one call not counted."""
    fn()
    w, c = time.perf_counter(), time.process_time()
    for _ in range(repeat):
        fn()
    return (1e3 * (time.perf_counter() - w) / repeat, 1e3 * (time.process_time() - c) / repeat)


def kernel_ops(sim, pulse: int) -> tuple[int, collections.Counter]:
    """Facets and LLVM IR instructions of the largest kernel of ``pulse`` (Dr.Jit's trace
    log, read from the process's standard error)."""
    import drjit as dr

    with tempfile.TemporaryFile(mode="w+") as log:
        sys.stdout.flush()
        sys.stderr.flush()
        saved = [os.dup(1), os.dup(2)]
        os.dup2(log.fileno(), 1)
        os.dup2(log.fileno(), 2)
        try:
            dr.set_log_level(dr.LogLevel.Trace)
            sim.pulse(pulse)
        finally:
            dr.set_log_level(dr.LogLevel.Warn)
            sys.stdout.flush()
            sys.stderr.flush()
            for fd, old in zip((1, 2), saved, strict=True):
                os.dup2(old, fd)
                os.close(old)
        log.seek(0)
        text = log.read()
    bodies = re.findall(r"define (?:internal )?(?:fastcc )?void @drjit_\w+\((.*?)\n}\n", text,
                        re.S)
    count: collections.Counter = collections.Counter()
    if not bodies:
        return 0, count
    for line in max(bodies, key=len).splitlines():
        m = re.search(r"= (fmul|fadd|fsub|fdiv|fneg) (?:\w+ )*<(\d+) x (float|double)>", line)
        if m:
            count[f"{m.group(1)} {m.group(3)}"] += 1
        m = re.search(r"call [^@]*@llvm\.(fma|sqrt|masked\.gather)\.v\d+(f32|f64)", line)
        if m:
            count[f"{m.group(1)} {'float' if m.group(2) == 'f32' else 'double'}"] += 1
    sizes = [int(n) for n in re.findall(r"launching \w+ \(n=(\d+),", text)]
    return max(sizes, default=0), count


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=20, help="calls timed per part")
    ap.add_argument("--no-ops", action="store_true", help="skip the kernel's operations")
    add_option(ap)
    args = ap.parse_args()
    path = SIM2
    if args.smoke:
        path = small_scene(SIM2, grid=GRID, pulses=10**6)
        args.repeat = 1
    warnings.simplefilter("ignore")
    import finufft

    import seaecho.radar.system as system
    from seaecho.checks.guards import _finite
    from seaecho.config import load_scene
    from seaecho.radar.echo import accumulate
    from seaecho.simulation import Simulation, wake_damping

    sim = Simulation(load_scene(path), base_dir=path.parent)
    seen: dict = {}
    real = system.accumulate

    def keep_sea(tau, amplitudes, *a, **k):  # the pulse's largest scatterer set
        if np.size(tau) > seen.get("n", -1):
            seen.update(n=np.size(tau), tau=np.array(tau),
                        amp=[np.array(x) for x in amplitudes], spec=a[0], window=a[1])
        return real(tau, amplitudes, *a, **k)

    system.accumulate = keep_sea
    pulse = 40 if sim.radar.n_pulses > 41 else 0
    sim.pulse(pulse)
    system.accumulate = real
    tau, amp, spec, window = seen["tau"], seen["amp"], seen["spec"], seen["window"]
    n_p = sim.radar.waveform.n_samples
    state = sim.surface_state(pulse)
    surface = sim.sea.surface
    half = surface._a.shape
    five = np.ones((5, *half), dtype=np.complex64)
    load = os.getloadavg()[0]
    rows = [
        ("guard, the channels stacked (before)", lambda: _finite(np.asarray(amp))),
        ("guard, channel by channel", lambda: _finite(amp)),
        ("window: mask of every delay (before)", lambda: window.keep(tau, n_p).all()),
        ("window: the least and greatest delay", lambda: window.keeps_all(tau, n_p)),
        ("ocean: 5 float32 irfft2, batched (used)",
         lambda: scipy.fft.irfft2(five, s=surface.shape, axes=(-2, -1), norm="forward",
                                  workers=-1)),
        ("ocean: 5 float32 irfft2, one per field (not used)",
         lambda: [scipy.fft.irfft2(f, s=surface.shape, norm="forward", workers=-1)
                  for f in five]),
        ("ocean: travelling waves of one time (kept, evolving)",
         lambda: surface._travelling_at(0.3)),
        ("wake damping per facet (no ship: not computed)", lambda: wake_damping(state)),
        ("accumulation, 4 channels, 1 worker",
         lambda: accumulate(tau, amp, spec, window, workers=1)),
    ]
    resident = getattr(sim, "_resident", None)
    if resident is not None:
        xp, n = resident.xp, resident.n_facets(state)

        def uncompacted():  # timing only: hidden facets and echoes outside the window kept
            count = xp.count
            xp.count = lambda mask: n
            try:
                sim.sea_echo(pulse)
            finally:
                xp.count = count

        rows += [("fused sea echo (kernel + compaction)", lambda: sim.sea_echo(pulse)),
                 ("fused sea echo, compaction skipped (timing only)", uncompacted)]
    print(f"bench_pulse_parts: {path.stem}, {surface.shape[0]}^2 sea, {tau.size} facets "
          f"in the window, {len(amp)} channels; {os.cpu_count()} CPUs, load {load:.2f}; "
          f"finufft {finufft.__version__} from {Path(finufft.__file__).parent}")
    print(f"  {'part':52s} {'wall [ms]':>10s} {'CPU [ms]':>10s}")
    for name, fn in rows:
        w, c = timed(fn, args.repeat)
        print(f"  {name:52s} {w:10.2f} {c:10.2f}")
    if not args.no_ops:
        n, ops = kernel_ops(sim, pulse + 1)
        total = sum(ops.values())
        print(f"  largest kernel: {n} lanes; {total} floating-point vector instructions: "
              + ", ".join(f"{v} {k}" for k, v in sorted(ops.items(), key=lambda kv: -kv[1])))
    print(f"  load {load:.2f} -> {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
