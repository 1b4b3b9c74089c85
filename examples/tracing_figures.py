"""Figures of ``docs/tracing.md``: ``python examples/tracing_figures.py docs/figures``.

- ``tracing_smith.png``: lit fraction of Gaussian random surfaces, ray traced vs Smith's
  function (Smith 1967) and the Smith-weighted analytic mode, against the grazing angle;
- ``tracing_box_shadow.png``: a box over a flat sea, ray-traced shadow and the analytic
  shadow polygon;
- ``tracing_modes.png``: visibility maps of a wind sea with the 10 m motor boat, ray traced
  vs analytic (Smith), bistatic.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np


def _gaussian_surface(n, dx, corr_len, sigma_h, rng):
    k = 2 * np.pi * np.fft.fftfreq(n, dx)
    kx, ky = np.meshgrid(k, k)
    z = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n)))
                             * np.exp(-(kx**2 + ky**2) * corr_len**2 / 8)))
    return z * sigma_h / z.std()


def smith_figure(path: Path) -> None:
    import matplotlib.pyplot as plt

    from seaecho.geometry.facets import smith_weights
    from seaecho.geometry.shadowing import smith_monostatic
    from seaecho.io.dataset import atomic_savefig
    from seaecho.tracing.tracer import FacetTracer

    n, corr = 256, 8.0
    x = (np.arange(n) - n / 2) * 1.0
    tr = FacetTracer(x, x)
    grazing = np.array([3.0, 5.0, 7.5, 10.0, 15.0, 20.0, 30.0])
    fig, ax = plt.subplots(figsize=(6.4, 4.4), constrained_layout=True)
    for colour, s in (("C0", 0.1), ("C1", 0.2)):
        traced, analytic = [], []
        for g in grazing:
            gr = np.deg2rad(g)
            tx = 1e5 * np.array([0.0, -np.cos(gr), np.sin(gr)])
            vals = []
            for seed in range(3):
                z = _gaussian_surface(n, 1.0, corr, s * corr / np.sqrt(2),
                                      np.random.default_rng(seed))
                f = tr.facets(z, None, tx)
                zc = f.centroid[:, 2] - f.centroid[:, 2].mean()
                keep = (f.centroid[:, 1] - x[0]) > (zc.max() - zc.min()) / np.tan(gr)
                grad = np.stack([-f.normal[:, 0] / f.normal[:, 2],
                                 -f.normal[:, 1] / f.normal[:, 2]])
                w, _, _ = smith_weights(zc, f.n_i, f.n_s, zc.std(), np.cov(grad[:, keep]))
                vals.append((f.lit[keep].mean(), ((f.theta_i < np.pi / 2) * w)[keep].mean()))
            traced.append(np.mean([v[0] for v in vals]))
            analytic.append(np.mean([v[1] for v in vals]))
        gg = np.linspace(1.0, 32.0, 200)
        ax.plot(gg, smith_monostatic(np.deg2rad(90 - gg), s), color=colour,
                label=f"Smith (1967), rms slope {s}")
        ax.plot(grazing, traced, "o", color=colour, label="ray traced (Mitsuba)")
        ax.plot(grazing, analytic, "x", color=colour, ms=8, label="analytic mode + Smith")
    ax.set_xlabel("grazing angle [deg]")
    ax.set_ylabel("lit fraction [-]")
    ax.set_title("Gaussian surfaces (corr. length 8 m, 1 m grid, 3 seeds)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    atomic_savefig(fig, path, dpi=110)
    plt.close(fig)


def box_figure(path: Path) -> None:
    import matplotlib.pyplot as plt
    import trimesh
    from scipy.spatial import ConvexHull

    from seaecho.io.dataset import atomic_savefig
    from seaecho.tracing.scene import ObjectGeometry
    from seaecho.tracing.tracer import FacetTracer

    n = 64
    x = (np.arange(n) - n / 2) * 1.0
    lo, hi = np.array([-6.0, -4.0, -2.0]), np.array([5.0, 3.0, 4.0])
    m = trimesh.creation.box(bounds=[lo, hi])
    box = ObjectGeometry("box", np.asarray(m.vertices, float), np.asarray(m.faces, np.uint32))
    src = np.array([-150.0, -90.0, 40.0])
    f = FacetTracer(x, x, objects=[box]).facets(np.zeros((n, n)), None, src)
    corners = np.array([[a, b] for a in (lo[0], hi[0]) for b in (lo[1], hi[1])])
    s = src[2] / (src[2] - hi[2])
    proj = src[None, :2] + s * (corners - src[None, :2])
    pts = np.vstack([corners, proj])
    poly = pts[ConvexHull(pts).vertices]
    fig, ax = plt.subplots(figsize=(5.6, 5), constrained_layout=True)
    ax.imshow(f.cell_mean("lit"), origin="lower", extent=(x[0], x[-1], x[0], x[-1]),
              cmap="gray", vmin=0, vmax=1, interpolation="nearest")
    ax.plot(*np.vstack([poly, poly[:1]]).T, "r-", lw=1.5, label="analytic shadow polygon")
    ax.add_patch(plt.Rectangle(lo[:2], *(hi - lo)[:2], fill=False, ec="C1", lw=1.5,
                               label="box footprint"))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"lit facets, source at ({src[0]:g}, {src[1]:g}, {src[2]:g}) m")
    ax.legend(loc="upper left", fontsize=8)
    atomic_savefig(fig, path, dpi=110)
    plt.close(fig)


def modes_figure(path: Path) -> None:
    import matplotlib.pyplot as plt

    from seaecho.build import build_engine, build_sea
    from seaecho.config import parse_scene
    from seaecho.io.dataset import atomic_savefig

    hull = Path(__file__).resolve().parents[1] / "scenes" / "meshes" / "motor_boat_10m.ply"
    scene = parse_scene({
        "sea": {"spectrum": "pierson-moskowitz", "wind_speed_m_s": 8.0,
                "wind_direction_deg": 30.0, "size_x_m": 128.0, "nx": 256},
        "ship": {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 10.0,
                 "heading_deg": 35.0},
        "objects": [{"name": "boat", "file": str(hull), "follow_ship": True}],
        "run": {"seed": 1},
    })
    tx, rx = np.array([-300.0, -200.0, 30.0]), np.array([200.0, -250.0, 20.0])
    sea = build_sea(scene)
    # the sea water and the tracing need a carrier: the paper's 10 GHz
    traced = build_engine(scene, sea.state, frequency=10e9, tx_position=tx, rx_position=rx)
    analytic = build_engine(scene, sea.state, frequency=10e9, mode="analytic",
                            tx_position=tx, rx_position=rx)
    ft, fa = traced.facets(0.0), analytic.facets(0.0)
    x, y = sea.x, sea.y
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    for ax, (a, title, cmap, lim) in zip(axes, [
            (ft.cell_mean("visibility"), "ray traced: lit and seen", "gray", (0, 1)),
            (fa.cell_mean("visibility"), "analytic + Smith: lit and seen", "gray", (0, 1)),
            (np.degrees(fa.cell_mean("theta_i") - ft.cell_mean("theta_i")),
             "theta_i analytic - ray traced [deg]", "RdBu_r", (-3, 3))], strict=True):
        im = ax.imshow(a, origin="lower", extent=(x[0], x[-1], y[0], y[-1]), cmap=cmap,
                       vmin=lim[0], vmax=lim[1], interpolation="nearest")
        ax.set_title(title)
        ax.set_xlabel("x (east) [m]")
        ax.set_ylabel("y (north) [m]")
        fig.colorbar(im, ax=ax, shrink=0.8)
    fig.suptitle("U19.5 = 8 m/s, 10 m boat at the centre; Tx (-300, -200, 30) m, "
                 "Rx (200, -250, 20) m")
    atomic_savefig(fig, path, dpi=100)
    plt.close(fig)


def main(argv: list[str]) -> int:
    import matplotlib

    matplotlib.use("Agg")
    out = Path(argv[0] if argv else "docs/figures")
    out.mkdir(parents=True, exist_ok=True)
    smith_figure(out / "tracing_smith.png")
    box_figure(out / "tracing_box_shadow.png")
    modes_figure(out / "tracing_modes.png")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main(sys.argv[1:]))
