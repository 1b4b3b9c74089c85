"""``seaecho trace SCENE.toml -o FILE.nc``: facets seen from the transmitter and receiver."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_geometry_options(p: argparse.ArgumentParser) -> None:
    """Options shared by ``trace`` and ``compare``."""
    p.add_argument("--time", "-t", type=float, default=0.0, metavar="T_S",
                   help="time of the surface and the platforms [s] (default 0)")
    p.add_argument("--tx", type=float, nargs=3, metavar=("X", "Y", "Z"),
                   help="transmitter position [m] (default: the scene's [transmitter])")
    p.add_argument("--rx", type=float, nargs=3, metavar=("X", "Y", "Z"),
                   help="receiver position [m] (default: the scene's [receiver]; with --tx "
                   "and no --rx: monostatic)")
    p.add_argument("--variant", choices=("llvm_ad_mono_polarized", "cuda_ad_mono_polarized"),
                   help="Mitsuba variant (default: [tracing] variant)")
    p.add_argument("--frequency-ghz", type=float, metavar="F",
                   help="radar carrier [GHz] (default: [radar] carrier_frequency_hz; needed "
                   "when the scene has no [radar]): sea-water permittivity and two-scale split")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "trace", help="facets of the sea seen from Tx and Rx (visibility, ranges, angles)",
        description="Compute the sea's facets at one time: visibility from the transmitter "
        "and the receiver (ray traced against sea and objects, or analytic), float64 "
        "ranges, local bistatic angles and basis rotations; write a netCDF dataset and "
        "PNG maps.",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", required=True, help="output netCDF file")
    p.add_argument("--mode", choices=("raytraced", "analytic"),
                   help="facet mode (default: [tracing] mode)")
    add_geometry_options(p)
    p.add_argument("--no-figure", action="store_true", help="do not write the PNG maps")
    p.set_defaults(func=run)


def build_engine(args: argparse.Namespace, mode: str | None = None):
    """(scene, sea, engine) of the CLI arguments; bad input -> SceneError / UsageError."""
    import math

    from ..build import build_engine as build_facet_engine
    from ..build import build_sea
    from ..config import load_scene
    from . import UsageError

    scene = load_scene(args.scene)
    if not math.isfinite(args.time):
        raise UsageError(f"--time {args.time}: must be a finite number of seconds")
    if args.rx is not None and args.tx is None:
        raise UsageError("--rx needs --tx")
    if args.tx is None and scene.transmitter is None:
        raise UsageError(f"{args.scene}: no [transmitter] section; give --tx X Y Z")
    freq = None if args.frequency_ghz is None else args.frequency_ghz * 1e9
    try:
        sea = build_sea(scene)
        engine = build_facet_engine(scene, sea.state, Path(args.scene).resolve().parent,
                                    frequency=freq, mode=mode, variant=args.variant,
                                    tx_position=args.tx, rx_position=args.rx)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return scene, sea, engine


def run(args: argparse.Namespace) -> int:
    from ..build import scene_attrs
    from ..io.dataset import write_dataset_atomic
    from ..io.facets import facet_maps, facets_dataset, visibility_summary
    from . import UsageError

    out = Path(args.output)
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    scene, sea, engine = build_engine(args, mode=args.mode)
    f = engine.facets(args.time)
    tx, rx = engine.positions(args.time)
    ds = facets_dataset(f, sea.x, sea.y, tx, rx, attrs=scene_attrs(scene))
    write_dataset_atomic(ds, out)
    s = visibility_summary(f)
    print(f"wrote {out} ({f.mode}, {f.n_facets} facets at t = {f.time_s:g} s; lit from Tx "
          f"{s['lit_fraction_tx']:.4f}, seen from Rx {s['seen_fraction_rx']:.4f}, both "
          f"{s['visible_fraction']:.4f})")
    if not args.no_figure:
        png = facet_maps(f, sea.x, sea.y, out.with_suffix(".png"),
                         title=f"{scene.name}: {f.mode} facets at t = {f.time_s:g} s")
        print(f"wrote {png}")
    return 0
