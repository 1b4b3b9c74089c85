"""``seaecho check SCENE.toml``: validate a scene file, write nothing."""

from __future__ import annotations

import argparse
import warnings


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check", help="validate a scene file (writes nothing)",
                       description="Validate a scene file and print a summary.")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--max-memory-gb", type=float, metavar="GB",
                   help="memory `seaecho run` may use (default: what is available, or "
                   "SEAECHO_MAX_MEMORY_GB)")
    p.add_argument("--no-figures", action="store_true",
                   help="estimate a run without figures (as `seaecho run --no-figures`)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from ..build import check_scene
    from ..checks.preflight import check_run, default_output
    from ..config import load_scene
    from . import check_memory_option

    check_memory_option(args.max_memory_gb)
    scene = load_scene(args.scene)
    runnable = scene.radar is not None and scene.transmitter is not None
    resources = None
    if runnable:  # what `seaecho run` would refuse, refused here too
        output, field = default_output(scene, args.scene)
        resources = check_run(scene, args.scene, base_dir=Path(args.scene).parent,
                              max_memory_gb=args.max_memory_gb, figures=not args.no_figures,
                              output=output, output_field=field)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_scene(scene)
    lx, ly = scene.sea.size_m
    ny, nx = scene.sea.shape
    print(f"{args.scene}: valid scene '{scene.name}'")
    print(f"  sea: {scene.sea.spectrum} spectrum, U19.5 = {scene.sea.wind_speed_m_s} m/s "
          f"towards {scene.sea.wind_direction_deg} deg, tile {lx} x {ly} m on {nx} x {ny}")
    for s, name in zip(scene.all_ships, scene.ship_names(), strict=True):
        track = (f"through {len(s.waypoints_m)} waypoints" if s.waypoints_m is not None
                 else f"heading {s.heading_deg} deg")
        print(f"  ship {name}: {s.length_m} x {s.beam_m} m, draft {s.draft_m} m, "
              f"{s.speed:.3f} m/s {track}")
    if resources is not None:
        print(f"  run: {resources}")
    if not runnable:
        print("  no [radar] and [transmitter]: `seaecho surface` and `seaecho trace` can use "
              "it, `seaecho run` needs both")
    for w in caught:
        print(f"  warning: {w.message}")
    return 0
