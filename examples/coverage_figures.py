"""The radar-wide sea's layout (``[sea] coverage = "radar"``): numbers and figure of
docs/scanning.md, "The sea over the whole coverage".

Run: ``python examples/coverage_figures.py`` (a few seconds, no pulse is simulated).
For the coastal VTS radar (scenes/coastal_vts_xband.toml with its sea around the radar:
128 m tiles at 1 m, a window from 300 m) and the S-band scene
(scenes/sband_longrange.toml) it prints the levels (spacing, nodes, band), the tiles of
the patchwork, and the tiles, grid nodes and facets the beam's bound keeps at a pulse,
for windows to 3, 6 and 12 km; it draws the patchwork of the coastal radar to 3 km with
the tiles of pulse 300 (docs/figures/coverage_patchwork.png).

``--sband``: also runs a sector of the S-band scene (its antenna sweeping bearings 350
to 10 deg once at 20 rpm, 167 pulses, the sea held over the sector: the tiles' unit-gain
echoes of docs/scanning.md serve every pulse) and draws its PPI with the ships' truth
(docs/figures/coverage_sband_ppi_sector.png), printing its seconds per pulse (minutes
in all on two cores).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def coastal(end_m: float, n_pulses: int = 2500):
    """The coastal scene with its sea around the radar and the window [300 m, end_m]."""
    from seaecho.config import load_scene

    sc = load_scene(ROOT / "scenes" / "coastal_vts_xband.toml")
    return sc.model_copy(update={
        "sea": sc.sea.model_copy(update={"coverage": "radar", "size_x_m": 128.0,
                                         "nx": 128}),
        "radar": sc.radar.model_copy(update={"window_start_m": 300.0,
                                             "window_end_m": end_m, "n_pulses": n_pulses}),
        "tracing": sc.tracing.model_copy(update={"subfacet_shadowing": True})})


def layout(scene):
    """(patchwork, radar system, boxes) of a coverage scene, without its sea."""
    from seaecho.build import build_radar, coverage_layout, sea_spectrum
    from seaecho.coverage import TILE_MARGIN_M
    from seaecho.radar.system import RadarSystem

    model = build_radar(scene)
    pw = coverage_layout(scene, model, sea_spectrum(scene))
    return pw, RadarSystem(model), pw.boxes(TILE_MARGIN_M), model.sea_gain_floor


def report(name: str, scene, pulse: int) -> None:
    from seaecho.radar.coverage import two_way_bounds

    pw, radar, boxes, floor = layout(scene)
    keep = two_way_bounds(radar, pulse, boxes) >= floor
    nodes = np.array([np.prod(lv.shape) for lv in pw.levels])[pw.level]
    facets = np.array([2 * (lv.shape[0] - 1) * (lv.shape[1] - 1) for lv in pw.levels]
                      )[pw.level]
    levels = ", ".join(f"{lv.spacing[0]:g} m x {lv.shape[1]} [{lv.band[0]:.0f}, "
                       f"{lv.band[1]:.0f}) m" for lv in pw.levels)
    print(f"{name}: levels {levels}; {len(pw)} tiles; pulse {pulse}: "
          f"{int(keep.sum())} tiles ({np.bincount(pw.level[keep], minlength=len(pw.levels))}"
          f" by level), {int(nodes[keep].sum())} nodes, {int(facets[keep].sum())} facets; "
          f"largest tile {int(nodes.max())} nodes")


def figure(path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from seaecho.radar.coverage import two_way_bounds

    pw, radar, boxes, floor = layout(coastal(3000.0))
    keep = two_way_bounds(radar, 300, boxes) >= floor
    fig, ax = plt.subplots(figsize=(6.4, 6.4))
    colours = ["#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd"]
    for i in range(len(pw)):
        x0, x1, y0, y1 = pw.span(i)
        c = colours[int(pw.level[i]) % len(colours)]
        ax.add_patch(Rectangle((x0 / 1e3, y0 / 1e3), (x1 - x0) / 1e3, (y1 - y0) / 1e3,
                               facecolor=c if keep[i] else "none", alpha=0.6 if keep[i]
                               else 1.0, edgecolor=c, linewidth=0.3))
    for r in pw.edges:
        t = np.linspace(0, 2 * np.pi, 400)
        ax.plot((pw.centre[0] + r * np.cos(t)) / 1e3, (pw.centre[1] + r * np.sin(t)) / 1e3,
                "k", linewidth=0.6)
    ax.plot(pw.centre[0] / 1e3, pw.centre[1] / 1e3, "r^")
    ax.set_aspect("equal")
    ax.set_xlim(-3.2, 3.2)
    ax.set_ylim(-5.2, 1.2)
    ax.set_xlabel("x east [km]")
    ax.set_ylabel("y north [km]")
    ax.set_title("Tiles of 1, 2, 4 m facets (blue, green, orange) to 3 km;\n"
                 "filled: computed at pulse 300 (beam at bearing 43 deg)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


def sband_sector(path: Path) -> None:
    """The S-band scene's sector PPI (module docstring) and its cost."""
    import os
    import resource
    import time

    from _gallery import first_ppi

    import seaecho

    scene = seaecho.with_overrides(
        seaecho.load_scene(ROOT / "scenes" / "sband_longrange.toml"),
        {"transmitter.antenna.scan": {"mode": "sector", "rate_rpm": 20.0,
                                      "sector_deg": [10.0, -10.0]},
         "radar.n_pulses": 167, "radar.sea_update_pulses": 167,
         "scattering.sea_motion": "held"})
    wall, cpu = time.perf_counter(), time.process_time()
    ds = seaecho.simulate(scene, progress=False)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    first_ppi(ds, path.parent, path.stem)
    n = ds.sizes["pulse"]
    print(f"S band sector: {n} pulses in {wall:.0f} s wall / {cpu:.0f} s CPU "
          f"({wall / n * 1e3:.0f} / {cpu / n * 1e3:.0f} ms per pulse), peak RSS "
          f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB, load "
          f"{os.getloadavg()[0]:.1f}")
    print(f"wrote {path}")


def main() -> None:
    import sys

    from seaecho.config import load_scene

    warnings.simplefilter("ignore")
    for end in (3000.0, 6000.0, 12000.0):
        report(f"coastal X band to {end / 1e3:g} km", coastal(end), 300)
    report("S band (scenes/sband_longrange.toml) to 12 km",
           load_scene(ROOT / "scenes" / "sband_longrange.toml"), 300)
    figure(ROOT / "docs" / "figures" / "coverage_patchwork.png")
    if "--sband" in sys.argv[1:]:
        sband_sector(ROOT / "docs" / "figures" / "coverage_sband_ppi_sector.png")


if __name__ == "__main__":
    main()
