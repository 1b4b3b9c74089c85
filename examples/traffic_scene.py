"""The coastal traffic scene (scenes/coastal_traffic_xband.toml) end to end, and the ships'
motion in waves (docs/targets.md).

Run: ``python examples/traffic_scene.py [OUTDIR] [--pulses N]`` (default ``docs/figures``,
540 pulses: the 78 deg of the scan that hold every object). Writes

* ``traffic_rao.png``: heave (head seas) and roll (beam seas) response amplitude operators
  of the scene's 12 m launch and 30 m coaster (``BoxHullMotion``), natural periods dashed;
* ``traffic_ppi.png``: the PPI of the run's sweep with the truth (ships triangles, targets
  circles, named) and the CFAR detections (``seaecho detect``, CA-CFAR Pfa 1e-6) crosses;

and prints what docs/targets.md quotes: the natural periods, the run's wall time, which
hull's trace served each ship, and what the detector found (the objects with a
detection, the false alarms).
"""

from __future__ import annotations

import argparse
import csv
import os
import subprocess
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from seaecho.constants import G  # noqa: E402
from seaecho.io.cfradial import boresight_angles  # noqa: E402
from seaecho.targets.motion import BoxHullMotion, WaveComponents  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_traffic_xband.toml"
#: (label, L, B, T) of the scene's launch and coaster; GM the default 0.05 B.
HULLS = [("12 m launch", 12.0, 3.5, 1.0), ("30 m coaster", 30.0, 7.0, 2.5)]


def _rao(motion: BoxHullMotion, period: float, beam_sea: bool) -> float:
    """|heave| / A (head sea) or |roll| / (A k) (beam sea) of a regular wave [-]."""
    om = 2 * np.pi / period
    k = om * om / G
    d = np.pi / 2 if beam_sea else 0.0
    w = WaveComponents(np.array([k * np.cos(d)]), np.array([k * np.sin(d)]), np.array([om]),
                       np.array([1.0 + 0j]), np.array([0j]), np.array([1.0]))
    ts = np.linspace(0.0, period, 32, endpoint=False)
    x = [motion.attitude(w, (0.0, 0.0), 0.0, (0.0, 0.0), t) for t in ts]
    if beam_sea:
        return float(np.max(np.abs(np.tan([a[2] for a in x]))) / k)
    return float(np.max(np.abs([a[0] for a in x])))


def rao_figure(outdir: Path) -> Path:
    periods = np.linspace(1.0, 20.0, 200)
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.6), constrained_layout=True)
    for (label, L, B, T), colour in zip(HULLS, ("C0", "C1"), strict=True):
        m = BoxHullMotion(L, B, T, 0.05 * B)
        t3, t4 = 2 * np.pi / m.heave_frequency, 2 * np.pi / m.roll_frequency
        print(f"{label}: natural periods heave/pitch {t3:.2f} s, roll {t4:.2f} s "
              f"(GM {0.05 * B:.3f} m)")
        axes[0].plot(periods, [_rao(m, p, False) for p in periods], colour, label=label)
        axes[1].plot(periods, [_rao(m, p, True) for p in periods], colour, label=label)
        axes[0].axvline(t3, color=colour, ls="--", lw=0.8)
        axes[1].axvline(t4, color=colour, ls="--", lw=0.8)
    axes[0].set_ylabel("heave / wave amplitude [-]")
    axes[0].set_title("heave, head seas (at rest)", fontsize=9)
    axes[1].set_ylabel("roll / wave slope [-]")
    axes[1].set_title("roll, beam seas (at rest)", fontsize=9)
    for ax in axes:
        ax.set_xlabel("wave period [s]")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    path = outdir / "traffic_rao.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def run_scene(outdir: Path, pulses: int) -> tuple[Path, Path]:
    """``seaecho run`` and ``seaecho detect`` on the scene, in ``outdir``."""
    run = outdir / "traffic_run.nc"
    det = outdir / "traffic_run_detections.csv"
    env = {**os.environ, "SEAECHO_CACHE": os.environ.get("SEAECHO_CACHE", "off")}
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "seaecho", "run", str(SCENE), "-o", str(run),
                    "--pulses", str(pulses), "-q"], check=True, env=env)
    print(f"seaecho run --pulses {pulses}: {time.perf_counter() - t0:.0f} s wall "
          f"[load {os.getloadavg()[0]:.1f}]")
    subprocess.run([sys.executable, "-m", "seaecho", "detect", str(run), "-o", str(det)],
                   check=True, env=env)
    return run, det


