"""Start-up of ``seaecho run``: from process start to the first pulse, per stage.

Run: ``python benchmarks/bench_startup.py [SCENE.toml ...] [--repeat 2] [--profile N]``
(default: the README's main job, Simulation 1, and Simulation 2).

Each run is a fresh process (``python -c``) that executes ``seaecho run SCENE -o TMP.nc
--pulses 1 --no-figures -q`` and records, from ``time.perf_counter`` and
``time.process_time`` (every thread of the process) at the start of the interpreter:

- ``import``: importing the command line (``seaecho.cli``) and parsing;
- ``build``: ``build_simulation`` + ``Simulation.from_models`` (scene, sea model, tracer,
  hull signatures);
- ``static``: the dataset's static part (``Simulation.static_dataset``: sea truth with the
  NRCS map, hull truth, xarray);
- ``first pulse``: when the first pulse starts (the start-up), and when it ends.

``--profile N`` prints the N most expensive functions (cumulative) of one cProfile'd
start-up per scene. The machine's load average is printed with every figure: on a shared
machine wall times are inflated, the CPU time is the steadier figure.
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

ROOT = Path(__file__).resolve().parents[1]
SCENES = [ROOT / "scenes" / "paper_sim1_bistatic_64m.toml",
          ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"]

CHILD = textwrap.dedent("""
    import json, sys, time
    w0, c0 = time.perf_counter(), time.process_time()
    marks = {}
    def mark(name):
        marks.setdefault(name, (time.perf_counter() - w0, time.process_time() - c0))
    import seaecho.cli as cli
    parser = cli.build_parser()
    mark("import")
    import seaecho.simulation as s
    from_models, static, pulse = (s.Simulation.from_models, s.Simulation.static_dataset,
                                  s.Simulation.pulse)
    def fm(*a, **k):
        out = from_models(*a, **k)
        mark("build")
        return out
    def st(self):
        out = static(self)
        mark("static")
        return out
    def pl(self, p):
        mark("first pulse starts")
        out = pulse(self, p)
        mark("first pulse ends")
        return out
    s.Simulation.from_models, s.Simulation.static_dataset, s.Simulation.pulse = (
        classmethod(lambda cls, m: fm(m)), st, pl)
    argv = sys.argv[1:]
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
    print(json.dumps(marks))
    sys.exit(rc)
""")


def startup(scene: Path, profile: int = 0) -> dict:
    """One ``seaecho run --pulses 1`` of ``scene`` in a fresh process: the marks
    {stage: (wall s, CPU s)} since the interpreter started, and the load average."""
    with tempfile.TemporaryDirectory() as d:
        args = ["run", str(scene), "-o", str(Path(d) / "out.nc"), "--pulses", "1",
                "--no-figures", "-q"]
        if profile:
            args = ["--profile", str(profile), *args]
        load = os.getloadavg()[0]
        res = subprocess.run([sys.executable, "-c", CHILD, *args], capture_output=True,
                             text=True, cwd=d)
    if res.returncode != 0:
        raise RuntimeError(f"seaecho run failed:\n{res.stderr[-3000:]}")
    if profile:
        print(res.stderr)
    elif res.stderr.strip():
        print(f"  stderr: {res.stderr.strip()[-500:]}")
    marks = json.loads(res.stdout.strip().splitlines()[-1])
    return {"marks": marks, "load": load}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenes", nargs="*", type=Path, default=SCENES)
    ap.add_argument("--repeat", type=int, default=2, help="runs per scene (median)")
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="print the N top functions of a cProfile'd start-up per scene")
    args = ap.parse_args()
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores, load "
          f"{os.getloadavg()[0]:.2f}")
    for scene in args.scenes:
        if args.profile:
            startup(scene, args.profile)
        runs = [startup(scene) for _ in range(args.repeat)]
        print(f"\n{scene.name}: median of {len(runs)} runs, load "
              f"{statistics.mean(r['load'] for r in runs):.2f} "
              f"(each: {', '.join(format(r['load'], '.2f') for r in runs)})")
        print(f"  {'mark (since process start)':32s} {'wall s':>8s} {'CPU s':>8s}")
        for name in runs[0]["marks"]:
            wall = statistics.median(r["marks"][name][0] for r in runs)
            cpu = statistics.median(r["marks"][name][1] for r in runs)
            print(f"  {name:32s} {wall:8.2f} {cpu:8.2f}")


if __name__ == "__main__":
    main()
