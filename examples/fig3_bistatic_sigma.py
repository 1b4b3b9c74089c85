"""The paper's Fig. 3: bistatic sigma_mn against phi_s for Kirchhoff, SPM and the blend.

    python examples/fig3_bistatic_sigma.py [--out docs/gallery] [--quick]

Writes ``scattering_fig3.png``: theta_i = 20 deg, theta_s = 30 deg, phi_i = 0,
phi_s = 0..180 deg, U19.5 = 4.53 m/s (wind towards +x), 10 GHz, 20 degC, 35 psu,
Pierson-Moskowitz spectrum with Longuet-Higgins s = 1 spreading (paper eqs 5-6) as in the
paper, Gaussian slopes of the waves longer than k/3 for the Kirchhoff part; the
two-scale model (Khenchaf & Airiau) is drawn as a reference in the SPM panel. Each panel
shows HH, HV, VH, VV. ``--quick``: phi_s every 10 deg instead of 1.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
from _gallery import db, options, save

import seaecho
from seaecho.warnings import ValidityWarning

STYLES = ("-", "--", ":", "-")
#: The paper's Fig. 3 sea: Pierson-Moskowitz with Longuet-Higgins s = 1 spreading
#: (U19.5 = 4.53 m/s, 10 GHz, 20 degC, 35 psu are seaecho.sigma's defaults)
SEA = {"spectrum": "pierson-moskowitz", "spreading": "longuet-higgins", "spreading_s": 1.0}


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    phi_s = np.arange(0.0, 180.5, 10.0 if args.quick else 1.0)
    with warnings.catch_warnings():
        # Kirchhoff away from specular and SPM over the whole sea are outside their
        # domains: that is the point of the figure (and of the blend).
        warnings.simplefilter("ignore", ValidityWarning)
        panels = {m: seaecho.sigma(m, theta_i_deg=20.0, theta_s_deg=30.0, phi_s_deg=phi_s,
                                   **SEA) for m in ("kirchhoff", "spm", "blend", "two-scale")}
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(6.4, 9.0), sharex=True, constrained_layout=True)
    titles = {"kirchhoff": "Kirchhoff approximation (GO, eq 7)",
              "spm": "small perturbations (eqs 8-9); grey: two-scale",
              "blend": "interpolation (eqs 10-11)"}
    for ax, model in zip(axes, ("kirchhoff", "spm", "blend"), strict=True):
        s = panels[model]
        for c, pol in enumerate(s["polarisation"].values):
            ax.plot(phi_s, db(s.sel(polarisation=pol)), STYLES[c], label=str(pol),
                    color=f"C{c}")
        if model == "spm":
            for pol in ("HH", "VV"):
                ax.plot(phi_s, db(panels["two-scale"].sel(polarisation=pol)), color="0.6",
                        lw=0.8)
        ax.set_ylim(-60, 20)
        ax.set_ylabel("sigma [dB]")
        ax.set_title(titles[model], fontsize=10)
        ax.grid(True, alpha=0.3)
    axes[0].legend(ncol=4, fontsize=8, loc="lower left")
    axes[-1].set_xlabel("phi_s [deg]")
    a = panels["blend"].attrs
    fig.suptitle("theta_i = 20 deg, theta_s = 30 deg, phi_i = 0, U19.5 = 4.53 m/s, 10 GHz, "
                 f"eps = {a['eps_r_real']:.1f}{a['eps_r_imag']:+.1f}j", fontsize=9)
    return [save(fig, args.out, "scattering_fig3.png")]


if __name__ == "__main__":
    main()
