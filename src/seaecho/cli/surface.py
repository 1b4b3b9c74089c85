"""``seaecho surface SCENE.toml -o OUT.nc``: the sea (+ wake) at one or several times.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "surface", help="synthesise the sea surface (+ wake) at given times",
        description="Synthesise the scene's sea surface and ship wake at one or several "
        "times; write a netCDF dataset and a PNG elevation map (paper Fig. 6a).",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", help="output netCDF file (default: [run] output, "
                   "else <scene>_surface.nc)")
    p.add_argument("--time", "-t", type=float, nargs="+", metavar="T_S",
                   help="times [s] (default: [run] surface_times_s)")
    p.add_argument("--no-figure", action="store_true", help="do not write the PNG")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import warnings

    from ..api import load_scene, save, surface
    from ..plotting.run import elevation_map
    from . import UsageError

    scene = load_scene(args.scene)
    if args.output:
        out = Path(args.output)
    elif scene.run.output:
        out = Path(scene.run.output)
    else:
        out = Path(Path(args.scene).stem + "_surface.nc")
    if not out.parent.is_dir() and str(out.parent):
        raise UsageError(f"output directory {out.parent} does not exist")
    with warnings.catch_warnings():
        warnings.simplefilter("always")  # SamplingWarning: tile or grid too coarse
        ds = surface(scene, args.time or None, progress=True)  # bad --time: SceneError
    save(ds, out)
    print(f"wrote {out} ({ds.sizes['time']} time(s), {ds.sizes['y']} x {ds.sizes['x']} grid, "
          f"Hs of resolved band {ds.attrs['expected_hs_resolved_m']:.3f} m)")
    if not args.no_figure:
        png = elevation_map(ds, out.with_suffix(".png"))
        print(f"wrote {png}")
    return 0
