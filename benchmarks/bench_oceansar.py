"""Side by side with OceanSAR: time per pulse of the same SAR job, run back to back.

Run::

    python benchmarks/bench_oceansar.py --oceansar /path/to/oceansar-checkout
    python benchmarks/bench_oceansar.py --seaecho-only [--match "new sea"]

The job is the size of the paper's Simulation 2: a 128 m tile on a 512 x 512 grid,
10 GHz, 45 deg incidence from 3000 m, 222 m/s, PRF 222 Hz, 75 MHz sampled at 90 MHz,
4 m antennas (OceanSAR's own geometry then gives its 175 pulses; seaecho's scene has 160).

- **OceanSAR** (P. Lopez-Dekker et al., github.com/pakodekker/oceansar): its raw
  simulator ``oceansar.radarsim.sar_raw_nompi.sar_raw``, single process, co-pol HH + VV,
  the sea re-synthesised at every pulse (choppy Elfouhaily sea), Bragg scattering
  (Romeiser 1997) refreshed every 12 pulses (``[ocean] dt``), no specular term, no
  shadowing, no range compression, one channel. It is installed from the checkout given on
  the command line into a throw-away virtual environment under /tmp with its own
  dependencies (numpy, scipy, numexpr, numba, matplotlib, netCDF4, tqdm); nothing of it is
  imported by seaecho. Its pulse loop is timed by wrapping the loop's ``tqdm`` iterator;
  the first pulses (numba compilation) are left out.
- **seaecho**: Simulation 2 (``scenes/paper_sim2_sar_128m_wind55.toml``) with the
  shadowing ray-traced and refreshed every 0.1 s, re-traced every pulse, and with a new
  sea every pulse (with and without the ship's wake, whose synthesis OceanSAR does not
  have), the new sea held for its pulse (``[scattering] sea_motion = "held"``: new
  speckle draws every pulse) or evolving (``"evolving"``, what ``"auto"`` chooses for a
  sea renewed within the run: the speckle of the pulse's time, docs/dynamics.md);
  quad-pol as the scene, and co-pol (HH, VV) like OceanSAR. Per pulse: the pulse
  and its range compression, as ``Simulation.run`` does.

Each case runs in a subprocess of its own; the rounds alternate the two simulators so
that both see the same machine load. Printed per case: median wall time, the fastest
pulse's wall time (the nearest to an idle machine that a shared one gives), median CPU
time (``time.process_time``: all threads) per pulse, and the load average. ``--seaecho-run``
also times ``seaecho run`` of Simulation 2 end to end (start-up: wall time to the first
pulse).

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006), "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

from _smoke import PULSES, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"
VENV = Path(tempfile.gettempdir()) / "seaecho-bench-oceansar-venv"

#: OceanSAR configuration of the Simulation 2 job (its sim_nompi.cfg with these values)
OCEANSAR_CFG = """
[sim]
path={path}
raw_run=True
raw_file=raw_data.nc
ocean_file=ocean.nc
ocean_reuse=False
errors_file=errors.nc
errors_reuse=False

[sar]
f0=10e9
inc_angle=45.
pol=DP
prf=222.
rg_bw=75e6
over_fs=1.2
squint=0
alt=3000.
v_ground=222.
heading=0.
ant_L_tx=4.
ant_L_rx=4.
num_ch=1
b_ati=0
b_xti=0
use_errors=False
sigma_n_tx=0.
phase_n_tx=0.
sigma_beta_tx=0.
phase_beta_tx=0.
sigma_n_rx=0.
phase_n_rx=0.
sigma_beta_rx=0.
phase_beta_rx=0.

[ocean]
Lx=128.
Ly=128.
dx=0.25
dy=0.25
opt_res=False
dt={bragg_dt}
depth=100
wind_dir=55.
wind_U=4.84
wind_fetch=500e3
swell_dir_enable=False
sigf=0.007
freq_r=.068
dir_swell_dir=45
sigs=8
Hs=0.005
swell_enable=False
swell_wl=80
swell_dir=45
swell_ampl=0.5
spec_model=elfouhaily
spread_model=elfouhaily
cutoff_wl=auto
current_mag=0
current_dir=90.
fft_max_prime=3
choppy_enable=True
frozen_ocean=False
use_buoy_data=False

