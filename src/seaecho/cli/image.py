"""``seaecho image RAW.nc -o IMAGE.nc``: focus raw pulses into a calibrated SAR image.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "image", help="focus the raw pulses of `seaecho run` into SAR images",
        description="Backproject the range-compressed pulses of a raw dataset onto a "
        "ground grid, per channel, calibrated in RCS and sigma0 (docs/imaging.md); write "
        "the image dataset atomically, PNG figures (one dB scale for all channels, Pauli "
        "composite) and the paper's image measures. Options override the [image] section "
        "of the file's scene.",
    )
    p.add_argument("raw", help="raw dataset written by `seaecho run` (netCDF)")
    p.add_argument("-o", "--output", help="image dataset (default: <raw>_image.nc)")
    p.add_argument("--track", choices=("nominal", "true"),
                   help="platform track used to focus (default nominal)")
    p.add_argument("--pixel-m", type=float, help="pixel size [m]")
    p.add_argument("--extent", type=float, nargs=4, metavar=("XMIN", "XMAX", "YMIN", "YMAX"),
                   help="image area in the scene frame [m]")
    p.add_argument("--height-m", type=float, help="height of the image plane [m]")
    p.add_argument("--window", choices=("none", "hamming", "taylor"),
                   help="azimuth weighting over the processed Doppler band")
    p.add_argument("--range-weighting", choices=("none", "hamming", "taylor"),
                   help="matched-filter weighting (re-compresses the raw data)")
    p.add_argument("--doppler-bandwidth-hz", type=float,
                   help="processed Doppler bandwidth [Hz] (default the PRF)")
    p.add_argument("--looks", type=int, nargs=2, metavar=("LY", "LX"),
                   help="multilook (y, x) in pixels")
    p.add_argument("--filter", dest="speckle_filter",
                   choices=("none", "boxcar", "refined-lee"), help="speckle filter")
    p.add_argument("--filter-size", type=int, help="speckle filter window [pixels]")
    p.add_argument("--backend", choices=("drjit", "numpy"), default="drjit",
                   help="backprojection kernel (default drjit)")
    p.add_argument("--no-figures", action="store_true", help="do not write PNG figures")
    p.add_argument("--max-memory-gb", type=float, metavar="GB", help="refuse an image whose "
                   "estimated peak memory exceeds this (default: what is available, or "
                   "SEAECHO_MAX_MEMORY_GB)")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar")
    p.set_defaults(func=run)


#: CLI option -> [image] field.
_OVERRIDES = {"track": "track", "pixel_m": "pixel_m", "extent": "extent_m",
              "height_m": "height_m", "window": "azimuth_window",
              "range_weighting": "range_weighting",
              "doppler_bandwidth_hz": "doppler_bandwidth_hz", "looks": "looks",
              "speckle_filter": "speckle_filter", "filter_size": "filter_size"}


def image_fields(args: argparse.Namespace) -> dict:
    """The [image] fields given on the command line (options left out are None)."""
    return {field: getattr(args, opt, None) for opt, field in _OVERRIDES.items()}


def focus_to_files(raw_path: Path, out: Path, cfg, backend: str = "drjit",
                   progress: bool = True, figures: bool = True) -> list[Path]:
    """Focus ``raw_path`` into ``out`` (atomic) and its figures; print the measures."""
    import time

    from ..api import figures as draw
    from ..api import image, image_measures
    from ..checks.guards import check_image
    from ..io.dataset import write_dataset_atomic
    from ..io.run import quiet_invalid_netcdf

    timings: dict = {}
    t = time.perf_counter()
    img = image(raw_path, cfg, backend=backend, progress=progress, timings=timings)
    if "receiver" in img.dims:  # multistatic: each receiver's checked, and the fusion
        return _multistatic_files(img, out, cfg, timings, t, figures)
    with quiet_invalid_netcdf():  # Inf, or NaN at a pixel with data: exit 2, no file
        write_dataset_atomic(img, out, guard=lambda ds: check_image(ds, str(raw_path)))
    wrote = [out]
    ny, nx = img.sizes["y"], img.sizes["x"]
    print(f"wrote {out} ({img.sizes['channel']} channels x {ny} x {nx} pixels of "
          f"{img.attrs['pixel_m']:g} m, track {cfg.track}; backprojection "
          f"{timings['backprojection']:.2f} s, {timings['pixel_pulses_per_s']:.3g} "
          f"pixel-pulses/s, total {time.perf_counter() - t:.2f} s)")
    metrics = image_measures(img)
    for ch, m in metrics.items():
        if m:
            text = ", ".join(f"{k} {v:.2f}" for k, v in m.items())
            print(f"  {ch}: {text}")
    if figures and cfg.figures:
        for png in draw(img, out.with_suffix("")):
            wrote.append(png)
            print(f"wrote {png}")
    return wrote


def _multistatic_files(img, out: Path, cfg, timings: dict, t: float,
                       figures: bool) -> list[Path]:
    """Write a multistatic image (every receiver's and their incoherent combination,
    ``seaecho.multistatic.image_multistatic``), print each receiver's measures."""
    import time

    from ..api import figures as draw
    from ..api import image_measures
    from ..io.dataset import write_dataset_atomic
    from ..io.run import quiet_invalid_netcdf

    with quiet_invalid_netcdf():
        write_dataset_atomic(img, out)
    wrote = [out]
    ny, nx = img.sizes["y"], img.sizes["x"]
    print(f"wrote {out} ({img.sizes['receiver']} receivers x {img.sizes['channel']} "
          f"channels x {ny} x {nx} pixels of {img.attrs['pixel_m']:g} m and their "
          f"incoherent combination, track {cfg.track}; total "
          f"{time.perf_counter() - t:.2f} s)")
    for what, m in image_measures(img).items():
        if m:
            print(f"  {what}: " + ", ".join(f"{k} {v:.2f}" for k, v in m.items()))
    if figures and cfg.figures:
        for png in draw(img, out.with_suffix("")):
            wrote.append(png)
            print(f"wrote {png}")
    return wrote


def run(args: argparse.Namespace) -> int:
    from ..api import image_config
    from . import UsageError

    raw = Path(args.raw)
    if not raw.is_file():
        raise UsageError(f"raw dataset {raw} does not exist")
    out = Path(args.output) if args.output else raw.with_name(raw.stem + "_image.nc")
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if out.resolve() == raw.resolve():
        raise UsageError(f"output {out} would overwrite the raw dataset")
    cfg = image_config(raw, **image_fields(args))
    from ..api import open_dataset
    from ..checks.resources import check_image_memory
    from . import check_memory_option

    check_memory_option(args.max_memory_gb)
    with open_dataset(raw) as ds:  # the pixels against the memory, before any is allocated
        print(check_image_memory(ds, cfg, str(raw), args.max_memory_gb,
                                 figures=not args.no_figures)[1])
    focus_to_files(raw, out, cfg, backend=args.backend, progress=not args.quiet,
                   figures=not args.no_figures)
    return 0
