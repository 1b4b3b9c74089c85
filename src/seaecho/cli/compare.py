"""``seaecho compare SCENE.toml -o DIR``: ray-traced vs analytic facets on the same sea."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    from .trace import add_geometry_options

    p = sub.add_parser(
        "compare", help="compare the ray-traced and analytic facet modes on one sea",
        description="Run both facet modes on the same surface realisation and geometry; "
        "write a CSV table (lit/seen fractions from Tx and Rx, local-angle differences, "
        "summed sigma per channel) and PNG figures into DIR.",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if missing)")
    add_geometry_options(p)
    p.set_defaults(func=run)


def table_rows(ds) -> list[tuple]:
    """Rows (quantity, unit, raytraced, analytic, analytic - raytraced) of the CSV table
    from :func:`seaecho.api.compare`'s dataset."""
    import numpy as np

    from ..conventions import CHANNELS

    rows = []
    for key in ("lit_fraction_tx", "seen_fraction_rx", "visible_fraction"):
        t, a = (float(v) for v in ds[key].values)
        rows.append((key, "1", t, a, a - t))
    for name in ("theta_i", "theta_s", "phi", "normal"):
        d = ds[f"{name}_difference"].values
        d = d[np.isfinite(d)]
        rows.append((f"{name}_difference_mean", "deg", np.nan, np.nan, float(d.mean())))
        rows.append((f"{name}_difference_rms", "deg", np.nan, np.nan,
                     float(np.sqrt(np.mean(d**2)))))
        rows.append((f"{name}_difference_max_abs", "deg", np.nan, np.nan,
                     float(np.abs(d).max())))
    for c in CHANNELS:
        a, b = (float(v) for v in ds["sigma_sum"].sel(polarisation=c).values)
        rows.append((f"sigma_sum_{c}", "m2", a, b, b - a))
        rows.append((f"sigma_sum_{c}_db", "dB", float(10 * np.log10(a)),
                     float(10 * np.log10(b)), float(10 * np.log10(b / a))))
    return rows


def run(args: argparse.Namespace) -> int:
    import csv

    from ..api import compare
    from ..io.dataset import atomic_path
    from ..plotting.facets import compare_figures
    from . import UsageError
    from .trace import geometry_arguments, load

    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise UsageError(f"-o {out}: exists and is not a folder")
    kwargs = geometry_arguments(args)
    ds = compare(load(args), **kwargs)
    out.mkdir(parents=True, exist_ok=True)
    rows = table_rows(ds)
    table = out / "compare.csv"
    with atomic_path(table) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["quantity", "unit", "raytraced", "analytic", "analytic_minus_raytraced"])
        for r in rows:
            w.writerow([r[0], r[1]] + [f"{v:.6g}" for v in r[2:]])

    compare_figures(ds, out)
    print(f"wrote {table}, {out / 'compare_visibility.png'}, {out / 'compare_angles.png'}")
    for r in rows[:3]:
        print(f"  {r[0]}: raytraced {r[2]:.4f}, analytic {r[3]:.4f}")
    return 0
