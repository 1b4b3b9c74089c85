"""The paper's Fig. 5: Pierson-Moskowitz spectra for wind speeds in a geometric progression.

    python examples/fig5_pm_spectra.py [--out docs/gallery] [--quick]

Writes ``ocean_fig5_pm_spectra.png``: the omnidirectional wavenumber spectrum S(K) of
Pierson & Moskowitz (paper eq 5, a0 = 8.1e-3, with the standard factor 1/2,
docs/ocean.md) for U19.5 = 2.5, 5, 10 and 20 m/s (factor a = 2), in log-log axes. The
paper's invariant (eq 14): multiplying U by a moves the curve by (-2 log a, +6 log a),
since S(K / a^2; a U) = a^6 S(K; U); the dotted curves are the 2.5 m/s spectrum moved so,
on top of the computed ones. Each curve's peak K_p = sqrt(2 b0 / 3) g / U^2 and H_s =
0.209 U^2 / g are marked (``seaecho.wave_spectrum``). ``--quick``: 200 wavenumbers instead of 2000.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from _gallery import options, save

import seaecho

WINDS = (2.5, 5.0, 10.0, 20.0)  # U19.5 [m/s], factor a = 2 (the paper's choice)


def main(argv: list[str] | None = None) -> list[Path]:
    args = options(__doc__, argv)
    import matplotlib.pyplot as plt

    k = np.geomspace(1e-3, 1e2, 200 if args.quick else 2000)
    fig, ax = plt.subplots(figsize=(7.0, 4.6), constrained_layout=True)
    base = seaecho.wave_spectrum(k, wind_speed_m_s=WINDS[0], spectrum="pierson-moskowitz")
    for i, u in enumerate(WINDS):
        s = seaecho.wave_spectrum(k, wind_speed_m_s=u, spectrum="pierson-moskowitz")
        hs, kp = s.attrs["significant_wave_height_m"], s.attrs["peak_wavenumber_rad_m"]
        ax.loglog(k, s, color=f"C{i}", label=f"U19.5 = {u:g} m/s: H_s = {hs:.2f} m, "
                  f"K_p = {kp:.3g} rad/m")
        peak = seaecho.wave_spectrum(kp, wind_speed_m_s=u, spectrum="pierson-moskowitz")
        ax.plot(kp, float(peak), "o", color=f"C{i}", ms=4)
        if i:  # eq 14: the 2.5 m/s curve moved by (-2 log a, +6 log a), a = u / 2.5
            a = u / WINDS[0]
            ax.loglog(k / a**2, base * a**6, ":", color="k", lw=1.0)
    ax.set_ylim(1e-12, 1e4)
    ax.set_xlim(k[0], k[-1])
    ax.set_xlabel("wavenumber K [rad/m]")
    ax.set_ylabel("S(K) [m^3]")
    ax.set_title("Pierson-Moskowitz (a0 = 8.1e-3): dots = peaks K_p, dotted = the "
                 "2.5 m/s curve moved by eq 14", fontsize=9)
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8, loc="lower left")
    return [save(fig, args.out, "ocean_fig5_pm_spectra.png")]


if __name__ == "__main__":
    main()
