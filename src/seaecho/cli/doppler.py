"""``seaecho doppler RAW.nc -o OUT.nc``: range-Doppler maps and Doppler spectra of a run."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "doppler", help="range-Doppler maps and clutter Doppler spectra of a run",
        description="Doppler power spectral density of every range cell of the "
        "range-compressed pulses of a dataset written by `seaecho run` (per channel, "
        "Welch average of half-overlapping CPIs), the clutter's Doppler spectrum, its "
        "centroid and width, and the temporal autocorrelation (docs/dynamics.md); "
        "written atomically, with a PNG figure beside it.",
    )
    p.add_argument("raw", help="dataset written by `seaecho run` (netCDF)")
    p.add_argument("-o", "--output", help="Doppler dataset (default: <raw>_doppler.nc)")
    p.add_argument("--cpi", type=int, help="pulses per coherent processing interval "
                   "(default: all pulses)")
    p.add_argument("--window", choices=("hann", "hamming", "none"), default="hann",
                   help="taper over the pulses of a CPI (default hann)")
    p.add_argument("--floor-db", type=float, default=20.0,
                   help="range cells within this many dB of the strongest make the "
                   "clutter spectrum (default 20)")
    p.add_argument("--no-figure", action="store_true", help="do not write the PNG figure")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import xarray as xr

    from ..io.dataset import write_dataset_atomic
    from ..io.doppler import doppler_dataset
    from ..io.run import quiet_invalid_netcdf
    from ..plotting.doppler import doppler_figure
    from . import UsageError

    raw = Path(args.raw)
    if not raw.is_file():
        raise UsageError(f"raw dataset {raw} does not exist")
    out = Path(args.output) if args.output else raw.with_name(raw.stem + "_doppler.nc")
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if out.resolve() == raw.resolve():
        raise UsageError(f"output {out} would overwrite the raw dataset")
    if not (args.floor_db > 0):
        raise UsageError(f"--floor-db = {args.floor_db}: must be > 0 dB")
    try:
        with xr.open_dataset(raw, engine="h5netcdf") as ds:
            if int(ds.attrs.get("multistatic", 0)):
                raise ValueError("a multistatic run (several receivers): not implemented "
                                 "yet here; take one receiver with "
                                 "seaecho.multistatic.receiver_dataset(ds, name)")
            product = doppler_dataset(ds, cpi=args.cpi, window=args.window,
                                      floor_db=args.floor_db)
    except (OSError, ValueError) as exc:
        raise UsageError(f"{raw}: {exc}") from None
    with quiet_invalid_netcdf():
        write_dataset_atomic(product, out)
    print(f"wrote {out} ({product.sizes['channel']} channels, {product.sizes['doppler']} "
          f"Doppler bins of {float(product.attrs['prf_hz']) / product.sizes['doppler']:.3g} "
          f"Hz, {int(product['clutter_cell'].sum())} clutter cells)")
    for c, cen, wid in zip(product["channel"].values, product["doppler_centroid"].values,
                           product["doppler_width"].values, strict=True):
        print(f"  {c}: centroid {cen:+.1f} Hz, width {wid:.1f} Hz")
    if not args.no_figure:
        png = doppler_figure(product, out.with_suffix(".png"))
        print(f"wrote {png}")
    return 0
