"""``seaecho truth``: the ground-truth tracks of a run as CSV (one row per pulse and
object: ships and point targets; columns in :mod:`seaecho.io.truth_tracks`)."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "truth", help="ground-truth tracks of a run (ships, targets) as CSV",
        description="Write the per-pulse ground truth of a run (position, velocity, heading, "
        "RCS, range, range cell, visibility of every ship and point target) as a tidy CSV, "
        "one row per pulse and object (docs/targets.md).")
    p.add_argument("run", help="dataset written by `seaecho run` (netCDF or .zarr)")
    p.add_argument("-o", "--output", help="CSV file (default: <run>_truth.csv)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from ..io.run import open_run
    from ..io.truth_tracks import write_truth_csv
    from . import UsageError

    src = Path(args.run)
    if not src.exists():
        raise UsageError(f"run dataset {src} does not exist")
    out = Path(args.output) if args.output else src.with_name(src.stem + "_truth.csv")
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if out.resolve() == src.resolve():
        raise UsageError(f"output {out} would overwrite the run dataset")
    try:
        with open_run(src) as ds:
            path = write_truth_csv(ds, out)
            n_o = ds.sizes["object"]
            n_p = ds.sizes["pulse"]
    except (OSError, ValueError) as exc:
        raise UsageError(f"{src}: {exc}") from None
    print(f"wrote {path} ({n_o} objects x {n_p} pulses)")
    return 0
