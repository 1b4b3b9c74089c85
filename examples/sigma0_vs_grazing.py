"""Monostatic sigma0 of seaecho's mean-plane models against published clutter models.

Run: ``python examples/sigma0_vs_grazing.py [OUTDIR]`` (default ``docs/figures``).
Writes ``scattering_sigma0_vs_grazing.png``, four panels, sigma0 averaged over the looks
upwind, crosswind (x2) and downwind, sea water at 20 degC and 35 psu, Elfouhaily spectrum,
U19.5 from U10 by the log profile of seaecho.ocean.wind:

* (a), (b) X band (9.3 GHz), HH and VV against grazing angle for sea states 3 and 5
  (U10 7 and 12.5 m/s): blend, two-scale and two-scale + breaking (Kudryavtsev et al.
  2003) against Nathanson's table (points), the GIT model and the NRL model;
* (c) C band (5.3 GHz) VV against incidence at U10 = 10 m/s against CMOD5.N;
* (d) C-band VV/HH against incidence against Mouche et al. (2005).

The reference models are those of ``tests/reference_models.py`` (with their provenance).
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from reference_models import (  # noqa: E402
    NATHANSON_XBAND,
    SEA_STATE_WIND,
    cmod5n,
    git_sigma0,
    mouche_pr,
    nrl_sigma0,
)
from seaecho.ocean.seawater import sea_water_permittivity  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.ocean.wind import u19_5_from_u10
from seaecho.scattering.models import sea_sigma  # noqa: E402
from seaecho.warnings import ValidityWarning  # noqa: E402

LOOKS_DEG = (0.0, 90.0, 180.0, 270.0)
MODELS = (("blend", ":"), ("two-scale", "--"), ("two-scale+breaking", "-"))


def look_averaged(model: str, f_hz: float, u10: float, inc_deg) -> np.ndarray:
    """Monostatic sigma0 (n, 4) averaged over the four looks; wind towards +x."""
    eps = sea_water_permittivity(f_hz, 20.0, 35.0)
    spec = DirectionalSpectrum(u19_5=float(u19_5_from_u10(u10)))
    th = np.radians(np.asarray(inc_deg, dtype=float))[:, None]
    phi_i = np.pi + np.radians(LOOKS_DEG)[None, :]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        s = sea_sigma(model, th + 0 * phi_i, phi_i, th + 0 * phi_i, phi_i + np.pi, f_hz,
                      spec, eps)
    return s.mean(axis=1)


def _db(x):
    return 10.0 * np.log10(np.maximum(x, 1e-30))


def main(outdir: str = "docs/figures") -> Path:
    fig, axes = plt.subplots(2, 2, figsize=(11.0, 8.5), constrained_layout=True)
    grazing = np.array([1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 30.0, 40.0, 50.0, 60.0])
    for ax, ss in zip(axes[0], (3, 5), strict=True):
        u10 = SEA_STATE_WIND[ss]
        for model, ls in MODELS:
            s = look_averaged(model, 9.3e9, u10, 90.0 - grazing)
            ax.plot(grazing, _db(s[:, 0]), ls, color="C0", label=f"{model} HH")
            ax.plot(grazing, _db(s[:, 3]), ls, color="C3", label=f"{model} VV")
        for pol, c in (("H", "C0"), ("V", "C3")):
            pts = NATHANSON_XBAND[(pol, ss)]
            g = np.array(sorted(pts))
            ax.plot(g, [pts[k] for k in g], "o", color=c, mfc="none",
                    label=f"Nathanson {pol}{pol}")
            git = [np.mean([git_sigma0(9.3, u10, gg, pol, p) for p in LOOKS_DEG])
                   for gg in grazing]
            ax.plot(grazing, git, "-.", color=c, lw=0.8, label=f"GIT {pol}{pol}")
            ax.plot(grazing, nrl_sigma0(9.3, ss, grazing, pol), color=c, lw=2.5, alpha=0.3,
                    label=f"NRL {pol}{pol}")
        ax.set_xscale("log")
        ax.set_xlim(1, 60)
        ax.set_ylim(-70, -5)
        ax.set_xlabel("grazing angle [deg]")
        ax.set_ylabel("sigma0 [dB]")
        ax.set_title(f"X band 9.3 GHz, sea state {ss} (U10 = {u10} m/s)", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0, 0].legend(fontsize=6.5, ncol=2, loc="lower right")

    inc = np.arange(20.0, 60.5, 2.5)
    u10 = 10.0
    ax = axes[1, 0]
    ref = np.mean([cmod5n(u10, p, inc) for p in LOOKS_DEG], axis=0)
    ax.plot(inc, _db(ref), "k-", lw=2.5, alpha=0.4, label="CMOD5.N")
    ax_pr = axes[1, 1]
    ax_pr.plot(inc, _db(np.mean([mouche_pr(inc, p) for p in LOOKS_DEG], axis=0)), "k-", lw=2.5,
               alpha=0.4, label="Mouche et al. (2005)")
    for model, ls in MODELS:
        s = look_averaged(model, 5.3e9, u10, inc)
        ax.plot(inc, _db(s[:, 3]), ls, color="C3", label=f"{model} VV")
        ax_pr.plot(inc, _db(s[:, 3] / s[:, 0]), ls, color="C2", label=model)
    ax.set_xlabel("incidence [deg]")
    ax.set_ylabel("sigma0 VV [dB]")
    ax.set_title("C band 5.3 GHz, U10 = 10 m/s", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax_pr.set_xlabel("incidence [deg]")
    ax_pr.set_ylabel("VV / HH [dB]")
    ax_pr.set_title("C band 5.3 GHz polarisation ratio, U10 = 10 m/s", fontsize=10)
    ax_pr.grid(True, alpha=0.3)
    ax_pr.legend(fontsize=8)
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "scattering_sigma0_vs_grazing.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main(*sys.argv[1:]))
