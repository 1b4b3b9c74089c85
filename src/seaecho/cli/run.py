"""``seaecho run SCENE.toml -o OUT.nc``: simulate the radar echoes of a scene.

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import sys
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "run", help="simulate the raw radar echoes of a scene",
        description="Simulate every pulse of the scene's radar (sea clutter, targets, "
        "noise), stream the raw and range-compressed signals to a netCDF file (written "
        "atomically) and draw the paper's Fig. 6 panels.",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", help="output netCDF file, or Zarr store if it ends in "
                   ".zarr (default: [run] output, else <scene>.nc)")
    p.add_argument("--pulses", type=int, metavar="N",
                   help="simulate only the first N pulses (quick look)")
    p.add_argument("--no-figures", action="store_true", help="do not write PNG figures")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar")
    p.add_argument("--no-cache", action="store_true", help="neither read nor write the "
                   "cache of hull signatures (default: the user cache folder, or "
                   "SEAECHO_CACHE_DIR; SEAECHO_CACHE=off also disables it)")
    p.add_argument("--max-memory-gb", type=float, metavar="GB", help="refuse a run whose "
                   "estimated peak memory exceeds this (default: what is available, or "
                   "SEAECHO_MAX_MEMORY_GB)")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--workers", type=int, metavar="N",
                   help="run the blocks of pulses on a local Dask cluster of N worker "
                   "processes (default: serially in this process; same bytes)")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on an existing Dask cluster (e.g. tcp://host:8786); a Zarr "
                   "output and the scene's meshes must be on a file system the workers see")
    p.add_argument("--resume", action="store_true",
                   help="Zarr output: continue an interrupted run of the same scene, "
                   "computing only the missing blocks")
    p.add_argument("--block-pulses", type=int, metavar="N",
                   help="pulses per block of work and per Zarr chunk (default: about 16, "
                   "aligned with the held sea and the occlusion refresh)")
    p.set_defaults(func=run)


@contextlib.contextmanager
def _cache_disabled(disabled: bool):
    """``SEAECHO_CACHE=off`` for the run (and the local workers it starts) if asked."""
    from ..targets.cache import CACHE_ENV

    if not disabled:
        yield
        return
    before = os.environ.get(CACHE_ENV)
    os.environ[CACHE_ENV] = "off"
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(CACHE_ENV, None)
        else:
            os.environ[CACHE_ENV] = before


def run(args: argparse.Namespace) -> int:
    from ..api import figures, first_pulses, load_scene, simulate
    from ..checks.guards import NonFiniteEchoError
    from ..checks.preflight import check_run, default_output, image_output
    from ..config import SceneError
    from ..io.zarr_run import StoreError, is_zarr, part_path
    from . import UsageError

    scene = load_scene(args.scene)
    if scene.radar is None or scene.transmitter is None:
        raise SceneError(f"{args.scene}: `seaecho run` needs [radar] and [transmitter] "
                         "sections")
    out, out_field = ((Path(args.output), "-o") if args.output
                      else default_output(scene, args.scene))  # [run] output, or SCENE.nc
    zarr_out = is_zarr(out)
    # (a Zarr output with [image], a folder that does not exist: the preflight below)
    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers {args.workers}: must be >= 1")
    if args.block_pulses is not None and args.block_pulses < 1:
        raise UsageError(f"--block-pulses {args.block_pulses}: must be >= 1")
    from . import check_memory_option

    check_memory_option(args.max_memory_gb)  # memory estimate, degenerate geometry...
    checked = scene if args.pulses is None else first_pulses(scene, args.pulses)
    print(check_run(checked, args.scene, base_dir=Path(args.scene).parent,
                    max_memory_gb=args.max_memory_gb, figures=not args.no_figures,
                    workers=args.workers, block=args.block_pulses, output=out,
                    output_field=out_field))
    try:  # the Python API's run: same checks, same bytes (seaecho.simulate)
        with _cache_disabled(args.no_cache):
            ds = simulate(scene, path=out, pulses=args.pulses, progress=not args.quiet,
                          workers=args.workers, scheduler=args.scheduler,
                          block_pulses=args.block_pulses, resume=args.resume)
    except StoreError as exc:
        raise UsageError(str(exc)) from None
    except NonFiniteEchoError:
        if zarr_out:  # a NaN pulse comes back on --resume: nothing worth keeping
            shutil.rmtree(part_path(out), ignore_errors=True)
        raise
    except KeyboardInterrupt:
        if not zarr_out:
            raise
        print(f"seaecho: interrupted; the blocks written so far are kept in "
              f"{part_path(out)}: continue with --resume", file=sys.stderr)
        return 130
    wrote = [out]
    with ds:
        many = (f"{ds.sizes['receiver']} receivers x " if "receiver" in ds.dims else "")
        print(f"wrote {out} ({ds.sizes['pulse']} pulses x {many}{ds.sizes['channel']} "
              f"channels x {ds.sizes.get('fast_time', ds.sizes.get('sample'))} samples)")
        if "sweep" in ds:  # a scanning radar: its sweeps as CfRadial 2 (docs/scanning.md)
            from ..io.cfradial import write_ppi

            wrote.append(write_ppi(ds, out.with_name(out.stem + "_ppi.nc")))
            print(f"wrote {wrote[-1]}")
        if not args.no_figures:
            for png in figures(ds, out.with_suffix("")):
                wrote.append(png)
                print(f"wrote {png}")
    if scene.image is not None:  # [image]: focus the raw data just written (seaecho image)
        from .image import focus_to_files

        try:
            focus_to_files(out, image_output(out), scene.image,
                           progress=not args.quiet, figures=not args.no_figures)
        except NonFiniteEchoError:  # the image guard: exit 2 leaves no file of this run
            for path in wrote:
                Path(path).unlink(missing_ok=True)
            raise
    return 0
