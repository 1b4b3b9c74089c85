"""Measured peak memory and run time of `seaecho run` against ``seaecho.checks.resources``.

Run as ``python benchmarks/bench_resources.py`` (about 5 minutes; ``--quick`` for the
small cases only, ``--cases NAME ...`` for some). Each case is a variant of the
calibration scene that grows one term of the memory model (eq M1 of
``seaecho.checks.resources``): the sea grid (analytic and ray-traced facets), the receive window
(samples per pulse), the pulses, the figures. Each run is a child process (the console
script); its peak resident memory is ``ru_maxrss`` of the children, read by a wrapper
process that does nothing else. Printed per case: the sizes, the estimate, the measured
peak, their ratio (>= 1 means the estimate holds), the estimated and measured wall time,
and the load average (timings on a shared machine are indicative only).
"""

from __future__ import annotations

import argparse
import copy
import json
import os
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

from _smoke import add_option

ROOT = Path(__file__).resolve().parents[1]
CAL = ROOT / "scenes" / "calibration_point_target.toml"
SEAECHO = Path(sys.executable).with_name("seaecho")

#: Child wrapper: runs the command, prints [status, peak RSS of children kB, wall s].
WRAPPER = ("import json, resource, subprocess, sys, time\n"
           "t = time.perf_counter()\n"
           "r = subprocess.run(sys.argv[1:], capture_output=True, text=True)\n"
           "print(json.dumps([r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN)"
           ".ru_maxrss, time.perf_counter() - t, r.stderr[-500:]]))\n")


def _base() -> dict:
    return tomllib.loads(CAL.read_text())


def targets(n_pulses=2, bandwidth=100e6, fs=200e6) -> dict:
    s = _base()
    s["radar"].update(n_pulses=n_pulses, sampling_rate_hz=fs)
    s["radar"]["waveform"]["bandwidth_hz"] = bandwidth
    return s


def sea(nx: int, mode: str, n_pulses: int = 2) -> dict:
    s = _base()
    s["sea"].update(nx=nx, size_x_m=0.125 * nx)
    s["radar"].update(sea_clutter=True, n_pulses=n_pulses)
    s["tracing"] = {"mode": mode}
    return s


def cases(quick: bool) -> dict[str, tuple[dict, bool]]:
    """name -> (scene dict, figures)."""
    out = {
        "targets_2p": (targets(), False),
        "targets_2p_fig": (targets(), True),
        "sea_analytic_64": (sea(64, "analytic"), False),
        "sea_raytraced_64": (sea(64, "raytraced"), False),
        "sea_analytic_256": (sea(256, "analytic"), False),
        "window_400k_2p": (targets(bandwidth=1e3, fs=1e8), False),
        "pulses_1000": (targets(n_pulses=1000), False),
    }
    if not quick:
        out.update({
            "sea_raytraced_256": (sea(256, "raytraced"), False),
            "sea_analytic_512": (sea(512, "analytic"), False),
            "sea_raytraced_512": (sea(512, "raytraced"), False),
            "sea_analytic_1024": (sea(1024, "analytic"), False),
            "sea_raytraced_1024": (sea(1024, "raytraced"), False),
            "sea_analytic_512_fig": (sea(512, "analytic", n_pulses=16), True),
            "window_1600k_2p": (targets(bandwidth=250.0, fs=1e8), False),
            "window_400k_16p": (targets(n_pulses=16, bandwidth=1e3, fs=1e8), False),
            "window_400k_16p_fig": (targets(n_pulses=16, bandwidth=1e3, fs=1e8), True),
            "window_100k_200p_fig": (targets(n_pulses=200, bandwidth=4e3, fs=1e8), True),
            "pulses_10000": (targets(n_pulses=10000), False),
            "pulses_2000_fig": (targets(n_pulses=2000), True),
        })
    return out


def measure(scene: dict, figures: bool) -> dict:
    from seaecho.checks.resources import estimate
    from seaecho.config import parse_scene
    from seaecho.config.toml_writer import dumps

    est = estimate(parse_scene(copy.deepcopy(scene)), figures=figures)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "scene.toml"
        path.write_text(dumps(scene))
        cmd = [str(SEAECHO), "run", str(path), "-o", str(Path(tmp) / "out.nc"), "-q",
               "--max-memory-gb", "1000"] + ([] if figures else ["--no-figures"])
        r = subprocess.run([sys.executable, "-c", WRAPPER, *cmd], capture_output=True,
                           text=True, check=True)
        rc, peak_kb, wall, err = json.loads(r.stdout)
    if rc != 0:
        raise RuntimeError(f"run failed ({rc}): {err}")
    return {"est": est, "peak": peak_kb * 1024.0, "wall": wall, "load": os.getloadavg()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small cases only (~1 min)")
    parser.add_argument("--cases", nargs="*", help="run only these cases")
    parser.add_argument("--json", help="also write the results to this file")
    add_option(parser)
    args = parser.parse_args()
    if args.smoke:  # one case of each kind
        args.cases = ["targets_2p", "sea_analytic_64"]
    table = cases(args.quick and not args.cases)
    if args.cases:
        table = {k: v for k, v in cases(False).items() if k in args.cases}
    print(f"{'case':24s} {'cells':>8s} {'samples':>8s} {'pulses':>6s} {'est MiB':>8s} "
          f"{'peak MiB':>8s} {'est/peak':>8s} {'est s':>7s} {'wall s':>7s}  load")
    rows = []
    for name, (scene, figures) in table.items():
        m = measure(scene, figures)
        e = m["est"]
        ratio = e.peak_bytes / m["peak"]
        rows.append({"case": name, "cells": e.cells, "samples": e.n_samples,
                     "n_fft": e.n_fft, "pulses": e.n_pulses, "channels": e.channels,
                     "figures": figures, "estimate_bytes": e.peak_bytes,
                     "peak_bytes": m["peak"], "ratio": ratio, "estimate_s": e.time_s,
                     "wall_s": m["wall"], "load": m["load"][0]})
        print(f"{name:24s} {e.cells:8d} {e.n_samples:8d} {e.n_pulses:6d} "
              f"{e.peak_bytes / 2**20:8.0f} {m['peak'] / 2**20:8.0f} {ratio:8.2f} "
              f"{e.time_s:7.1f} {m['wall']:7.1f}  {m['load'][0]:.1f}", flush=True)
    ratios = [r["ratio"] for r in rows]
    print(f"estimate / measured peak: min {min(ratios):.2f}, max {max(ratios):.2f} "
          f"over {len(rows)} cases")
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
