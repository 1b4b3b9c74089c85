"""Start-up of ``seaecho run``: from process start to the first pulse, per stage.

Run: ``python benchmarks/bench_startup.py [SCENE.toml ...] [--repeat 2] [--cache both]
[--profile N] [--importtime]`` (default: the README's main job, Simulation 1, and
Simulation 2).

Each run is a fresh process (``python -c``) that executes ``seaecho run SCENE -o TMP.nc
--pulses 1 --no-figures -q`` (``--pulses N``; 0: the whole run) and records, from
``time.perf_counter`` and ``time.process_time`` (every thread of the process) since the
interpreter started:

- the **timeline**: the end of the command line's imports, the end of the build
  (``build_simulation`` + the simulation's set-up), the end of the dataset's static part
  (sea truth with the NRCS map, hull truth), the start of the first pulse (the
  start-up) and its end;
- the **stages** (inclusive wall and CPU time of the functions named in :data:`STAGES`,
  indented under the stage that calls them): preflight checks, build, antenna
  normalisation, sea state, tracer (BVH), NRCS map, hull truth, hull traces (the SBR
  itself, or the cache lookups), the dataset's static part.

The hull signatures are cached on disk (``seaecho.targets.cache``). ``--cache cold``
runs each start-up with an empty cache folder of its own (every hull traced),
``--cache warm`` with a folder filled by a first, unmeasured run (every trace read
back), ``both`` (default) measures the two, ``off`` runs with ``--no-cache``.

``--profile N`` prints the N most expensive functions (cumulative) of one cProfile'd
start-up per scene; ``--importtime`` the 25 slowest imports (``python -X importtime``).
The machine's load average is printed with every figure: on a shared machine wall times
are inflated, the CPU time is the steadier figure.
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
from pathlib import Path

from _smoke import add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SCENES = [ROOT / "scenes" / "paper_sim1_bistatic_64m.toml",
          ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"]

#: (label, module, attribute path, depth): functions timed in the child (inclusive).
STAGES = [
    ("preflight checks (check_run)", "seaecho.checks.preflight", "check_run", 0),
    ("build models (build_simulation)", "seaecho.build", "build_simulation", 0),
    ("antenna normalisation", "seaecho.radar.antennas", "aperture_radiated_power", 1),
    ("simulation set-up", "seaecho.simulation", "Simulation._setup", 0),
    ("sea truth (sea_truth)", "seaecho.simulation", "Simulation.sea_truth", 0),
    ("sea state (surface + wake)", "seaecho.sea", "Sea.state", 1),
    ("tracer (Mitsuba scenes, BVH)", "seaecho.tracing.tracer", "FacetTracer.__init__", 1),
    ("NRCS map (sigma_cells)", "seaecho.radar.resident", "ResidentSea.sigma_cells", 1),
    ("hull truth (HullEchoes.truth)", "seaecho.tracing.hull_echo", "HullEchoes.truth", 0),
    ("hull signatures (cache or trace)", "seaecho.tracing.hull_echo", "HullEchoes._trace", 1),
    ("SBR traces (trace_signature)", "seaecho.tracing.hull_echo", "trace_signature", 2),
    ("dataset, static part (xarray)", "seaecho.io.run", "run_dataset", 0),
]

CHILD = textwrap.dedent("""
    import functools, importlib, json, sys, time
    w0, c0 = time.perf_counter(), time.process_time()
    marks, stages = {}, {}
    def now():
        return time.perf_counter() - w0, time.process_time() - c0
    def mark(name):
        marks.setdefault(name, now())
    import seaecho.cli as cli
    parser = cli.build_parser()
    mark("imports (command line)")
    def timed(label, fn):
        @functools.wraps(fn)
        def wrapper(*a, **k):
            w, c = time.perf_counter(), time.process_time()
            try:
                return fn(*a, **k)
            finally:
                s = stages.setdefault(label, [0, 0.0, 0.0])
                s[0] += 1
                s[1] += time.perf_counter() - w
                s[2] += time.process_time() - c
        return wrapper
    for label, module, attr, _ in json.loads(sys.argv[1]):
        try:
            owner = importlib.import_module(module)
        except ImportError:
            continue
        *path, name = attr.split(".")
        for p in path:
            owner = getattr(owner, p)
        setattr(owner, name, timed(label, getattr(owner, name)))
    import seaecho.simulation as s
    from_models, static, pulse = (s.Simulation.from_models, s.Simulation.static_dataset,
                                  s.Simulation.pulse)
    def fm(*a, **k):
        out = from_models(*a, **k)
        mark("build + set-up")
        return out
    def st(self):
        out = static(self)
        mark("dataset's static part")
        return out
    def pl(self, p):
        mark("first pulse starts")
        out = pulse(self, p)
        mark("first pulse ends")
        return out
    s.Simulation.from_models, s.Simulation.static_dataset, s.Simulation.pulse = (
        classmethod(lambda cls, m: fm(m)), st, pl)
    argv = sys.argv[2:]
    if argv[0] == "--profile":
        import cProfile, pstats
        n = int(argv[1])
        prof = cProfile.Profile()
        prof.enable()
        rc = cli.main(argv[2:])
        prof.disable()
        pstats.Stats(prof, stream=sys.stderr).sort_stats("cumulative").print_stats(n)
    else:
        rc = cli.main(argv)
    mark("end")
    print(json.dumps({"marks": marks, "stages": stages}))
    sys.exit(rc)
