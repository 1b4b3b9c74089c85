"""``seaecho compare SCENE.toml -o DIR``: ray-traced vs analytic facets on the same sea."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..conventions import CHANNELS


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


def _wrap(a):
    import numpy as np

    return np.angle(np.exp(1j * a))


def summed_sigma(f, sea_model):
    """Sum over facets of area x visibility x sigma_mn (HH, HV, VH, VV) [m^2], with the
    simulation's own sea model (:func:`seaecho.build.build_sea_model`)."""
    from ..scattering.facet import facet_sigma

    sigma = facet_sigma(f.n_i, f.n_s, f.normal, *sea_model.facet_model, local=f)
    return (f.area * f.visibility) @ sigma


def run(args: argparse.Namespace) -> int:
    import csv

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from ..build import build_engine as build_facet_engine
    from ..build import build_sea_model
    from ..io.dataset import atomic_path, atomic_savefig
    from ..io.facets import visibility_summary
    from . import UsageError
    from .trace import build_engine

    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise UsageError(f"-o {out}: exists and is not a folder")
    scene, sea, traced = build_engine(args, mode="raytraced")
    freq = None if args.frequency_ghz is None else args.frequency_ghz * 1e9
    try:
        sea_model = build_sea_model(scene, freq)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    analytic = build_facet_engine(scene, sea.state, Path(args.scene).resolve().parent,
                                  frequency=freq, mode="analytic", tx_position=args.tx,
                                  rx_position=args.rx, sea_model=sea_model)
    st = sea.state(args.time)
    ft = traced.facets(args.time, state=st)
    fa = analytic.facets(args.time, state=st)
    out.mkdir(parents=True, exist_ok=True)

    rows = []
    vt, va = visibility_summary(ft), visibility_summary(fa)
    for key in vt:
        rows.append((key, "1", vt[key], va[key], va[key] - vt[key]))
    both = (ft.visibility > 0) & (fa.visibility > 0)
    diffs = {
        "theta_i": np.degrees(fa.theta_i - ft.theta_i),
        "theta_s": np.degrees(fa.theta_s - ft.theta_s),
        "phi": np.degrees(_wrap(fa.phi - ft.phi)),
        "normal": np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", ft.normal, fa.normal),
                                               -1, 1))),
    }
    for name, d in diffs.items():
        d = d[both]
        rows.append((f"{name}_difference_mean", "deg", np.nan, np.nan, float(d.mean())))
        rows.append((f"{name}_difference_rms", "deg", np.nan, np.nan,
                     float(np.sqrt(np.mean(d**2)))))
        rows.append((f"{name}_difference_max_abs", "deg", np.nan, np.nan,
                     float(np.abs(d).max())))
    st_sig, sa_sig = summed_sigma(ft, sea_model), summed_sigma(fa, sea_model)
    for c, a, b in zip(CHANNELS, st_sig, sa_sig, strict=True):
        rows.append((f"sigma_sum_{c}", "m2", float(a), float(b), float(b - a)))
        rows.append((f"sigma_sum_{c}_db", "dB", float(10 * np.log10(a)),
                     float(10 * np.log10(b)), float(10 * np.log10(b / a))))

    table = out / "compare.csv"
    with atomic_path(table) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["quantity", "unit", "raytraced", "analytic", "analytic_minus_raytraced"])
        for r in rows:
            w.writerow([r[0], r[1]] + [f"{v:.6g}" for v in r[2:]])

    x, y = sea.x, sea.y
    ext = (x[0], x[-1], y[0], y[-1])
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    for ax, (a, title, cmap, lim) in zip(axes, [
            (ft.cell_mean("visibility"), "ray-traced: lit and seen", "gray", (0, 1)),
            (fa.cell_mean("visibility"), f"analytic ({analytic.shadowing}): lit and seen",
             "gray", (0, 1)),
            (fa.cell_mean("visibility") - ft.cell_mean("visibility"),
             "analytic - ray-traced", "RdBu_r", (-1, 1))], strict=True):
        im = ax.imshow(a, origin="lower", extent=ext, cmap=cmap, vmin=lim[0], vmax=lim[1],
                       interpolation="nearest")
        ax.set_title(title)
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
        fig.colorbar(im, ax=ax, shrink=0.8)
    atomic_savefig(fig, out / "compare_visibility.png", dpi=100)
    plt.close(fig)

    fig, axes = plt.subplots(1, 4, figsize=(16, 3.8), constrained_layout=True)
    for ax, (name, d) in zip(axes, diffs.items(), strict=True):
        ax.hist(d[both], bins=100, color="C0")
        ax.set_xlabel(f"{name}: analytic - ray-traced [deg]" if name != "normal"
                      else "angle between normals [deg]")
        ax.set_yscale("log")
    fig.suptitle("per-facet differences (facets visible in both modes)")
    atomic_savefig(fig, out / "compare_angles.png", dpi=100)
    plt.close(fig)
    print(f"wrote {table}, {out / 'compare_visibility.png'}, {out / 'compare_angles.png'}")
    for r in rows[:3]:
        print(f"  {r[0]}: raytraced {r[2]:.4f}, analytic {r[3]:.4f}")
    return 0
