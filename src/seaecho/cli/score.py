"""``seaecho score DETECTIONS.csv``: P_D per object and per SNR bin, false alarms per look
and per km^2, P_FA per cell of a ``seaecho detect`` table (docs/detection.md)."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "score", help="P_D, false alarms and P_FA of `seaecho detect`'s detections",
        description="Score the detections written by `seaecho detect` against their "
        "truth table (<detections>_truth.csv): probability of detection per object and "
        "per SNR bin (an object binned by its mean SNR), false alarms per look and per "
        "km^2, false-alarm cells over tested cells. Optionally write the scores as JSON.",
    )
    p.add_argument("detections", help="detections CSV of `seaecho detect`")
    p.add_argument("--truth", help="truth CSV (default: <detections>_truth.csv)")
    p.add_argument("-o", "--output", help="scores as JSON")
    p.add_argument("--snr-bins-db", type=float, nargs="+", metavar="DB",
                   help="SNR bin edges [dB] (default 0 5 10 15 20, open at both ends)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import json
    import math

    from ..api import score
    from ..io.dataset import atomic_path
    from . import UsageError

    det = Path(args.detections)
    if not det.is_file():
        raise UsageError(f"detections {det} does not exist")
    truth = Path(args.truth) if args.truth else det.with_name(det.stem + "_truth.csv")
    if not truth.is_file():
        raise UsageError(f"truth table {truth} does not exist (write it with `seaecho "
                         "detect`, or give --truth)")
    if args.output and Path(args.output).parent != Path("") and \
            not Path(args.output).parent.is_dir():
        raise UsageError(f"output directory {Path(args.output).parent} does not exist")
    bins = (-math.inf, 0.0, 5.0, 10.0, 15.0, 20.0, math.inf)
    if args.snr_bins_db:
        edges = sorted(args.snr_bins_db)
        if any(not math.isfinite(e) for e in edges) or len(set(edges)) != len(edges):
            raise UsageError(f"--snr-bins-db {args.snr_bins_db}: distinct finite numbers")
        bins = (-math.inf, *edges, math.inf)
    try:
        s = score(det, truth, snr_bins_db=bins)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    print(f"{s['detector']}, design P_FA {s['pfa_design']:g}: {s['detections']} "
          f"detections, P_D {s['pd']:.3f} over all visible opportunities")
    for o, (hit, n, pd) in s["pd_object"].items():
        print(f"  {s['objects'].get(o, o)}: P_D {pd:.3f} ({hit}/{n}), mean SNR "
              f"{s['object_snr_db'][o]:.1f} dB")
    for o, (hit, n) in s.get("hidden_object", {}).items():
        print(f"  {s['objects'].get(o, o)}: hidden by the truth in {n} look(s), not "
              f"scored ({hit} with a plot)")
    for lo, hi, hit, n, pd in s["pd_snr"]:
        print(f"  SNR [{lo:g}, {hi:g}) dB: P_D {pd:.3f} ({hit}/{n})")
    per_km2 = s["false_alarms_per_km2"]
    print(f"  false alarms {s['false_alarms']}: {s['false_alarms_per_look']:.3g} per look"
          + (f", {per_km2:.3g} per km^2 per look" if math.isfinite(per_km2) else "")
          + f"; P_FA per cell {s['pfa_cell']:.3g}")
    if args.output:
        def clean(v):
            if isinstance(v, dict):
                return {str(k): clean(x) for k, x in v.items()}
            if isinstance(v, list | tuple):
                return [clean(x) for x in v]
            if isinstance(v, float) or hasattr(v, "dtype"):
                f = float(v)
                return f if math.isfinite(f) else None
            return v

        with atomic_path(args.output) as tmp:
            tmp.write_text(json.dumps(clean(s), indent=1) + "\n", encoding="utf-8")
        print(f"wrote {args.output}")
    return 0
