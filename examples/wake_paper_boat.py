"""Kelvin wake of the paper's 10 m motor boat at 10 kt (section V), and the model behind it.

Run: ``python examples/wake_paper_boat.py [OUTDIR]`` (default ``docs/figures``). Writes

* ``wake_paper_boat.png``: wake elevation on the paper's 128 m, 512 x 512 tile (sims 2-3)
  for L = 10 m, B = 4 m, T = 1.5 m, V = 10 kt, heading 35 deg, with the crest lines of
  paper eq 16 (from the bow), the cusp lines at asin(1/3) and the turbulent-wake strip;
* ``wake_michell.png``: the Michell amplitude function |A(theta)| of that boat, and the
  wave-resistance coefficient of the standard Wigley hull (B/L = 0.1, T/L = 0.0625) from
  eq W6 against Froude number.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from seaecho.constants import KNOT  # noqa: E402
from seaecho.wake import (  # noqa: E402
    KELVIN_HALF_ANGLE,
    KelvinWake,
    Ship,
    kelvin_crest_lines,
    turbulent_wake_mask,
    wigley_wave_resistance,
    wigley_wetted_surface,
)


def _world(ship: Ship, xs, ys, t: float = 0.0):
    """Ship-frame (x', y') -> world (x, y) (inverse of eq W2)."""
    c, s = np.cos(ship.heading), np.sin(ship.heading)
    p = ship.position(t)
    return p[0] - xs * c + ys * s, p[1] - xs * s - ys * c


def wake_map(outdir: Path) -> Path:
    ship = Ship(10.0, 4.0, 1.5, 10.0 * KNOT, np.deg2rad(35.0), (40.0, 30.0))
    wake = KelvinWake(ship)
    n, tile = 512, 128.0
    x = (np.arange(n) - n / 2) * tile / n
    y = x.copy()
    f = wake.fields(x, y, 0.0)
    mask = turbulent_wake_mask(ship, x, y, 0.0)

    fig, ax = plt.subplots(figsize=(7.2, 6.0), constrained_layout=True)
    lim = float(np.abs(f.elevation).max())
    im = ax.pcolormesh(x, y, f.elevation, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    fig.colorbar(im, ax=ax, label="wake elevation z [m]")
    ax.contour(x, y, mask, levels=[0.5], colors="k", linewidths=0.9, linestyles="--")
    bow = -0.5 * ship.length
    theta = np.linspace(-np.pi / 2, np.pi / 2, 401)
    for k in range(1, 12):
        xs, ys = kelvin_crest_lines(k, ship.speed, theta)
        ax.plot(*_world(ship, xs + bow, ys), color="0.25", lw=0.5, alpha=0.7)
    r = np.array([0.0, 300.0])
    for sgn in (1, -1):
        ax.plot(
            *_world(ship, bow + r * np.cos(KELVIN_HALF_ANGLE), sgn * r * np.sin(KELVIN_HALF_ANGLE)),
            "k:",
            lw=1.0,
        )
    hull_x = np.linspace(-5, 5, 50)
    hull_y = 2.0 * (1 - (2 * hull_x / 10.0) ** 2)
    ax.fill(*_world(ship, np.r_[hull_x, hull_x[::-1]], np.r_[hull_y, -hull_y[::-1]]), color="k")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (east) [m]")
    ax.set_ylabel("y (north) [m]")
    ax.set_title(
        "Kelvin wake, L 10 m, B 4 m, T 1.5 m, 10 kt, heading 35 deg "
        "(Michell pattern, Kriebel-Seelig heights)\n"
        "thin lines: crests of eq 16 from the bow; dotted: cusp lines 19.47 deg; "
        "dashed: turbulent wake",
        fontsize=8,
    )
    out = outdir / "wake_paper_boat.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def michell_figure(outdir: Path) -> Path:
    ship = Ship(10.0, 4.0, 1.5, 10.0 * KNOT)
    wake = KelvinWake(ship)
    theta = np.linspace(-1.45, 1.45, 2001)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(9.0, 3.6), constrained_layout=True)
    a1.plot(np.degrees(theta), np.abs(wake.amplitude(theta)))
    a1.set_xlabel("wave angle theta [deg]")
    a1.set_ylabel("|A(theta)| [m/rad]")
    a1.set_title(
        f"paper's boat, Fn = {ship.froude_number:.2f}: R_w = "
        f"{wake.wave_resistance() / 1e3:.0f} kN (eq W6)",
        fontsize=9,
    )
    fn = np.linspace(0.18, 1.0, 300)
    g, rho = 9.80665, 1000.0
    s = wigley_wetted_surface(1.0, 0.1, 0.0625)
    cw = [
        wigley_wave_resistance(1.0, 0.1, 0.0625, f * np.sqrt(g), rho) / (0.5 * rho * f**2 * g * s)
        for f in fn
    ]
    a2.plot(fn, 1e3 * np.array(cw))
    a2.set_xlabel("Froude number V / sqrt(g L)")
    a2.set_ylabel("10^3 C_w = R_w / (rho V^2 S / 2)")
    a2.set_title("standard Wigley hull (B/L 0.1, T/L 0.0625), Michell", fontsize=9)
    out = outdir / "wake_michell.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


def main(argv: list[str]) -> int:
    outdir = Path(argv[1]) if len(argv) > 1 else Path("docs/figures")
    outdir.mkdir(parents=True, exist_ok=True)
    for p in (wake_map(outdir), michell_figure(outdir)):
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
