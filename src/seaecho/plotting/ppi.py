"""PPI figures of a scanning run: one per sweep, the range-compressed power on the plane
around the radar with the truth marked (the sweeps of :func:`seaecho.io.cfradial.ppi_tree`).
Headless (Agg)."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..io.cfradial import ppi_tree, scene_name


def ppi_figures(run, stem: str | os.PathLike, dynamic_range_db: float = 60.0,
                max_sweeps: int = 8) -> list[Path]:
    """A PPI figure per sweep, ``<stem>_ppi_sweep<N>.png`` (the first ``max_sweeps``).

    Range-compressed power [dB] of the run's first channel, drawn on the plane: x east
    and y north of the radar, x = r sin(az), y = r cos(az) with az the ray's azimuth
    clockwise from north and r its range (the slant range, as a radar's PPI draws it).
    Truth from the run at the sweep's middle time, relative to the radar's position:
    every ship (triangle) and target (circle) of ``truth_position`` with its name, or,
    in a file without it, the point targets and the ship's hull centre; the coastline
    of ``[[land]]`` (``land_outline``) as lines.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..io.dataset import atomic_savefig

    tree = ppi_tree(run)
    stem = Path(stem)
    t_run = np.asarray(run["time"].values, dtype=float)
    out = []
    channel = str(run["channel"].values[0])
    for name in list(tree.children)[:max_sweeps]:
        sw = tree[name].to_dataset()
        # the rays in time order, unwrapped: a sweep turns one way (a sector crossing
        # north, a revolution from its start back to it)
        az = np.unwrap(np.radians(sw["azimuth"].values))
        r = sw["range"].values
        p = sw[f"{channel}_power"].values.astype(float)
        if az.size > 1 and az[-1] < az[0]:
            az, p = az[::-1], p[::-1]
        # cell edges: half-way between rays (a ray's own width at the ends) and gates
        if az.size > 1:
            mid = 0.5 * (az[1:] + az[:-1])
            a_edges = np.concatenate([[2 * az[0] - mid[0]], mid, [2 * az[-1] - mid[-1]]])
        else:
            a_edges = az[0] + np.array([-0.5, 0.5]) * np.radians(0.5)
        dr = r[1] - r[0] if r.size > 1 else 1.0
        r_edges = np.concatenate([r - 0.5 * dr, [r[-1] + 0.5 * dr]])
        x = r_edges[None, :] * np.sin(a_edges)[:, None]
        y = r_edges[None, :] * np.cos(a_edges)[:, None]
        top = float(p.max())
        fig, ax = plt.subplots(figsize=(6.6, 5.8), constrained_layout=True)
        im = ax.pcolormesh(x / 1e3, y / 1e3, p, shading="flat", cmap="viridis",
                           vmin=top - dynamic_range_db, vmax=top, rasterized=True)
        fig.colorbar(im, ax=ax, label=f"{channel} range-compressed power [dB re 1 W]")
        rows = np.flatnonzero(run["sweep"].values == int(name.split("_")[1])
                              + int(run["sweep"].values[0]))
        mid = rows[len(rows) // 2] if rows.size else 0
        scanner = run["sweep"].attrs.get("scan_antenna", "tx")
        radar = np.asarray(run[f"{scanner}_position"].values[mid], dtype=float)
        t_mid = t_run[mid]
        if "truth_position" in run:  # every ship and target of the run, named
            tp = np.asarray(run["truth_position"].values[mid], dtype=float)
            kinds = np.asarray(run["object_kind"].values).astype(str)
            names = np.asarray(run["object"].values).astype(str)
            for kind, mark, colour in (("ship", "^", "orange"), ("target", "o", "r")):
                sel = kinds == kind
                if np.any(sel):
                    ax.plot((tp[sel, 0] - radar[0]) / 1e3, (tp[sel, 1] - radar[1]) / 1e3,
                            mark, ms=9, mfc="none", mec=colour, mew=1.3,
                            label=f"{kind}s (truth)")
            for n, q in zip(names, tp, strict=True):
                ax.annotate(n, ((q[0] - radar[0]) / 1e3, (q[1] - radar[1]) / 1e3),
                            xytext=(5, 4), textcoords="offset points", fontsize=6,
                            color="w")
        elif "target_position" in run:
            tp = (run["target_position"].values + t_mid * run["target_velocity"].values)
            ax.plot((tp[:, 0] - radar[0]) / 1e3, (tp[:, 1] - radar[1]) / 1e3, "o", ms=9,
                    mfc="none", mec="r", mew=1.2, label="targets (truth)")
        if "ship_position" in run and "truth_position" not in run:
            sp = np.asarray(run["ship_position"].values[mid], dtype=float)
            ax.plot((sp[0] - radar[0]) / 1e3, (sp[1] - radar[1]) / 1e3, "^", ms=9,
                    mfc="none", mec="orange", mew=1.5, label="ship (truth)")
        if "land_outline" in run:  # the coastline ([[land]]), closed polygons
            xy = np.asarray(run["land_outline"].values, dtype=float)
            which = np.asarray(run["land_outline_land"].values)
            for k, i in enumerate(np.unique(which)):
                q = xy[which == i]
                q = np.vstack([q, q[:1]])
                ax.plot((q[:, 0] - radar[0]) / 1e3, (q[:, 1] - radar[1]) / 1e3, "-",
                        color="sienna", lw=1.0, label="coastline" if k == 0 else None)
        if any(v in run for v in ("truth_position", "target_position", "ship_position",
                                  "land_outline")):
            ax.legend(loc="upper right", fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlabel("x east of the radar [km]")
        ax.set_ylabel("y north of the radar [km]")
        ax.set_title(f"{scene_name(run)} PPI, {name} "
                     f"({str(sw['sweep_mode'].values)}), t = {t_mid:.2f} s", fontsize=9)
        out.append(atomic_savefig(fig, stem.with_name(f"{stem.name}_ppi_{name}.png"),
                                  dpi=110))
        plt.close(fig)
    return out


__all__ = ["ppi_figures"]