[srg]
use_hmtf=False
use_lut=True
nesz=-30.
wh_tol=2.73
scat_spec_enable=False
scat_spec_mode=spa
scat_bragg_enable=True
scat_bragg_model=romeiser97
scat_bragg_spec=elfouhaily
scat_bragg_spread=elfouhaily
scat_bragg_d=0.125
"""

OCEANSAR_CHILD = """
import json, os, sys, time
import numpy as np
import oceansar.radarsim.sar_raw_nompi as sim

if not hasattr(np, "trapz"):  # OceanSAR's calibration after the loop; gone in numpy 2.4
    np.trapz = np.trapezoid

limit, skip, cfg, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], sys.argv[4]
wall, cpu, load = [], [], os.getloadavg()[0]

def timed(iterable):
    w, c = time.perf_counter(), time.process_time()
    for k, item in enumerate(iterable):
        if k >= limit:
            break
        yield item
        w1, c1 = time.perf_counter(), time.process_time()
        wall.append(w1 - w)
        cpu.append(c1 - c)
        w, c = w1, c1

sim.tqdm = timed
t0 = time.perf_counter()
sim.sar_raw(cfg, os.path.join(out, "raw.nc"), os.path.join(out, "ocean.nc"), False,
            os.path.join(out, "errors.nc"), False, plot_save=True)
print(json.dumps({"wall": wall[skip:], "cpu": cpu[skip:], "load": load,
                  "pulses": len(wall), "total_s": time.perf_counter() - t0}))
"""


def oceansar_python(checkout: Path, python: str | None) -> str:
    """The Python of a virtual environment holding OceanSAR (made under /tmp if needed)."""
    if python:
        return python
    py = VENV / "bin" / "python"
    if not py.exists():
        print(f"installing OceanSAR from {checkout} into {VENV} ...", flush=True)
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        pip = [str(py), "-m", "pip", "install", "-q"]
        subprocess.run(pip + ["numpy", "scipy", "numexpr", "numba", "matplotlib", "netCDF4",
                              "tqdm"], check=True)
        subprocess.run(pip + ["--no-deps", "-e", str(checkout)], check=True)
    return str(py)


def run_oceansar(python: str, checkout: Path, pulses: int, skip: int, bragg_pulses: int
                 ) -> dict:
    with tempfile.TemporaryDirectory() as d:
        cfg = Path(d) / "sim2.cfg"
        cfg.write_text(OCEANSAR_CFG.format(path=d, bragg_dt=bragg_pulses / 222.0))
        child = Path(d) / "child.py"
        child.write_text(OCEANSAR_CHILD)
        env = dict(os.environ, MPLBACKEND="Agg")
        res = subprocess.run([python, str(child), str(pulses + skip), str(skip), str(cfg), d],
                             capture_output=True, text=True, cwd=str(checkout), env=env)
    if res.returncode != 0:
        raise RuntimeError(f"OceanSAR failed:\n{res.stderr[-3000:]}")
    return json.loads(res.stdout.strip().splitlines()[-1])


SEAECHO_CHILD = """
import json, os, sys, time, warnings
warnings.simplefilter("ignore")
from seaecho.config import load_scene
from seaecho.simulation import Simulation

path, pulses, skip, refresh, update, wake, channels, prefetch, motion = sys.argv[1:10]
pulses, skip, update = int(pulses), int(skip), int(update)
scene = load_scene(path)
radar = {"sea_update_pulses": update}
if channels != "all":
    radar["channels"] = channels.split(",")
upd = {"tracing": scene.tracing.model_copy(update={"refresh_interval_s": float(refresh)}),
       "radar": scene.radar.model_copy(update=radar)}
if motion != "auto":
    upd["scattering"] = scene.scattering.model_copy(update={"sea_motion": motion})
if wake == "0":
    upd["ship"] = None
    upd["objects"] = []
