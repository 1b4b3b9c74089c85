"""Figures of docs/ship.md: the boat's RCS against aspect, and sea-multipath lobing.

    python examples/ship_signature.py [--out docs/figures] [--step 2] [--density 3]

1. ``ship_boat_rcs_aspect.png``: monostatic RCS (HH, VV) of the paper's 10 m motor boat
   (scenes/meshes/motor_boat_10m.ply, steel) at 10 GHz and 10 deg elevation against the
   aspect (0 deg: seen from the bow), free space above the mean sea (the sea hides the
   hull below the waterline; no multipath), by shooting and bouncing rays.
2. ``ship_multipath_lobing.png``: RCS of a sphere of radius 0.25 m against its height over
   a smooth sea, radar 1 km away and 10 m high (grazing ~0.6 deg): the traced four paths
   against Blake's pattern-propagation factor |1 + Gamma exp(-jk Delta)|^4 times the
   free-space RCS.

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006), "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import trimesh  # noqa: E402

from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.seawater import sea_water_permittivity  # noqa: E402
from seaecho.scattering.fresnel import fresnel_coefficients  # noqa: E402
from seaecho.targets import canonical  # noqa: E402
from seaecho.targets.multipath import mirror  # noqa: E402
from seaecho.tracing.sbr import SBROptions, SeaPlane, TraceMesh, trace_signature  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
F = 10e9
K = 2 * np.pi * F / C0


def _db(x):
    return 10 * np.log10(np.maximum(x, 1e-30))


def rcs_vs_aspect(step: float, density: float, out: Path) -> None:
    m = trimesh.load(ROOT / "scenes" / "meshes" / "motor_boat_10m.ply", process=False)
    hull = TraceMesh.single(m.vertices, m.faces)
    el = np.deg2rad(10.0)
    az = np.arange(0.0, 360.0, step)
    rcs = []
    for a in np.deg2rad(az):
        u = np.array([np.cos(el) * np.cos(a), np.cos(el) * np.sin(a), np.sin(el)])
        tx = 1e5 * u
        sig = trace_signature(hull, tx, tx, F, sea=SeaPlane(),
                              options=SBROptions(rays_per_wavelength=density, cell=0.5),
                              reference=[0, 0, 0])
        rcs.append(sig.rcs)
    rcs = np.array(rcs)
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(az, _db(rcs[:, 0]), label="HH", lw=1)
    ax.plot(az, _db(rcs[:, 3]), label="VV", lw=1, alpha=0.8)
    ax.set_xlabel("aspect [deg] (0: bow on, 90: port beam, 180: stern)")
    ax.set_ylabel("RCS [dBsm]")
    ax.set_title(f"10 m motor boat, 10 GHz, elevation 10 deg, monostatic "
                 f"(SBR, {density:g} rays/lambda, 3 bounces)")
    ax.set_xlim(0, 360)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "ship_boat_rcs_aspect.png", dpi=120)
    plt.close(fig)
    print(f"median RCS HH {np.median(_db(rcs[:, 0])):.1f} dBsm, max "
          f"{_db(rcs[:, 0]).max():.1f} dBsm at {az[np.argmax(rcs[:, 0])]:.0f} deg")


def lobing(out: Path) -> None:
    eps = complex(sea_water_permittivity(F, 20.0, 35.0))
    v, f = canonical.sphere(0.25, 5)
    tx = np.array([-1000.0, 0.0, 10.0])
    heights = np.arange(0.5, 5.01, 0.05)
    traced, free = [], []
    for h in heights:
        mesh = TraceMesh.single(v + [0, 0, h], f)
        opts = SBROptions(rays_per_wavelength=3, cell=0.5)
        traced.append(trace_signature(mesh, tx, tx, F, options=opts,
                                      sea=SeaPlane(eps_r=eps), reference=[0, 0, h]).rcs)
        free.append(trace_signature(mesh, tx, tx, F, options=opts, reference=[0, 0, h]).rcs)
    traced, free = np.array(traced), np.array(free)
    hf = np.linspace(heights[0], heights[-1], 1000)
    p = np.stack([np.zeros_like(hf), np.zeros_like(hf), hf], -1)
    r_d = np.linalg.norm(p - tx, axis=-1)
    r_i = np.linalg.norm(p - mirror(tx), axis=-1)
    psi = np.arcsin((tx[2] + hf) / r_i)
    r_h, r_v = fresnel_coefficients(np.sin(psi), eps)
    sigma0 = np.pi * 0.25**2
    fig, ax = plt.subplots(figsize=(8, 4))
    for ch, r, name in ((0, r_h, "HH"), (3, r_v, "VV")):
        f4 = np.abs(1 + (r_d / r_i) * r * np.exp(-1j * K * (r_i - r_d))) ** 4
        ax.plot(hf, _db(f4 * sigma0), lw=1, label=f"{name}: Blake, pi a^2 |F|^4")
        ax.plot(heights, _db(traced[:, ch]), ".", ms=4, label=f"{name}: SBR, four paths")
    ax.plot(heights, _db(free[:, 0]), "k--", lw=1, label="SBR, free space")
    ax.set_ylim(-40, 22)
    ax.set_xlabel("sphere centre height above the mean sea [m]")
    ax.set_ylabel("RCS [dBsm]")
    ax.set_title("Sphere a = 0.25 m over a smooth sea, radar 1 km away at 10 m, 10 GHz")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, ncol=3, loc="upper center")
    fig.tight_layout()
    fig.savefig(out / "ship_multipath_lobing.png", dpi=120)
    plt.close(fig)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "figures")
    ap.add_argument("--step", type=float, default=2.0, help="aspect step [deg]")
    ap.add_argument("--density", type=float, default=3.0, help="rays per wavelength")
    ap.add_argument("--only", choices=("lobing", "aspect"), default=None)
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    if args.only != "aspect":
        lobing(args.out)
    if args.only != "lobing":
        rcs_vs_aspect(args.step, args.density, args.out)


if __name__ == "__main__":
    main()
