"""The paper's Fig. 4: blended sigma_mn over (theta_s, phi_s) for theta_i = 39 deg.

    python examples/fig4_bistatic_map.py [--out docs/gallery] [--quick]

Writes ``scattering_fig4.png``: theta_i = 39 deg, phi_i = 0, theta_s = 0..89 deg,
phi_s = 0..180 deg, U19.5 = 4.53 m/s, wind direction psi = 0, 10 GHz, 20 degC, 35 psu,
Pierson-Moskowitz + Longuet-Higgins (s = 1) as in the paper; the Kirchhoff / SPM blend of
eqs 10-11, four channels. ``--quick``: a 10 deg grid instead of 1 x 2 deg.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from _gallery import db, options, save

import seaecho

SEA = {"spectrum": "pierson-moskowitz", "spreading": "longuet-higgins", "spreading_s": 1.0}


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    theta_s = np.arange(0.0, 89.5, 10.0 if args.quick else 1.0)
    phi_s = np.arange(0.0, 180.5, 10.0 if args.quick else 2.0)
    s = seaecho.sigma("blend", theta_i_deg=39.0, theta_s_deg=theta_s, phi_s_deg=phi_s, **SEA)
    values = db(s.values)  # (theta_s, phi_s, polarisation)
    top = values.max()
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(9.0, 5.6), constrained_layout=True,
                             subplot_kw={"projection": "polar"})
    ps, ts = np.meshgrid(np.radians(phi_s), theta_s)
    for c, ax in enumerate(axes.flat):
        im = ax.pcolormesh(ps, ts, values[..., c], shading="auto", vmin=top - 60, vmax=top,
                           cmap="viridis")
        ax.set_thetamin(0)
        ax.set_thetamax(180)
        ax.set_title(f"sigma_{s['polarisation'].values[c]}", fontsize=10, pad=-10)
        ax.set_rticks([20, 40, 60, 80])
        ax.tick_params(labelsize=7)
    fig.colorbar(im, ax=axes, label="sigma [dB]", shrink=0.8)
    fig.suptitle("blend (eqs 10-11), theta_i = 39 deg, phi_i = 0, U19.5 = 4.53 m/s, psi = 0, "
                 "10 GHz; angle: phi_s [deg], radius: theta_s [deg]", fontsize=9)
    return [save(fig, args.out, "scattering_fig4.png")]


if __name__ == "__main__":
    main()
