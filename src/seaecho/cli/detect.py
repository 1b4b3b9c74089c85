"""``seaecho detect RUN.nc -o DETECTIONS.csv``: CFAR detections of a run, an image or PPI
sweeps, each with the object it belongs to (docs/detection.md)."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "detect", help="CFAR detections of a run, an image or PPI sweeps",
        description="Run a CFAR detector on the range profiles of a run (`seaecho run`), "
        "the sweeps of a scanning run or a CfRadial 2 file, or a SAR image (`seaecho "
        "image`); join detected cells into plots and write one row per plot (time, pulse "
        "or sweep and azimuth, range, x, y, power, SNR estimate, the object it belongs to "
        "or none) to a CSV file, and the objects' opportunities (an object in a look) to "
        "<output>_truth.csv, both atomically; `seaecho score` reads them. Several images "
        "of one grid (in time order) make a stack for the clutter map (--cfar map).",
    )
    p.add_argument("dataset", nargs="+",
                   help="run, scanning run, image (netCDF) or CfRadial 2 file; or several "
                   "images of one grid (a stack for --cfar map)")
    p.add_argument("-o", "--output", help="detections CSV (default: <dataset>_detections.csv)")
    p.add_argument("--cfar", choices=("ca", "go", "so", "os", "map"), default="ca",
                   help="cell averaging, greatest-of, smallest-of, ordered statistic, or "
                   "clutter map (default ca)")
    p.add_argument("--pfa", type=float, default=1e-6,
                   help="design false-alarm probability per cell (default 1e-6)")
    p.add_argument("--train", type=int, nargs="+", default=[16], metavar="N",
                   help="training cells each side: N (along range) or NA NR (2-D)")
    p.add_argument("--guard", type=int, nargs="+", default=[2], metavar="G",
                   help="guard cells each side: G or GA GR (2-D)")
    p.add_argument("--rank", type=int, help="OS-CFAR's order statistic (default 3N/4)")
    p.add_argument("--channel", help="channel, e.g. HH (default the first)")
    p.add_argument("--m-of-n", type=int, nargs=2, metavar=("M", "N"),
                   help="range profiles: M of N consecutive pulses")
    p.add_argument("--map-weight", type=float,
                   help="clutter map: weight of the newest scan (default 0.125)")
    p.add_argument("--no-land-mask", action="store_true",
                   help="PPI sweeps of a run with [[land]]: test the land's cells too (by "
                   "default they are blanked: never tested, no plot)")
    p.add_argument("--land-margin", type=float, default=0.0, metavar="M",
                   help="the land mask's margin outward from the shore [m] (default 0)")
    p.add_argument("--land-spread-db", type=float, default=None, metavar="X",
                   help="the land mask also blanks the sea the land's echo spreads onto: "
                   "the azimuths where the run's two-way antenna pattern is above -X dB, "
                   "the compressed pulse's tails above -X dB in range (default 65; > 0)")
    p.add_argument("--no-land-spread", action="store_true",
                   help="blank the land (and --land-margin) only, not its echo's spread")
    p.add_argument("--no-land-censor", action="store_true",
                   help="leave the land mask's cells in the CFAR's training windows (by "
                   "default they are left out: each estimate averages the sea cells of its "
                   "window, with the threshold for that number of cells)")
    p.add_argument("--censor-min-fraction", type=float, default=0.5, metavar="F",
                   help="land censoring: cells whose window keeps fewer than this fraction "
                   "of its training cells are not tested (default 0.5; in (0, 1])")
    p.add_argument("--stonesoup", metavar="DIR",
                   help="also write the detections and the truth as Stone Soup reads them")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from ..api import LAND_SPREAD_DB, detect, write_detections
    from . import UsageError

    sources = [Path(d) for d in args.dataset]
    for d in sources:
        if not d.exists():
            raise UsageError(f"dataset {d} does not exist")
    src = sources[0]
    out = Path(args.output) if args.output else src.with_name(src.stem + "_detections.csv")
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if out.suffix.lower() != ".csv":
        raise UsageError(f"output {out}: a detections table is a .csv file")
    if not (0.0 < args.pfa < 1.0):
        raise UsageError(f"--pfa {args.pfa}: the design false-alarm probability must be in "
                         "(0, 1)")
    for name in ("train", "guard"):
        v = getattr(args, name)
        if len(v) > 2 or min(v) < (1 if name == "train" else 0):
            raise UsageError(f"--{name} {' '.join(map(str, v))}: one or two whole numbers "
                             f"{'>= 1' if name == 'train' else '>= 0'}")
    if not args.land_margin >= 0.0:
        raise UsageError(f"--land-margin {args.land_margin}: the land mask's margin must "
                         "be >= 0 m")
    if args.land_spread_db is not None and (args.no_land_spread
                                            or not args.land_spread_db > 0.0):
        raise UsageError(f"--land-spread-db {args.land_spread_db:g}: the level below the "
                         "two-way beam's peak out to which the land's echo spreads must be "
                         "> 0 dB" + (" (and not with --no-land-spread)"
                                     if args.no_land_spread else ""))
    if not 0.0 < args.censor_min_fraction <= 1.0:
        raise UsageError(f"--censor-min-fraction {args.censor_min_fraction}: the fraction of "
                         "a window's training cells a land-censored estimate needs must be "
                         "in (0, 1]")
    if args.stonesoup and Path(args.stonesoup).exists() and not Path(args.stonesoup).is_dir():
        raise UsageError(f"--stonesoup {args.stonesoup}: exists and is not a directory")
    try:
        det, truth = detect(src if len(sources) == 1 else sources, cfar=args.cfar, pfa=args.pfa,
                            train=tuple(args.train) if len(args.train) > 1 else args.train[0],
                            guard=tuple(args.guard) if len(args.guard) > 1 else args.guard[0],
                            rank=args.rank, channel=args.channel,
                            m_of_n=tuple(args.m_of_n) if args.m_of_n else None,
                            map_weight=args.map_weight,
                            land_mask=False if args.no_land_mask else None,
                            land_margin_m=args.land_margin,
                            land_censor=False if args.no_land_censor else None,
                            censor_min_fraction=args.censor_min_fraction,
                            land_spread_db=None if args.no_land_spread else
                            LAND_SPREAD_DB if args.land_spread_db is None
                            else args.land_spread_db)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    paths = write_detections(det, truth, out)
    a = det.attrs
    n_fa = int((det["object_index"].values < 0).sum())
    print(f"wrote {paths[0]} ({det.sizes['detection']} detections, {n_fa} false alarms; "
          f"{a['detector']}, P_FA {a['pfa']:g}, alpha {a['alpha']:.4g}; {a['n_looks']} "
          f"looks, {a['cells_tested']} cells tested"
          + (f", {a['cells_blanked']} on the land blanked" if a.get("land_mask") else "")
          + (f" (its echo's spread at -{a['land_spread_db']:g} dB: {a['land_spread_rays']} "
             f"rays, {a['land_spread_gates']} gates)" if a.get("land_spread_db") else "")
          + (f"; land censored: {a['cells_censored']} cells with sea-only windows, "
             f"{a['cells_short']} with too little sea untested" if a.get("land_censor")
             else "") + ")")
    print(f"wrote {paths[1]} ({truth.sizes['opportunity']} object opportunities)")
    if args.stonesoup:
        from ..api import write_stonesoup_dir

        for p in write_stonesoup_dir(det, truth, args.stonesoup).values():
            print(f"wrote {p}")
    return 0