scene = scene.model_copy(update=upd)
sim = Simulation(scene, base_dir=os.path.dirname(path))
wall, cpu, load = [], [], os.getloadavg()[0]
for p in range(pulses + skip):
    w, c = time.perf_counter(), time.process_time()
    if prefetch == "1" and p + 1 < pulses + skip and hasattr(sim, "prefetch_surface"):
        # as Simulation.pulses does (versions before it have no prefetch_surface)
        sim.surface_state(p)
        sim.prefetch_surface(p + 1)
    sim.compress(sim.pulse(p))
    wall.append(time.perf_counter() - w)
    cpu.append(time.process_time() - c)
print(json.dumps({"wall": wall[skip:], "cpu": cpu[skip:], "load": load,
                  "pulses": len(wall)}))
"""


def run_seaecho(pulses: int, skip: int, refresh: float, update: int, wake: bool,
                channels: str, prefetch: bool = True, motion: str = "auto") -> dict:
    with tempfile.TemporaryDirectory() as d:
        child = Path(d) / "child.py"
        child.write_text(SEAECHO_CHILD)
        res = subprocess.run([sys.executable, str(child), str(SIM2), str(pulses), str(skip),
                              str(refresh), str(update), "1" if wake else "0", channels,
                              "1" if prefetch else "0", motion],
                             capture_output=True, text=True)
    if res.returncode != 0:
        raise RuntimeError(f"seaecho failed:\n{res.stderr[-3000:]}")
    return json.loads(res.stdout.strip().splitlines()[-1])


def seaecho_run(pulses: int | None) -> dict:
    """``seaecho run`` of Simulation 2 in a subprocess: wall time, and start-up (wall time
    until the first pulse is written, from the progress of the pulse loop)."""
    with tempfile.TemporaryDirectory() as d:
        scene = SIM2
        if pulses is not None:
            text = SIM2.read_text()
            text = text.replace("n_pulses = 160", f"n_pulses = {pulses}")
            text = text.replace("sea_update_pulses = 160", f"sea_update_pulses = {pulses}")
            text = text.replace("sigma_map_pulse = 80", f"sigma_map_pulse = {pulses // 2}")
            scene = Path(d) / "sim2.toml"
            scene.write_text(text.replace('file = "meshes/', f'file = "{SIM2.parent}/meshes/'))
        code = textwrap.dedent(f"""
            import resource, sys, time
            t0 = time.perf_counter()
            from seaecho.cli import main
            import seaecho.simulation as s
            first = []
            pulse = s.Simulation.pulse
            def timed(self, *a, **k):  # the first pulse computed (serial run)
                out = pulse(self, *a, **k)
                if not first:
                    first.append(time.perf_counter() - t0)
                return out
            s.Simulation.pulse = timed
            rc = main(["run", {str(scene)!r}, "-o", {str(Path(d) / "out.nc")!r}])
            ru = resource.getrusage(resource.RUSAGE_SELF)
            print(first[0] if first else -1, time.perf_counter() - t0,
                  ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024)
            sys.exit(rc)
        """)
        load = os.getloadavg()[0]
        res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if res.returncode != 0:
        raise RuntimeError(f"seaecho run failed:\n{res.stderr[-3000:]}")
    first, total, cpu, rss = (float(v) for v in res.stdout.split()[-4:])
    return {"first_pulse_s": first, "total_s": total, "cpu_s": cpu, "peak_rss_mib": rss,
            "load": load}


def _line(name: str, r: list[dict]) -> str:
    walls = [v for x in r for v in x["wall"]]
    wall, fastest = statistics.median(walls), min(walls)
    cpu = statistics.median(v for x in r for v in x["cpu"])
    load = statistics.mean(x["load"] for x in r)
    return (f"  {name:58s} {1e3 * wall:8.0f} {1e3 * fastest:8.0f} {1e3 * cpu:8.0f}"
            f"   {load:5.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--oceansar", type=Path, default=None,
                    help="checkout of github.com/pakodekker/oceansar (needed unless "
                    "--seaecho-only)")
    ap.add_argument("--seaecho-only", action="store_true",
                    help="seaecho's cases only (e.g. to compare two versions of seaecho)")
    ap.add_argument("--no-prefetch", action="store_true",
                    help="seaecho's pulses without the next sea state computed ahead "
                    "(Simulation.prefetch_surface, which Simulation.pulses uses)")
    ap.add_argument("--match", default="",
                    help="only the cases whose name contains this text")
    ap.add_argument("--oceansar-python", default=None,
                    help="Python of an environment with OceanSAR installed (default: a "
                    f"virtual environment made at {VENV})")
    ap.add_argument("--pulses", type=int, default=30, help="pulses timed per case")
    ap.add_argument("--skip", type=int, default=3, help="warm-up pulses left out")
    ap.add_argument("--rounds", type=int, default=2, help="alternating rounds")
    ap.add_argument("--seaecho-run", action="store_true",
                    help="also time `seaecho run` of Simulation 2 end to end")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # seaecho's cases on a small grid, one round, and its `seaecho run`
        global SIM2
        SIM2 = small_scene(SIM2, pulses=10**6)
        args.seaecho_only, args.seaecho_run = True, True
        args.pulses, args.skip, args.rounds = 1, 0, 1
    if args.oceansar is None and not args.seaecho_only:
        ap.error("--oceansar is required unless --seaecho-only")
    py = None if args.seaecho_only else oceansar_python(args.oceansar.resolve(),
                                                          args.oceansar_python)
    pf = not args.no_prefetch
    cases = {
        "OceanSAR: new sea every pulse, Bragg every 12 pulses, HH+VV":
            lambda: run_oceansar(py, args.oceansar, args.pulses, args.skip, 12),
        "seaecho: held sea, shadowing refreshed every 0.1 s, quad-pol":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 160, True, "all", pf),
        "seaecho: held sea, shadowing refreshed every 0.1 s, HH+VV":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 160, True, "HH,VV", pf),
        "seaecho: held sea, shadowing re-traced every pulse, quad-pol":
            lambda: run_seaecho(args.pulses, args.skip, 0.0, 160, True, "all", pf),
        "seaecho: new sea every pulse, held (+ wake), quad-pol":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 1, True, "all", pf, "held"),
        "seaecho: new sea every pulse, held, no ship, HH+VV":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 1, False, "HH,VV", pf, "held"),
        "seaecho: new sea every pulse, evolving (+ wake), quad-pol":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 1, True, "all", pf,
                                "evolving"),
        "seaecho: new sea every pulse, evolving, no ship, HH+VV":
            lambda: run_seaecho(args.pulses, args.skip, 0.1, 1, False, "HH,VV", pf,
                                "evolving"),
    }
    cases = {k: f for k, f in cases.items() if args.match in k
             and not (args.seaecho_only and k.startswith("OceanSAR"))}
    results: dict[str, list[dict]] = {k: [] for k in cases}
    print(f"bench_oceansar: {os.cpu_count()} CPUs, {args.pulses} pulses per case after "
          f"{args.skip} warm-up, {args.rounds} rounds", flush=True)
    t0 = time.time()
    for r in range(args.rounds):
        for name, fn in cases.items():
            results[name].append(fn())
            print(f"  round {r + 1}: {name} done (load {os.getloadavg()[0]:.2f}, "
                  f"{time.time() - t0:.0f} s)", flush=True)
    print(f"\n  {'case (Simulation 2 size: 512 x 512 sea, 10 GHz, 45 deg)':58s} "
          f"{'wall ms':>8s} {'fastest':>8s} {'CPU ms':>8s}   load")
    for name in cases:
        print(_line(name, results[name]))
    if args.seaecho_run:
        pulses = PULSES if args.smoke else None
        r = seaecho_run(pulses)
        print(f"\n  seaecho run of Simulation 2 ({pulses or 160} pulses): {r['total_s']:.1f} s "
              "wall, "
              f"{r['cpu_s']:.1f} s CPU, first pulse after {r['first_pulse_s']:.1f} s, "
              f"peak RSS {r['peak_rss_mib']:.0f} MiB, load {r['load']:.2f}")


if __name__ == "__main__":
    main()
