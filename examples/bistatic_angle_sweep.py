"""Beyond the paper: the sea's bistatic sigma_mn swept over the scattering direction.

    python examples/bistatic_angle_sweep.py [--out docs/gallery] [--paper | --quick]

Writes ``bistatic_angle_sweep.png`` (``seaecho.sigma``, the blend of the paper's eqs
10-11, Elfouhaily spectrum, 10 GHz, 20 degC, 35 psu, wind towards +x), theta_i = 40 deg:

* (a) in the plane of incidence, theta_s from backscatter (left, phi_s = 180 deg) through
  nadir to forward scatter (right, phi_s = 0): the specular peak at theta_s = theta_i
  widens with the wind (steeper slopes), the backscatter floor rises;
* (b) out of the plane, theta_s = 40 deg against phi_s: the cross-polarised HV, zero in
  the plane (phi_s = 0, 180 deg) by reflection symmetry, largest a few tens of degrees
  off the forward direction;
* (c) the co-polarised ratio VV / HH on the same cut: HH's first-order (SPM) term
  vanishes near phi_s = 90 deg, where the ratio peaks.

For U19.5 = 3, 7 and 12 m/s. ``--quick``: a 5 deg grid instead of 1 deg (``--paper`` is
the default grid: the figure is not from the paper).

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

WINDS = (3.0, 7.0, 12.0)  # U19.5 [m/s]
THETA_I = 40.0  # [deg]


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    step = 5.0 if args.quick else 1.0
    theta_s = np.arange(0.0, 89.0, step)
    phi_s = np.arange(0.0, 180.0 + step / 2, step)
    import matplotlib.pyplot as plt

    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(14.0, 4.4), constrained_layout=True)
    with warnings.catch_warnings():
        # the blend is the model meant for the whole hemisphere: its parts' domain notices
        # (Kirchhoff far from specular, SPM on long waves) are expected here
        warnings.simplefilter("ignore", ValidityWarning)
        for i, u in enumerate(WINDS):
            back = seaecho.sigma(theta_i_deg=THETA_I, theta_s_deg=theta_s, phi_s_deg=180.0,
                                 wind_speed_m_s=u)
            fwd = seaecho.sigma(theta_i_deg=THETA_I, theta_s_deg=theta_s, phi_s_deg=0.0,
                                wind_speed_m_s=u)
            x = np.concatenate([-theta_s[::-1], theta_s])
            for pol, style in (("VV", "-"), ("HH", "--")):
                y = np.concatenate([back.sel(polarisation=pol).values[::-1],
                                    fwd.sel(polarisation=pol).values])
                ax1.plot(x, db(y), style, color=f"C{i}",
                         label=f"{pol}, U19.5 = {u:g} m/s" if pol == "VV" or i == 0 else None)
            out = seaecho.sigma(theta_i_deg=THETA_I, theta_s_deg=THETA_I, phi_s_deg=phi_s,
                                wind_speed_m_s=u)
            ax2.plot(phi_s, db(out.sel(polarisation="HV")), color=f"C{i}",
                     label=f"U19.5 = {u:g} m/s")
            ratio = out.sel(polarisation="VV") / out.sel(polarisation="HH")
            ax3.plot(phi_s, db(ratio), color=f"C{i}", label=f"U19.5 = {u:g} m/s")
    ax1.axvline(THETA_I, color="0.5", lw=0.8)
    ax1.axvline(-THETA_I, color="0.5", lw=0.8, ls=":")
    ax1.set_xlabel("theta_s [deg] (< 0: towards the radar, phi_s = 180 deg)")
    ax1.set_ylabel("sigma [dB]")
    ax1.set_ylim(-60, 25)
    ax1.set_title(f"(a) plane of incidence, theta_i = {THETA_I:g} deg", fontsize=10)
    ax1.legend(fontsize=7)
    ax2.set_xlabel("phi_s [deg]")
    ax2.set_ylabel("sigma_HV [dB]")
    ax2.set_ylim(-70, 0)
    ax2.set_title(f"(b) cross-pol, theta_s = theta_i = {THETA_I:g} deg", fontsize=10)
    ax2.legend(fontsize=7)
    ax3.set_xlabel("phi_s [deg]")
    ax3.set_ylabel("sigma_VV / sigma_HH [dB]")
    ax3.set_ylim(-30, 60)
    ax3.set_title("(c) co-pol ratio, same cut", fontsize=10)
    ax3.legend(fontsize=7)
    for ax in (ax1, ax2, ax3):
        ax.grid(True, alpha=0.3)
    fig.suptitle("Bistatic sigma_mn of the sea (blend, eqs 10-11), Elfouhaily spectrum, "
                 "10 GHz, wind towards +x", fontsize=10)
    return [save(fig, args.out, "bistatic_angle_sweep.png")]


if __name__ == "__main__":
    main()
