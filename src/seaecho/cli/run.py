"""``seaecho run SCENE.toml -o OUT.nc``: simulate the radar echoes of a scene."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "run", help="simulate the raw radar echoes of a scene",
        description="Simulate every pulse of the scene's radar (sea clutter, targets, "
        "noise), stream the raw and range-compressed signals to a netCDF file (written "
        "atomically) and draw the paper's Fig. 6 panels.",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", help="output netCDF file (default: [run] output, "
                   "else <scene>.nc)")
    p.add_argument("--pulses", type=int, metavar="N",
                   help="simulate only the first N pulses (quick look)")
    p.add_argument("--no-figures", action="store_true", help="do not write PNG figures")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar")
    p.add_argument("--max-memory-gb", type=float, metavar="GB", help="refuse a run whose "
                   "estimated peak memory exceeds this (default: what is available, or "
                   "SEAECHO_MAX_MEMORY_GB)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import xarray as xr

    from ..config import SceneError, load_scene
    from ..ocean.sampling import check_sampling
    from ..radar.figures import run_figures
    from ..simulation import Simulation
    from . import UsageError

    scene = load_scene(args.scene)
    if scene.radar is None or scene.transmitter is None:
        raise SceneError(f"{args.scene}: `seaecho run` needs [radar] and [transmitter] "
                         "sections")
    if args.pulses is not None:
        if args.pulses < 1:
            raise UsageError(f"--pulses {args.pulses}: must be >= 1")
        n = min(args.pulses, scene.radar.n_pulses)
        radar = scene.radar.model_copy(update={
            "n_pulses": n, "sigma_map_pulse": min(scene.radar.sigma_map_pulse, n - 1)})
        scene = scene.model_copy(update={"radar": radar})
    from ..preflight import check_run
    from . import check_memory_option

    check_memory_option(args.max_memory_gb)  # memory estimate, degenerate geometry...
    print(check_run(scene, args.scene, base_dir=Path(args.scene).parent,
                    max_memory_gb=args.max_memory_gb, figures=not args.no_figures))
    if args.output:
        out = Path(args.output)
    elif scene.run.output:
        out = Path(scene.run.output)
    else:
        out = Path(Path(args.scene).stem + ".nc")
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if scene.radar.sea_clutter:
        check_sampling(scene)  # SamplingWarning on stderr if the tile / grid is too coarse
    try:
        sim = Simulation(scene, base_dir=Path(args.scene).parent)
    except ValueError as exc:
        raise SceneError(f"{args.scene}: {exc}") from None
    sim.run(out, progress=not args.quiet)
    r = sim.radar
    print(f"wrote {out} ({r.n_pulses} pulses x {len(r.channels)} channels x "
          f"{r.window.n_samples} samples)")
    if not args.no_figures:
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            for png in run_figures(ds, out.with_suffix("")):
                print(f"wrote {png}")
    return 0
