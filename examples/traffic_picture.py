"""A traffic picture: several ships with their wakes, one turning, Swerling targets, and
the ground truth a detector or tracker is scored against (docs/targets.md).

Run: ``python examples/traffic_picture.py [OUTDIR]`` (default ``docs/figures``). Writes

* ``traffic_wakes.png``: the wakes of three ships on a 512 m tile at t = 40 s (the sea
  with ships minus the same sea without them), the ferry turning through its waypoints,
  each ship's track over the first 60 s and its turbulent strip;
* ``traffic_swerling.png``: the RCS that four 10 m^2 targets (Swerling 1 to 4, a dwell of
  16 pulses) present over 128 pulses, from the run's ``truth_rcs``;

and prints what docs/targets.md quotes: the sample moments of the Swerling draws, the
start-up and per-pulse cost of the scene with and without its ships (wall time on this
machine), and the ground truth of the first pulse.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from seaecho.build import build_sea, build_ships  # noqa: E402
from seaecho.config import parse_scene  # noqa: E402
from seaecho.simulation import Simulation  # noqa: E402
from seaecho.targets.swerling import swerling_factor  # noqa: E402

SHIPS = [
    {"name": "freighter", "length_m": 80.0, "beam_m": 13.0, "draft_m": 4.5, "speed_kn": 12.0,
     "heading_deg": 60.0, "position_m": (-150.0, -220.0), "turbulent_wake_length_m": 300.0},
    {"name": "ferry", "length_m": 40.0, "beam_m": 9.0, "draft_m": 2.0, "speed_kn": 15.0,
     "waypoints_m": [(-230.0, 120.0), (-20.0, 120.0), (200.0, -100.0)],
     "turn_rate_deg_s": 3.0, "turbulent_wake_length_m": 300.0},
    {"name": "launch", "length_m": 12.0, "beam_m": 3.5, "draft_m": 0.8, "speed_kn": 8.0,
     "heading_deg": -90.0, "position_m": (150.0, 230.0), "turbulent_wake_length_m": 200.0},
]
TARGETS = [
    {"name": "buoy", "position_m": (60.0, -40.0, 1.0), "preset": "navigation-buoy"},
    {"name": "boat", "position_m": (-60.0, 40.0, 0.5), "preset": "small-boat"},
    {"name": "debris", "position_m": (10.0, 80.0, 0.2), "rcs_m2": 0.5, "swerling": 4},
]


def scene(ships=True, n_pulses=8, sea_clutter=True, targets=TARGETS, cpi=None):
    radar = {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 60e6, "prf_hz": 1000.0,
             "n_pulses": n_pulses, "sea_clutter": sea_clutter, "channels": ["HH", "VV"],
             "waveform": {"kind": "lfm", "bandwidth_hz": 50e6, "duration_s": 2e-6}}
    if cpi is not None:
        radar["cpi_pulses"] = cpi
    d = {"sea": {"wind_speed_m_s": 6.0, "wind_direction_deg": 30.0, "size_x_m": 512.0,
                 "nx": 256},
         "radar": radar,
         "transmitter": {"position_m": (-2000.0, 0.0, 25.0),
                         "antenna": {"pattern": "rectangular", "width_m": 0.3,
                                     "height_m": 0.3, "look_at_m": (0.0, 0.0, 0.0)}},
         "targets": targets}
    if ships:
        d["ships"] = SHIPS
    return parse_scene(d)


def wakes_figure(outdir: Path) -> Path:
    t = 40.0
    with_ships, without = build_sea(scene()), build_sea(scene(ships=False))
    st = with_ships.state(t)
    wake = st.elevation - without.state(t).elevation
    fig, ax = plt.subplots(figsize=(7.0, 6.0), constrained_layout=True)
    lim = float(np.percentile(np.abs(wake), 99.9))
    im = ax.pcolormesh(st.x, st.y, wake, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    fig.colorbar(im, ax=ax, label="wake elevation (sea with ships - without) [m]")
    ax.contour(st.x, st.y, st.wake_mask, levels=[0.2], colors="k", linewidths=0.8,
               linestyles="--")
    times = np.linspace(0.0, 60.0, 121)
    for ship in build_ships(scene()):
        p = ship.position(times)
        ax.plot(p[:, 0], p[:, 1], lw=1.0, label=ship.name)
        ax.plot(*ship.position(t), "k^", ms=5)
        if ship.route is not None:
            w = np.array(ship.route.waypoints)
            ax.plot(w[:, 0], w[:, 1], "kx", ms=6)
    for g in TARGETS:
        ax.plot(*g["position_m"][:2], "ko", ms=4, mfc="none")
    ax.set(xlabel="x (east) [m]", ylabel="y (north) [m]", aspect="equal",
           xlim=(st.x[0], st.x[-1]), ylim=(st.y[0], st.y[-1]),
           title=f"three ships at t = {t:g} s: wakes, tracks (0-60 s), turbulent strips")
    ax.legend(loc="lower right", fontsize=8)
    path = outdir / "traffic_wakes.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def swerling_figure(outdir: Path) -> Path:
    targets = [{"name": f"SW{c}", "position_m": (0.0, 20.0 * c, 0.0), "rcs_m2": 10.0,
                "swerling": c} for c in (1, 2, 3, 4)]
    sc = scene(ships=False, n_pulses=128, sea_clutter=False, targets=targets, cpi=16)
    ds = Simulation(sc).dataset(progress=False)
    rcs = ds["truth_rcs"].values[:, :, 0]
    fig, axes = plt.subplots(4, 1, figsize=(7.0, 6.0), sharex=True, constrained_layout=True)
    for i, ax in enumerate(axes):
        ax.step(ds["pulse"].values, rcs[:, i], where="post", lw=0.9)
        ax.axhline(10.0, color="k", lw=0.6, ls=":")
        for d in range(0, 129, 16):
            ax.axvline(d, color="0.8", lw=0.5)
        ax.set_ylabel(f"SW{i + 1} [m$^2$]")
    axes[-1].set_xlabel("pulse (grey: dwells of 16 pulses; dotted: the mean, 10 m$^2$)")
    path = outdir / "traffic_swerling.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def swerling_moments(n: int = 200_000) -> None:
    print(f"Swerling draws, {n} each (closed forms: E F = 1; E F^2 = 2 for m = 1, 1.5 for m = 2)")
    for case in (1, 2, 3, 4):
        f = swerling_factor(1, [case], np.arange(n)[:, None], 1, target=[case])[:, 0]
        print(f"  case {case}: mean {f.mean():.4f}, E F^2 {np.mean(f**2):.4f}, "
              f"lag-1 correlation {np.corrcoef(f[:-1], f[1:])[0, 1]:+.4f}")


def costs(n_pulses: int = 8) -> None:
    print(f"cost, 256 x 256 grid (131k facets), {n_pulses} pulses, sea and wakes every pulse "
          "(wall and CPU seconds; the machine is shared: wall times vary with its load)")
    for label, ships in (("no ships", False), ("3 ships", True)):
        w0, c0 = time.perf_counter(), time.process_time()
        sim = Simulation(scene(ships=ships, n_pulses=n_pulses))
        w1, c1 = time.perf_counter(), time.process_time()
        ds = sim.static_dataset()
        w2, c2 = time.perf_counter(), time.process_time()
        sim.pulses(0, n_pulses)
        w3, c3 = time.perf_counter(), time.process_time()
        print(f"  {label}: start-up {w1 - w0:.2f} s wall ({c1 - c0:.2f} s CPU); static part "
              f"with the truth {w2 - w1:.2f} s ({c2 - c1:.2f} s CPU); per pulse "
              f"{(w3 - w2) / n_pulses:.2f} s wall ({(c3 - c2) / n_pulses:.2f} s CPU)")
    print("ground truth at pulse 0:")
    for i, name in enumerate(ds["object"].values):
        p = ds["truth_position"].values[0, i]
        print(f"  {name:9s} ({str(ds['object_kind'].values[i])}): ({p[0]:7.1f}, {p[1]:7.1f}) m, "
              f"heading {np.rad2deg(ds['truth_heading'].values[0, i]):6.1f} deg, RCS HH "
              f"{ds['truth_rcs'].values[0, i, 0]:.3g} m^2, range cell "
              f"{int(ds['truth_range_cell'].values[0, i])}, visible "
              f"{int(ds['truth_visible'].values[0, i])}")


def main(argv: list[str] | None = None) -> list[Path]:
    argv = sys.argv[1:] if argv is None else argv
    outdir = Path(argv[0]) if argv else Path(__file__).resolve().parents[1] / "docs" / "figures"
    outdir.mkdir(parents=True, exist_ok=True)
    paths = [wakes_figure(outdir), swerling_figure(outdir)]
    swerling_moments()
    costs()
    for p in paths:
        print(f"wrote {p}")
    return paths


if __name__ == "__main__":
    main()