""")


def startup(scene: Path, cache_dir: Path | None, profile: int = 0, pulses: int = 1) -> dict:
    """One ``seaecho run --pulses N`` of ``scene`` in a fresh process, with the hull
    cache in ``cache_dir`` (None: ``--no-cache``): the marks {name: (wall s, CPU s)}
    since the interpreter started, the stages {label: (calls, wall s, CPU s)}, and the
    load average before and after."""
    env = dict(os.environ)
    env.pop("SEAECHO_CACHE", None)
    if cache_dir is not None:
        env["SEAECHO_CACHE_DIR"] = str(cache_dir)
    with tempfile.TemporaryDirectory() as d:
        args = ["run", str(scene), "-o", str(Path(d) / "out.nc"), "--no-figures", "-q"]
        if pulses:
            args += ["--pulses", str(pulses)]
        if cache_dir is None:
            args.append("--no-cache")
        if profile:
            args = ["--profile", str(profile), *args]
        load = os.getloadavg()[0]
        res = subprocess.run([sys.executable, "-c", CHILD, json.dumps(STAGES), *args],
                             capture_output=True, text=True, cwd=d, env=env)
    if res.returncode != 0:
        raise RuntimeError(f"seaecho run failed:\n{res.stderr[-3000:]}")
    if profile:
        print(res.stderr)
    out = json.loads(res.stdout.strip().splitlines()[-1])
    out["load"] = (load, os.getloadavg()[0])
    return out


def import_times(scene: Path, n: int = 25) -> None:
    """The ``n`` slowest imports (cumulative) of a start-up (``python -X importtime``)."""
    with tempfile.TemporaryDirectory() as d:
        res = subprocess.run([sys.executable, "-X", "importtime", "-m", "seaecho", "run",
                              str(scene), "-o", str(Path(d) / "out.nc"), "--pulses", "1",
                              "--no-figures", "-q", "--no-cache"],
                             capture_output=True, text=True, cwd=d)
    rows = []
    for line in res.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            _, cum, name = line.split("|")
            if cum.strip().isdigit():
                rows.append((int(cum), name.rstrip()))
    print(f"\n{scene.name}: slowest imports (cumulative, -X importtime, load "
          f"{os.getloadavg()[0]:.2f})")
    for cum, name in sorted(rows, reverse=True)[:n]:
        print(f"  {cum / 1e6:6.3f} s {name}")


def report(scene: Path, label: str, runs: list[dict]) -> None:
    loads = [x for r in runs for x in r["load"]]
    print(f"\n{scene.name}, {label}: median of {len(runs)} runs, load {min(loads):.2f}-"
          f"{max(loads):.2f}")
    print(f"  {'timeline (since process start)':40s} {'wall s':>8s} {'CPU s':>8s}")
    for name in runs[0]["marks"]:
        wall = statistics.median(r["marks"][name][0] for r in runs if name in r["marks"])
        cpu = statistics.median(r["marks"][name][1] for r in runs if name in r["marks"])
        print(f"  {name:40s} {wall:8.2f} {cpu:8.2f}")
    print(f"  {'stage (inclusive)':40s} {'wall s':>8s} {'CPU s':>8s} {'calls':>6s}")
    for stage, _, _, depth in STAGES:
        got = [r["stages"][stage] for r in runs if stage in r["stages"]]
        if not got:
            continue
        name = "  " * depth + stage
        print(f"  {name:40s} {statistics.median(g[1] for g in got):8.2f} "
              f"{statistics.median(g[2] for g in got):8.2f} {got[0][0]:6d}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenes", nargs="*", type=Path, default=SCENES)
    ap.add_argument("--repeat", type=int, default=2, help="runs per scene and case (median)")
    ap.add_argument("--cache", choices=("both", "cold", "warm", "off"), default="both",
                    help="hull-signature cache: empty (cold), filled (warm), both, or off")
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="print the N top functions of a cProfile'd start-up per scene")
    ap.add_argument("--pulses", type=int, default=1, metavar="N",
                    help="pulses of the run (default 1; 0: the whole run, whose hull truth "
                    "traces every refresh pulse before the first pulse)")
    ap.add_argument("--importtime", action="store_true",
                    help="print the slowest imports of a start-up per scene")
    add_option(ap)
    args = ap.parse_args()
    if args.smoke:  # Simulation 2 on a small grid, one run, no hull cache
        args.scenes = [small_scene(SCENES[1], pulses=10**6)]
        args.repeat, args.cache, args.pulses = 1, "off", 1
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, load "
          f"{os.getloadavg()[0]:.2f}")
    cases = ["cold", "warm"] if args.cache == "both" else [args.cache]
    for scene in (s.resolve() for s in args.scenes):
        if args.importtime:
            import_times(scene)
        with tempfile.TemporaryDirectory() as warm:
            if args.profile:
                startup(scene, Path(warm), args.profile, args.pulses)  # fills the cache
            for case in cases:
                runs = []
                for _ in range(args.repeat):
                    if case == "cold":
                        with tempfile.TemporaryDirectory() as cold:
                            runs.append(startup(scene, Path(cold), pulses=args.pulses))
                    elif case == "warm":
                        if not any(Path(warm).rglob("*.npz")):
                            startup(scene, Path(warm), pulses=args.pulses)  # fill it
                        runs.append(startup(scene, Path(warm), pulses=args.pulses))
                    else:
                        runs.append(startup(scene, None, pulses=args.pulses))
                report(scene, f"hull cache {case}", runs)


if __name__ == "__main__":
    main()
