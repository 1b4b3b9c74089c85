"""Benchmark of the radar stage: run as ``python benchmarks/bench_radar.py``.

1. One bistatic quad-pol pulse over the paper's Simulation 1 sea (its scene's 648 x 648
   grid, or ``--grid N``), ray traced, broken down by stage; best of ``--repeat`` runs.
2. Echo accumulation: NUFFT (eq E2) against the paper's per-facet pulse write (eq E1,
   ``accumulate_pulse_write``) on the same facets, as a ratio.
3. The SAR case: one monostatic quad-pol pulse of Simulation 2 (512 x 512 sea, ray traced,
   sea held for all pulses) with the shadowing re-traced every pulse, every
   ``--refresh`` seconds, and with a new sea every pulse; stage breakdown, best / mean.
4. Peak memory (RSS) of a streamed run of 20 and of 200 pulses (``--memory-grid``):
   bounded memory means the two peaks are about equal.

Timings on a shared machine are noisy: the load average is printed with them.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np
from _memory import peak_rss_mb
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"
#: Pulses of the streamed runs of the memory case.
MEMORY_PULSES = (20, 200)


def _best(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def bench_pulse(repeat: int, mode: str, grid: int | None = None) -> None:
    from seaecho.config import load_scene
    from seaecho.geometry.mesh import to_facets
    from seaecho.scattering.facet import facet_terms, speckle_amplitudes
    from seaecho.simulation import Simulation

    scene = load_scene(SIM1)
    update = {"tracing": scene.tracing.model_copy(update={"mode": mode}),
              "radar": scene.radar.model_copy(update={"n_pulses": 2 * repeat + 2})}
    if grid is not None:
        update["sea"] = scene.sea.model_copy(update={"nx": grid})
    scene = scene.model_copy(update=update)
    n_grid = scene.sea.nx
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(scene, base_dir=SIM1.parent)
    sim.compress(sim.pulse(0))  # JIT compilation, BVH, lazy imports: not timed
    radar = sim.radar
    model = sim.sea_model.facet_model
    names = ["platforms+pointing", "sea state (ocean+wake)", f"facets ({mode})",
             "scattering (sigma + speckle)", "radar equation (Dr.Jit kernel)",
             "accumulation (NUFFT, 4 ch)", "range compression"]
    table = {n: [] for n in names}
    whole = []
    # Each repetition is a new pulse with a new surface (sea_update_pulses = 1): the
    # BVH rebuild and the sea synthesis are paid every time, as in a run.
    for r in range(repeat):
        p = 1 + r
        clock = [time.perf_counter()]
        geo = radar.geometry(p)
        clock.append(time.perf_counter())
        st = sim.sea.state(sim.surface_time(p))
        clock.append(time.perf_counter())
        f = sim.engine.facets(geo.time, state=st)
        clock.append(time.perf_counter())
        idx = np.flatnonzero(f.visibility > 0)
        damping = to_facets(st.wake_mask).reshape(-1)
        t = facet_terms(f.n_i, f.n_s, f.normal, model, wake_damping=damping, local=f)
        amp = speckle_amplitudes(t, f.area * f.visibility, np.random.default_rng(p))
        clock.append(time.perf_counter())
        echo = radar.scatterer_echo(geo, f.centroid[idx], f.velocity[idx],
                                    amp[idx].reshape(-1, 2, 2))
        clock.append(time.perf_counter())
        raw = radar.receive(p, [echo])
        clock.append(time.perf_counter())
        sim.compress(raw)
        clock.append(time.perf_counter())
        for n, a, b in zip(names, clock[:-1], clock[1:], strict=True):
            table[n].append(b - a)
        sim._state_cache = None  # a cold pulse end to end, on another new surface
        t0 = time.perf_counter()
        sim.pulse(p + repeat)
        whole.append(time.perf_counter() - t0)
    numpy_t, _ = _best(lambda: radar.scatterer_echo_numpy(geo, f.centroid[idx],
                                                          f.velocity[idx],
                                                          amp[idx].reshape(-1, 2, 2)), 1)
    print(f"\n[1] one bistatic quad-pol pulse, {n_grid} x {n_grid} sea ({idx.size} of "
          f"{f.n_facets} "
          f"facets visible), {mode}, {repeat} new pulses, best / mean; "
          f"load {os.getloadavg()[0]:.2f}")
    for n in names:
        v = np.array(table[n])
        print(f"    {n:34s} {1e3 * v.min():8.1f} / {1e3 * v.mean():8.1f} ms")
    radar_stage = np.array(table[names[4]]) + np.array(table[names[5]]) + np.array(
        table[names[6]])
    print(f"    {'radar stage (kernel+NUFFT+RC)':34s} {1e3 * radar_stage.min():8.1f} / "
          f"{1e3 * radar_stage.mean():8.1f} ms")
    w = np.array(whole)
    print(f"    {'Simulation.pulse (end to end)':34s} {1e3 * w.min():8.1f} / "
          f"{1e3 * w.mean():8.1f} ms")
    print(f"    (numpy reference of the radar-equation kernel: {1e3 * numpy_t:.1f} ms)")
    bench_accumulation(radar, echo, repeat)


def bench_accumulation(radar, echo, repeat: int) -> None:
    from seaecho.radar.echo import accumulate, accumulate_pulse_write

    w = radar.window
    keep = w.keep(echo.tau, radar.waveform.n_samples)
    tau, amps = echo.tau[keep], echo.amplitudes[:, keep]
    spec = radar.waveform.spectrum(radar.n_fft)
    t_nufft, r1 = _best(lambda: accumulate(tau, amps, spec, w), repeat)
    bw, dur = radar.waveform.bandwidth, radar.waveform.duration

    def env(t):
        return np.exp(1j * np.pi * bw / dur * (t - 0.5 * dur) ** 2)

    t_write, r2 = _best(lambda: accumulate_pulse_write(tau, amps, env, dur, w), 1)
    print(f"\n[2] accumulation of {tau.size} facets x {amps.shape[0]} channels into "
          f"{w.n_samples} samples (pulse {radar.waveform.n_samples} samples); "
          f"load {os.getloadavg()[0]:.2f}")
    print(f"    NUFFT (finufft type 1, eq E2)        {1e3 * t_nufft:8.1f} ms")
    print(f"    per-facet pulse write (paper, E1)    {1e3 * t_write:8.1f} ms")
    print(f"    ratio write / NUFFT                  {t_write / t_nufft:8.1f}")
    rel = np.linalg.norm(r1 - r2) / np.linalg.norm(r2)
    print(f"    relative difference (band-limited vs analytic pulse edges): {rel:.2e}")


def bench_sar(repeat: int, refresh: float, update: int, label: str) -> None:
    """Per-pulse time of Simulation 2 with a refresh interval and a sea-update block."""
    from seaecho.config import load_scene
    from seaecho.scattering.facet import speckled_facet_amplitudes
    from seaecho.simulation import Simulation

    scene = load_scene(SIM2)
    # the held speckle drawn anew with each sea (the stages below time its host draws; an
    # evolving sea, which "auto" gives a new sea every pulse, has no such draws: its
    # pulses are timed by profile_pulse.py --motion evolving)
    scene = scene.model_copy(update={
        "tracing": scene.tracing.model_copy(update={"refresh_interval_s": refresh}),
        "radar": scene.radar.model_copy(update={"sea_update_pulses": update}),
        "scattering": scene.scattering.model_copy(update={"sea_motion": "held"})})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(scene, base_dir=SIM2.parent)
        first = 40
        for p in (first, first + 1):  # JIT compilation, BVH, lazy imports: not timed
            sim.compress(sim.pulse(p))
        radar, model = sim.radar, sim.sea_model.facet_model
        names = ["platforms+pointing", "sea state (ocean+wake)", "facets (raytraced)",
                 "speckle draws + wake (per sea)", "scattering P1-P4 (fused Dr.Jit)",
                 "radar equation (Dr.Jit kernel)", "accumulation (NUFFT, 4 ch)",
                 "range compression"]
        table = {n: [] for n in names}
        whole = []
        for r in range(repeat):
            p = first + 2 + 2 * r
            clock = [time.perf_counter()]
            geo = radar.geometry(p)
            clock.append(time.perf_counter())
            st = sim.surface_state(p)
            clock.append(time.perf_counter())
            f = sim.engine.facets(geo.time, state=st)
            clock.append(time.perf_counter())
            held = sim._block_quantities(p, st, f.visibility.size)
            clock.append(time.perf_counter())
            # as Simulation.sea_echo: the block's draws on the host, breaking zones
            amp = speckled_facet_amplitudes(
                f.n_i, f.n_s, f.normal, f.area * f.visibility, model,
                draws=sim._host_draws(held), wake_damping=held["damping"],
                breaking_fraction=held["breaking"], local=f)
            clock.append(time.perf_counter())
            vis = f.visibility > 0
            echo = radar.scatterer_echo(geo, f.centroid[vis], f.velocity[vis],
                                        amp[vis].reshape(-1, 2, 2))
            clock.append(time.perf_counter())
            raw = radar.receive(p, [echo])
            clock.append(time.perf_counter())
            sim.compress(raw)
            clock.append(time.perf_counter())
            for n, a, b in zip(names, clock[:-1], clock[1:], strict=True):
                table[n].append(b - a)
            t0 = time.perf_counter()
            sim.compress(sim.pulse(p + 1))  # end to end, as in a run
            whole.append(time.perf_counter() - t0)
    print(f"\n[3] Simulation 2 (SAR, monostatic quad-pol, 512 x 512, ray traced), {label}: "
          f"refresh_interval_s = {refresh:g}, sea_update_pulses = {update}; {repeat} pulses, "
          f"best / mean; load {os.getloadavg()[0]:.2f}")
    for n in names:
        v = np.array(table[n])
        print(f"    {n:34s} {1e3 * v.min():8.1f} / {1e3 * v.mean():8.1f} ms")
    w = np.array(whole)
    print(f"    {'pulse + compression (end to end)':34s} {1e3 * w.min():8.1f} / "
          f"{1e3 * w.mean():8.1f} ms")


MEMORY_SCENE = """
name = "bench-memory"
[sea]
spectrum = "pierson-moskowitz"
wind_speed_m_s = 4.53
size_x_m = {size}
nx = {n}
[run]
seed = 1
[tracing]
mode = "analytic"
[radar]
carrier_frequency_hz = 10.0e9
sampling_rate_hz = 180.0e6
prf_hz = 1000.0
n_pulses = {pulses}
sea_update_pulses = 1
[radar.waveform]
kind = "lfm"
bandwidth_hz = 150.0e6
duration_s = 1.0e-6
[transmitter]
position_m = [-93.41, 0.0, 256.65]
[transmitter.antenna]
pattern = "rectangular"
width_m = 0.18
height_m = 0.14
look_at_m = [0.0, 0.0, 0.0]
[receiver]
position_m = [-50.75, 0.0, 87.91]
[receiver.antenna]
pattern = "rectangular"
width_m = 0.18
height_m = 0.14
look_at_m = [0.0, 0.0, 0.0]
"""


def _child_run(scene_path: str, out: str) -> None:
    import warnings

    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    warnings.simplefilter("ignore")
    t = time.perf_counter()
    Simulation(load_scene(scene_path)).run(out, progress=False)
    peak_mb = peak_rss_mb()
    print(f"{peak_mb:.1f} {time.perf_counter() - t:.1f}")


def bench_memory(grid: int) -> None:
    print(f"\n[4] peak RSS of a streamed run, {grid} x {grid} sea (analytic facets), "
          f"quad-pol; load {os.getloadavg()[0]:.2f}")
    size = 64.0 * grid / 512
    with tempfile.TemporaryDirectory() as d:
        for pulses in MEMORY_PULSES:
            scene = Path(d) / f"m{pulses}.toml"
            scene.write_text(MEMORY_SCENE.format(size=size, n=grid, pulses=pulses))
            out = Path(d) / f"m{pulses}.nc"
            res = subprocess.run([sys.executable, __file__, "--child", str(scene), str(out)],
                                 capture_output=True, text=True, check=True)
            peak, secs = res.stdout.split()
            mb = out.stat().st_size / 2**20
            print(f"    {pulses:4d} pulses: peak RSS {peak:>7s} MB, file {mb:7.1f} MB, "
                  f"{secs} s")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--mode", default="raytraced", choices=["raytraced", "analytic"])
    ap.add_argument("--grid", type=int, default=None,
                    help="grid points per side of the Simulation 1 case (default: the "
                    "scene's, 648; 512 compares with earlier measurements)")
    ap.add_argument("--memory-grid", type=int, default=128)
    ap.add_argument("--refresh", type=float, default=0.1,
                    help="shadowing refresh interval of the SAR case [s]")
    ap.add_argument("--skip-pulse", action="store_true")
    ap.add_argument("--skip-sar", action="store_true")
    ap.add_argument("--skip-memory", action="store_true")
    ap.add_argument("--child", nargs=2, help=argparse.SUPPRESS)
    add_option(ap)
    args = ap.parse_args()
    if args.child:
        _child_run(*args.child)
        return
    if args.smoke:  # Simulation 2 on a small grid (its pulses kept: the SAR case
        global SIM1, SIM2, MEMORY_PULSES  # times pulses 40 on), one round
        SIM1 = small_scene(SIM1, grid=GRID, pulses=10**6)
        SIM2 = small_scene(SIM2, grid=GRID, pulses=10**6)
        MEMORY_PULSES = (2,)
        args.repeat, args.grid, args.memory_grid = 1, GRID, GRID
    print(f"bench_radar: {os.cpu_count()} CPUs")
    if not args.skip_pulse:
        bench_pulse(args.repeat, args.mode, args.grid)
    if not args.skip_sar:
        bench_sar(args.repeat, 0.0, 160, "held sea, shadowing re-traced every pulse")
        bench_sar(args.repeat, args.refresh, 160, "held sea, shadowing refreshed")
        bench_sar(args.repeat, args.refresh, 1, "new sea every pulse, held speckle")
    if not args.skip_memory:
        bench_memory(args.memory_grid)


if __name__ == "__main__":
    main()
