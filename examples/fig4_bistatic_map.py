"""The paper's Fig. 4: blended sigma_mn over (theta_s, phi_s) for theta_i = 39 deg.

Run: ``python examples/fig4_bistatic_map.py [OUTDIR]`` (default ``docs/figures``).
Writes ``scattering_fig4.png``: theta_i = 39 deg, phi_i = 0, theta_s = 0..89 deg,
phi_s = 0..180 deg, U19.5 = 4.53 m/s, wind direction psi = 0, 10 GHz, 20 degC, 35 psu,
Pierson-Moskowitz + Longuet-Higgins (s = 1) as in the paper; the Kirchhoff / SPM blend of
eqs 10-11, four channels.

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

from seaecho.ocean.seawater import sea_water_permittivity  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.scattering.models import sea_sigma  # noqa: E402

CHANNELS = ("HH", "HV", "VH", "VV")


def main(outdir: str = "docs/figures") -> Path:
    f = 10e9
    eps = complex(sea_water_permittivity(f, 20.0, 35.0, model="meissner-wentz"))
    spec = DirectionalSpectrum(spectrum="pierson-moskowitz", spreading="longuet-higgins",
                               u19_5=4.53, wind_direction=0.0, s=1.0)
    theta_s = np.radians(np.arange(0.0, 89.5, 1.0))
    phi_s = np.radians(np.arange(0.0, 180.5, 2.0))
    ts, ps = np.meshgrid(theta_s, phi_s, indexing="ij")
    sigma = sea_sigma("blend", np.radians(39.0), 0.0, ts, ps, f, spec, eps)
    db = 10 * np.log10(np.maximum(sigma, 1e-30))
    top = np.max(db)
    fig, axes = plt.subplots(2, 2, figsize=(9.0, 5.6), constrained_layout=True,
                             subplot_kw={"projection": "polar"})
    for c, ax in enumerate(axes.flat):
        im = ax.pcolormesh(ps, np.degrees(ts), db[..., c], shading="auto",
                           vmin=top - 60, vmax=top, cmap="viridis")
        ax.set_thetamin(0)
        ax.set_thetamax(180)
        ax.set_title(f"sigma_{CHANNELS[c]}", fontsize=10, pad=-10)
        ax.set_rticks([20, 40, 60, 80])
        ax.tick_params(labelsize=7)
    fig.colorbar(im, ax=axes, label="sigma [dB]", shrink=0.8)
    fig.suptitle("blend (eqs 10-11), theta_i = 39 deg, phi_i = 0, U19.5 = 4.53 m/s, psi = 0, "
                 "10 GHz; angle: phi_s [deg], radius: theta_s [deg]", fontsize=9)
    out = Path(outdir) / "scattering_fig4.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out


if __name__ == "__main__":
    print(main(*sys.argv[1:]))