def ppi_figure(run: Path, det: Path, outdir: Path) -> Path:
    with xr.open_dataset(run, engine="h5netcdf") as ds:
        ds = ds.load()
    names = ds["object"].values.astype(str)
    kinds = ds["object_kind"].values.astype(str)
    print("traces: " + ", ".join(
        f"{h} <- {ds['hull'].values[int(s)]}" for h, s in
        zip(ds["hull"].values.astype(str), ds["hull_trace_hull"].values[:, -1], strict=True)))
    radar = np.asarray(ds["tx_position"].values[0], dtype=float)
    y = np.abs(ds["compressed"].isel(channel=0).values) ** 2
    r = np.asarray(ds["range"].values, dtype=float)
    az = np.radians(boresight_angles(ds["tx_antenna_axes"].values)[0])  # clockwise, north
    with open(det, newline="") as f:  # the table after its '#' header lines
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    fig, ax = plt.subplots(figsize=(7.0, 6.2), constrained_layout=True)
    a = np.unwrap(az)
    x = r[None, :] * np.sin(a)[:, None]
    yy = r[None, :] * np.cos(a)[:, None]
    p = 10 * np.log10(np.maximum(y, 1e-30))
    im = ax.pcolormesh(x / 1e3, yy / 1e3, p, shading="nearest", cmap="viridis",
                       vmin=p.max() - 70, vmax=p.max(), rasterized=True)
    fig.colorbar(im, ax=ax, label="range-compressed power [dB re 1 W]")
    mid = ds.sizes["pulse"] // 2
    tp = np.asarray(ds["truth_position"].values[mid], dtype=float)
    for kind, mark, colour in (("ship", "^", "orange"), ("target", "o", "r")):
        sel = kinds == kind
        ax.plot((tp[sel, 0] - radar[0]) / 1e3, (tp[sel, 1] - radar[1]) / 1e3, mark, ms=10,
                mfc="none", mec=colour, mew=1.4, label=f"{kind}s (truth)")
    for n, q in zip(names, tp, strict=True):
        ax.annotate(n, ((q[0] - radar[0]) / 1e3, (q[1] - radar[1]) / 1e3), xytext=(6, 4),
                    textcoords="offset points", fontsize=7, color="w")
    if rows:
        dx = np.array([float(row["x_m"]) for row in rows]) - radar[0]
        dy = np.array([float(row["y_m"]) for row in rows]) - radar[1]
        ax.plot(dx / 1e3, dy / 1e3, "x", color="w", ms=5, mew=1.0, label="detections")
    found = sorted({row["object"] for row in rows if row.get("object") not in ("", None)})
    false = sum(1 for row in rows if row.get("object") in ("", None))
    missed = [n for n in names if n not in found]
    print(f"detections: {len(rows)} plots; objects detected: {', '.join(found) or 'none'};"
          f" not detected: {', '.join(missed) or 'none'}; plots on no object: {false}")
    ax.set_aspect("equal")
    ax.set_xlabel("x east of the radar [km]")
    ax.set_ylabel("y north of the radar [km]")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title(f"coastal-traffic-xband, {ds.sizes['pulse']} pulses from north "
                 "(clockwise)", fontsize=9)
    path = outdir / "traffic_ppi.png"
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> list[Path]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", nargs="?", default=str(ROOT / "docs" / "figures"))
    ap.add_argument("--pulses", type=int, default=540)
    ap.add_argument("--work", default=None, help="folder of the run's files (default "
                    "OUTDIR)")
    ap.add_argument("--reuse", action="store_true",
                    help="draw from the run and detections already in the work folder")
    args = ap.parse_args(argv)
    outdir = Path(args.outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    work = Path(args.work) if args.work else outdir
    work.mkdir(parents=True, exist_ok=True)
    out = [rao_figure(outdir)]
    if args.reuse:
        run, det = work / "traffic_run.nc", work / "traffic_run_detections.csv"
    else:
        run, det = run_scene(work, args.pulses)
    out.append(ppi_figure(run, det, outdir))
    return out


if __name__ == "__main__":
    main()
