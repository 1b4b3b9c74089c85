"""The paper's Fig. 3: bistatic sigma_mn against phi_s for Kirchhoff, SPM and the blend.

Run: ``python examples/fig3_bistatic_sigma.py [OUTDIR]`` (default ``docs/figures``).
Writes ``scattering_fig3.png``: theta_i = 20 deg, theta_s = 30 deg, phi_i = 0,
phi_s = 0..180 deg, U19.5 = 4.53 m/s (wind towards +x), 10 GHz, 20 degC, 35 psu,
Pierson-Moskowitz spectrum with Longuet-Higgins s = 1 spreading (paper eqs 5-6) as in the
paper, Gaussian slopes of the waves longer than k/3 for the Kirchhoff part; the
two-scale model (Khenchaf & Airiau) is drawn as a reference in the SPM panel. Each panel
shows HH, HV, VH, VV.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from seaecho.ocean.seawater import sea_water_permittivity  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.scattering.models import sea_sigma  # noqa: E402
from seaecho.warnings import ValidityWarning  # noqa: E402

CHANNELS = ("HH", "HV", "VH", "VV")
STYLES = ("-", "--", ":", "-")


def main(outdir: str = "docs/figures") -> Path:
    f = 10e9
    eps = complex(sea_water_permittivity(f, 20.0, 35.0, model="meissner-wentz"))
    spec = DirectionalSpectrum(spectrum="pierson-moskowitz", spreading="longuet-higgins",
                               u19_5=4.53, wind_direction=0.0, s=1.0)
    phi_s = np.radians(np.arange(0.0, 180.5, 1.0))
    ti, ts = np.radians(20.0), np.radians(30.0)
    with warnings.catch_warnings():
        # Kirchhoff away from specular and SPM over the whole sea are outside their
        # domains: that is the point of the figure (and of the blend).
        warnings.simplefilter("ignore", ValidityWarning)
        panels = {m: sea_sigma(m, ti, 0.0, ts, phi_s, f, spec, eps)
                  for m in ("kirchhoff", "spm", "blend", "two-scale")}
    fig, axes = plt.subplots(3, 1, figsize=(6.4, 9.0), sharex=True, constrained_layout=True)
    titles = {"kirchhoff": "Kirchhoff approximation (GO, eq 7)",
              "spm": "small perturbations (eqs 8-9); grey: two-scale",
              "blend": "interpolation (eqs 10-11)"}
    for ax, model in zip(axes, ("kirchhoff", "spm", "blend"), strict=True):
        db = 10 * np.log10(np.maximum(panels[model], 1e-30))
        for c in range(4):
            ax.plot(np.degrees(phi_s), db[:, c], STYLES[c], label=CHANNELS[c],
                    color=f"C{c}")
        if model == "spm":
            ts_db = 10 * np.log10(np.maximum(panels["two-scale"], 1e-30))
            ax.plot(np.degrees(phi_s), ts_db[:, 0], color="0.6", lw=0.8)
            ax.plot(np.degrees(phi_s), ts_db[:, 3], color="0.6", lw=0.8)
        ax.set_ylim(-60, 20)
        ax.set_ylabel("sigma [dB]")
        ax.set_title(titles[model], fontsize=10)
        ax.grid(True, alpha=0.3)
    axes[0].legend(ncol=4, fontsize=8, loc="lower left")
    axes[-1].set_xlabel("phi_s [deg]")
    fig.suptitle("theta_i = 20 deg, theta_s = 30 deg, phi_i = 0, U19.5 = 4.53 m/s, 10 GHz, "
                 f"eps = {eps.real:.1f}{eps.imag:+.1f}j", fontsize=9)
    out = Path(outdir) / "scattering_fig3.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:]))
