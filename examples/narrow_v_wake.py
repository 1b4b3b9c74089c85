"""Narrow-V wake in SAR images: arm contrast per channel and arm angle (docs/wake.md).

Runs, end to end (`seaecho run` + image, through :func:`seaecho.api.simulate` and
:func:`seaecho.api.image`), the paper's Simulation 2 (10 m boat, 10 kn, heading 35 deg,
the SAR flying north) with and without ``[ship] narrow_v``, and
``scenes/narrow_v_20m_16kn_along_track.toml`` (20 m boat, 16 kn, sailing north along the
SAR's track) with and without it. On each image it measures, per channel:

* the arms' contrast: mean sigma0 over the predicted arms (cells within 1 m of the lines
  |y'| = x' tan alpha_B, from the end of the near field to the tile's edge) over the mean
  over the open sea [dB];
* the paper's wake-to-sea contrast (``seaecho image``'s, over its Kelvin-arm mask);
* the narrow-V's rise in the arms: the image with it over the image without it, mean over
  the arms [dB] (same seed, so the same speckle);
* the arm angle: on the ratio of the two images, in 4 m bins of distance behind the ship,
  the across-track offset of the column where the ratio (averaged along the bin) peaks,
  on either side within 3 alpha_B of the track, where it rises by 1 dB or more; the slope
  of a line through midship fitted to those offsets.

Writes ``docs/figures/wake_narrow_v.png`` and prints the table of docs/wake.md. About 4-6
minutes on two cores. ``--angles`` prints only the half-angle table (eqs N1, N2).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import numpy as np

from seaecho import api
from seaecho.build import _scene_bragg_wavenumber, build_sea, carrier_frequency
from seaecho.constants import C0
from seaecho.wake.michell import transverse_wavelength
from seaecho.wake.narrow_v import narrow_v_half_angle

ROOT = Path(__file__).resolve().parents[1]
CASES = [
    ("Sim 2: 10 m, 10 kn, heading 35 deg", "scenes/paper_sim2_sar_128m_wind55.toml"),
    ("20 m, 16 kn, along the SAR track", "scenes/narrow_v_20m_16kn_along_track.toml"),
]


def _with_narrow_v(scene, on: bool):
    return scene.model_copy(update={"ship": scene.ship.model_copy(update={"narrow_v": on})})


def _measure(img, scene, img_off) -> dict:
    """Arm contrast (image with the narrow-V) and arm angle (its ratio to the image
    without it: same seed, same speckle, so the ratio isolates the narrow-V)."""
    ship = build_sea(scene).ship
    k_b = _scene_bragg_wavenumber(scene, 2.0 * np.pi * carrier_frequency(scene) / C0)
    alpha_b = float(narrow_v_half_angle(ship.speed, k_b))
    x, y = img["x"].values, img["y"].values
    xs, ys = ship.to_ship_frame(x[None, :], y[:, None], 0.0)
    s, s_off = img["sigma0"].values, img_off["sigma0"].values
    valid = (img["valid"].values.astype(bool) & np.all(np.isfinite(s), axis=0)
             & np.all(np.isfinite(s_off), axis=0))
    tile = img["tile"].values.astype(bool) if "tile" in img else valid
    sea = valid & img["open_sea"].values.astype(bool)
    start = 0.5 * ship.length + 0.5 * transverse_wavelength(ship.speed)
    arm = (valid & tile & (xs > start)
           & (np.abs(np.abs(ys) - xs * np.tan(alpha_b)) <= 1.0))
    paper = api.image_measures(img)
    out = {"alpha_b_deg": np.rad2deg(alpha_b), "k_b": k_b, "channels": {}}
    for c, name in enumerate(str(v) for v in img["channel"].values):
        if name not in ("HH", "VV"):
            continue
        sea_mean = float(s[c][sea].mean())
        arm_db = 10 * np.log10(float(s[c][arm].mean()) / sea_mean) if arm.any() else np.nan
        rise_db = (10 * np.log10(float(s[c][arm].mean()) / float(s_off[c][arm].mean()))
                   if arm.any() else np.nan)
        ratio = s[c] / np.maximum(s_off[c], 1e-30)
        # arm angle: per 4 m bin behind the ship, each side, the offset of the column
        # where the ratio (averaged along the bin) peaks, if it rises by 1 dB or more
        pts = []
        for x0 in np.arange(0.5 * ship.length, xs[tile].max(), 4.0):
            band = valid & tile & (xs >= x0) & (xs < x0 + 4.0)
            for side in (1.0, -1.0):
                lim = 3.0 * (x0 + 4.0) * np.tan(alpha_b) + 1.0
                sel = band & (side * ys > 0.0) & (side * ys < lim)
                if sel.sum() < 8:
                    continue
                off = np.round(np.abs(ys[sel]) / 0.5).astype(int)
                prof = np.bincount(off, ratio[sel]) / np.maximum(np.bincount(off), 1)
                j = int(np.argmax(prof))
                if prof[j] > 10 ** 0.1:
                    pts.append((x0 + 2.0, 0.5 * j))
        if len(pts) >= 3:
            p = np.asarray(pts)
            slope = float(np.sum(p[:, 0] * p[:, 1]) / np.sum(p[:, 0] ** 2))
            angle = float(np.rad2deg(np.arctan(slope)))
        else:
            angle = np.nan
        out["channels"][name] = {"arm_db": arm_db, "rise_db": rise_db,
                                 "paper_db": paper[name].get("contrast_db", np.nan),
                                 "angle_deg": angle, "n_bins": len(pts),
                                 "x_max": float(np.max(np.asarray(pts)[:, 0])) if pts
                                 else np.nan}
    return out


def angle_table() -> None:
    """Eqs N1-N2: half-angle of the arms [deg] per band and ship speed (``--angles``)."""
    from seaecho.constants import KNOT

    bands = [("L 1.275 GHz, 23 deg (SEASAT)", 1.275e9, 23.0), ("C 5.3 GHz, 23 deg", 5.3e9, 23.0),
             ("X 9.65 GHz, 30 deg", 9.65e9, 30.0), ("X 10 GHz, 45 deg (Sim 2)", 10.0e9, 45.0)]
    speeds_kn = (5.0, 10.0, 16.0, 20.0, 30.0)
    print("| band, incidence | k_B [rad/m] | " + " | ".join(f"{v:g} kn" for v in speeds_kn)
          + " | e-fold of the arms' energy V / (4 nu k_B^2) at 16 kn [m] |")
    print("|---|---|" + "---|" * (len(speeds_kn) + 1))
    from seaecho.constants import NU_SEA_WATER

    for name, f, inc in bands:
        k_b = 2.0 * (2.0 * np.pi * f / C0) * np.sin(np.deg2rad(inc))
        cells = " | ".join(f"{np.rad2deg(narrow_v_half_angle(v * KNOT, k_b)):.2f}"
                           for v in speeds_kn)
        print(f"| {name} | {k_b:.1f} | {cells} | "
              f"{16 * KNOT / (4 * NU_SEA_WATER * k_b**2):.0f} |")


def main() -> None:
    if "--angles" in sys.argv:
        angle_table()
        return
    rows, images = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for label, path in CASES:
            scene = api.load_scene(ROOT / path)
            imgs = {}
            for on in (False, True):
                sc = _with_narrow_v(scene, on)
                raw = api.simulate(sc, path=Path(tmp) / "raw.nc", progress=False,
                                   base_dir=(ROOT / path).parent)
                imgs[on] = (api.image(raw), sc)
            m_off = _measure(imgs[False][0], imgs[False][1], imgs[False][0])
            m = _measure(imgs[True][0], imgs[True][1], imgs[False][0])
            rows.append((label, m_off, m))
            images.append((label, imgs[True][0], imgs[True][1], m, imgs[False][0]))
            print(label, m_off, m, file=sys.stderr, flush=True)
    print("| scene | k_B [rad/m] | alpha_B [deg] | arms / sea, off: HH, VV [dB] | "
          "arms / sea, on [dB] | rise in the arms, on / off [dB] | paper's contrast, "
          "off / on: HH, VV [dB] | arm angle from on / off, HH, VV [deg] (bins, to x') |")
    print("|---|---|---|---|---|---|---|---|")
    for label, m_off, m in rows:
        ch, ch0 = m["channels"], m_off["channels"]

        def f(key, fmt, ch):
            return ", ".join(fmt.format(ch[c][key]) if np.isfinite(ch[c][key]) else "none"
                             for c in ("HH", "VV"))

        ang = ", ".join(f"{ch[c]['angle_deg']:.2f} ({ch[c]['n_bins']}, {ch[c]['x_max']:.0f} m)"
                        if np.isfinite(ch[c]["angle_deg"]) else "none" for c in ("HH", "VV"))
        print(f"| {label} | {m['k_b']:.0f} | {m['alpha_b_deg']:.2f} | "
              f"{f('arm_db', '{:+.1f}', ch0)} | {f('arm_db', '{:+.1f}', ch)} | "
              f"{f('rise_db', '{:+.2f}', ch)} | {f('paper_db', '{:+.1f}', ch0)} / "
              f"{f('paper_db', '{:+.1f}', ch)} | {ang} |")
    _figure(images)


def _figure(images) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(images), figsize=(6 * len(images), 10.8))
    for ax, (_, img, scene, _, img_off) in zip(axes[1], images, strict=True):
        c = [str(v) for v in img["channel"].values].index("VV")
        x, y = img["x"].values, img["y"].values
        r = 10 * np.log10(np.maximum(img["sigma0"].values[c], 1e-30)
                          / np.maximum(img_off["sigma0"].values[c], 1e-30))
        im = ax.pcolormesh(x, y, r, vmin=-3, vmax=10, cmap="magma", shading="auto")
        ship = build_sea(scene).ship
        p = ship.position(0.0)
        end = p - 60.0 * ship.direction  # 60 m astern
        ax.set_xlim(min(p[0], end[0]) - 10, max(p[0], end[0]) + 10)
        ax.set_ylim(min(p[1], end[1]) - 10, max(p[1], end[1]) + 10)
        ax.set_aspect("equal")
        ax.set_title("VV sigma0 with / without the narrow-V [dB]", fontsize=9)
        ax.set_xlabel("x east [m]")
        fig.colorbar(im, ax=ax, shrink=0.8)
    for ax, (label, img, scene, m, _) in zip(axes[0], images, strict=True):
        c = [str(v) for v in img["channel"].values].index("VV")
        x, y = img["x"].values, img["y"].values
        s = 10 * np.log10(np.maximum(img["sigma0"].values[c], 1e-12))
        im = ax.pcolormesh(x, y, s, vmin=-45, vmax=0, cmap="gray", shading="auto")
        ship = build_sea(scene).ship
        a = np.deg2rad(m["alpha_b_deg"])
        r = np.linspace(0.0, 200.0, 50)
        p = ship.position(0.0)
        for side in (1, -1):
            ang = ship.heading + np.pi - side * a
            ax.plot(p[0] + r * np.cos(ang), p[1] + r * np.sin(ang), "r--", lw=0.8)
        tile = img["tile"].values
        ax.contour(x, y, tile, levels=[0.5], colors="y", linewidths=0.6)
        ax.set_xlim(x.min(), x.max())
        ax.set_ylim(y.min(), y.max())
        ax.set_aspect("equal")
        ax.set_title(f"{label}\nVV sigma0 [dB], narrow-V on; dashed: alpha_B = "
                     f"{m['alpha_b_deg']:.2f} deg", fontsize=9)
        ax.set_xlabel("x east [m]")
        ax.set_ylabel("y north [m]")
        fig.colorbar(im, ax=ax, shrink=0.8)
    fig.tight_layout()
    out = ROOT / "docs" / "figures" / "wake_narrow_v.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
