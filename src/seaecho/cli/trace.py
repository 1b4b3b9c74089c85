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


def geometry_arguments(args: argparse.Namespace) -> dict:
    """Keyword arguments of :func:`seaecho.api.trace` / :func:`~seaecho.api.compare`
    from the shared options; ``--rx`` without ``--tx`` is a usage error."""
    from . import UsageError

    if args.rx is not None and args.tx is None:
        raise UsageError("--rx needs --tx")
    freq = None if args.frequency_ghz is None else args.frequency_ghz * 1e9
    return {"time": args.time, "tx_position": args.tx, "rx_position": args.rx,
            "variant": args.variant, "frequency_hz": freq}


def load(args: argparse.Namespace):
    """The scene of ``args.scene``, checked for what the geometry options need."""
    from ..api import load_scene
    from . import UsageError

    scene = load_scene(args.scene)
    if args.tx is None and scene.transmitter is None:
        raise UsageError(f"{args.scene}: no [transmitter] section; give --tx X Y Z")
    return scene


def run(args: argparse.Namespace) -> int:
    from ..api import save, trace
    from ..plotting.facets import facet_maps
    from . import UsageError

    out = Path(args.output)
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    kwargs = geometry_arguments(args)
    scene = load(args)
    ds = trace(scene, mode=args.mode, **kwargs)
    save(ds, out)
    a = ds.attrs
    print(f"wrote {out} ({a['facet_mode']}, {ds['area'].size} facets at t = {a['time_s']:g} s; "
          f"lit from Tx {a['lit_fraction_tx']:.4f}, seen from Rx {a['seen_fraction_rx']:.4f}, "
          f"both {a['visible_fraction']:.4f})")
    if not args.no_figure:
        png = facet_maps(ds, out.with_suffix(".png"), title=f"{scene.name}: "
                         f"{a['facet_mode']} facets at t = {a['time_s']:g} s")
        print(f"wrote {png}")
    return 0
