"""Monostatic sigma0 of the *simulation* (facet sums) beside the mean-plane models.

Run: ``python examples/sigma0_facets_vs_grazing.py [OUTDIR]`` (default ``docs/figures``).
Writes ``scattering_sigma0_facets_vs_grazing.png``: X band (9.3 GHz), sea states 3 and 5
(U10 = 7 and 12.5 m/s), HH and VV against grazing angle, averaged over the looks upwind,
crosswind (x2) and downwind. The simulation's sigma0 is the sum over the facets of one
surface realisation (Elfouhaily spectrum and spreading, 256 m tile, 1 m grid: the
unresolved waves are carried statistically, and sigma0 does not depend on the grid,
docs/scattering.md) of area x visibility x sigma_mn (eqs P1-P7: blend, unresolved-tilt
average, breaking zones on the crests of largest downward acceleration), per unit
horizontal area, for a distant radar (plane wave); visibility: the facing test times
Smith's shadowing (analytic facets), so that the low-grazing fall-off of shadowing is in
it. Beside it: the mean-plane two-scale + breaking model (``seaecho sigma``), Nathanson's
table, the GIT and the NRL models (``tests/reference_models.py``).
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
    git_sigma0,
    nrl_sigma0,
)
from seaecho.build import build_sea, build_sea_model  # noqa: E402
from seaecho.config import parse_scene  # noqa: E402
from seaecho.geometry.facets import analytic_facets  # noqa: E402
from seaecho.geometry.mesh import to_facets  # noqa: E402
from seaecho.ocean.seawater import sea_water_permittivity  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402
from seaecho.ocean.wind import u19_5_from_u10  # noqa: E402
from seaecho.scattering.breaking import breaking_placement  # noqa: E402
from seaecho.scattering.facet import facet_sigma  # noqa: E402
from seaecho.scattering.models import sea_sigma  # noqa: E402
from seaecho.warnings import ValidityWarning  # noqa: E402

LOOKS_DEG = (0.0, 90.0, 180.0, 270.0)
GRAZING = np.array([1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0])
F = 9.3e9
SIZE, N = 256.0, 256


def simulated(u10: float, seed: int = 1, spectrum: str = "elfouhaily",
              grazing_deg=GRAZING, f_hz: float = F, radar_height_m: float | None = None,
              multipath_shadowing: bool = False) -> np.ndarray:
    """Facet-sum sigma0 (grazing, 4) averaged over the four looks [m^2/m^2] at the
    carrier ``f_hz`` [Hz].

    With ``radar_height_m``, also the apparent sigma0 that a radar at that height (at the
    ground distance h / tan psi from the tile's centre, flat Earth) sees through the
    sea's two-ray factors (``[propagation] multipath = "two-ray"``,
    :class:`seaecho.radar.propagation.TwoRay`): each facet's sigma_mn weighted by
    |F_m F_n|^2 of its own height; returns (plain, apparent). ``multipath_shadowing``:
    the reflected legs shadowed by the waves (``[propagation] multipath_shadowing``)."""
    grazing_deg = np.asarray(grazing_deg, dtype=float)
    sc = parse_scene({
        "sea": {"spectrum": spectrum, "spreading": "elfouhaily",
                "wind_speed_m_s": float(u19_5_from_u10(u10)), "size_x_m": SIZE, "nx": N},
        "run": {"seed": seed},
        "scattering": {"model": "blend+breaking"},
        "tracing": {"mode": "analytic"},
    })
    sea = build_sea(sc)
    model = build_sea_model(sc, f_hz)
    st = sea.state(0.0)
    acc = to_facets(sea.kinematics(0.0).acceleration[..., 2]).reshape(-1)
    out = np.zeros((grazing_deg.size, 4))
    apparent = np.zeros((grazing_deg.size, 4))
    two_ray = None
    if radar_height_m is not None:
        from seaecho.build import sea_mirror, sea_slope_covariance
        from seaecho.constants import C0
        from seaecho.radar.propagation import TwoRay

        two_ray = TwoRay(C0 / f_hz, *sea_mirror(sc, f_hz), slope_cov=(
            sea_slope_covariance(sc, f_hz) if multipath_shadowing else None))
    area_h = (SIZE * (N - 1) / N) ** 2
    for i, g in enumerate(np.radians(grazing_deg)):
        for look in np.radians(LOOKS_DEG):
            # the radar looks towards pi + look from the wind: upwind for look = 0
            d = np.array([np.cos(g) * np.cos(look), np.cos(g) * np.sin(look), np.sin(g)])
            tx = 1e6 * d  # far away: a plane wave
            f = analytic_facets(st.x, st.y, st.elevation, st.slope_x, st.slope_y, None, tx,
                                shadowing="smith")
            q = breaking_placement(-acc, f.area, model.breaking.q)
            s = facet_sigma(f.n_i, f.n_s, f.normal, model.facet_model, local=f,
                            breaking_fraction=q)
            out[i] += (f.area * f.visibility) @ s / area_h / len(LOOKS_DEG)
            if two_ray is not None:  # the radar on the look's line, h / tan psi away
                radar = d * radar_height_m / np.sin(g)
                vis = f.visibility > 0  # the factors of the facets that echo
                fh, fv = two_ray.factors(radar, f.centroid[vis])
                fp = np.stack([fh, fv], axis=-1)  # (K, (h, v))
                w = np.abs(fp[:, [0, 0, 1, 1]] * fp[:, [0, 1, 0, 1]]) ** 2  # HH HV VH VV
                apparent[i] += ((f.area * f.visibility)[vis] @ (s[vis] * w) / area_h
                                / len(LOOKS_DEG))
    return out if two_ray is None else (out, apparent)


def mean_plane(model: str, u10: float) -> np.ndarray:
    eps = sea_water_permittivity(F, 20.0, 35.0)
    spec = DirectionalSpectrum(u19_5=float(u19_5_from_u10(u10)))
    th = np.radians(90.0 - GRAZING)[:, None]
    phi_i = np.pi + np.radians(LOOKS_DEG)[None, :]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        s = sea_sigma(model, th + 0 * phi_i, phi_i, th + 0 * phi_i, phi_i + np.pi, F, spec,
                      eps)
    return s.mean(axis=1)


def _db(x):
    return 10.0 * np.log10(np.maximum(x, 1e-30))


def main(outdir: str = "docs/figures") -> Path:
    fig, axes = plt.subplots(1, 2, figsize=(12.0, 4.6), constrained_layout=True)
    for ax, ss in zip(axes, (3, 5), strict=True):
        u10 = SEA_STATE_WIND[ss]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = simulated(u10)
        mp = mean_plane("two-scale+breaking", u10)
        print(f"sea state {ss}: grazing {GRAZING.tolist()}")
        print("  simulation HH " + " ".join(f"{v:6.1f}" for v in _db(sim[:, 0])))
        print("  simulation VV " + " ".join(f"{v:6.1f}" for v in _db(sim[:, 3])))
        print("  mean plane HH " + " ".join(f"{v:6.1f}" for v in _db(mp[:, 0])))
        print("  mean plane VV " + " ".join(f"{v:6.1f}" for v in _db(mp[:, 3])))
        for pol, c, j in (("H", "C0", 0), ("V", "C3", 3)):
            ax.plot(GRAZING, _db(sim[:, j]), "o-", color=c, label=f"simulation {pol}{pol}")
            ax.plot(GRAZING, _db(mp[:, j]), "--", color=c,
                    label=f"two-scale+breaking {pol}{pol}")
            pts = NATHANSON_XBAND[(pol, ss)]
            g = np.array(sorted(pts))
            ax.plot(g, [pts[k] for k in g], "s", color=c, mfc="none",
                    label=f"Nathanson {pol}{pol}")
            git = [np.mean([git_sigma0(9.3, u10, gg, pol, p) for p in LOOKS_DEG])
                   for gg in GRAZING]
            ax.plot(GRAZING, git, "-.", color=c, lw=0.8, label=f"GIT {pol}{pol}")
            ax.plot(GRAZING, nrl_sigma0(9.3, ss, GRAZING, pol), color=c, lw=2.5, alpha=0.3,
                    label=f"NRL {pol}{pol}")
        ax.set_xscale("log")
        ax.set_xlim(0.9, 65)
        ax.set_ylim(-75, -5)
        ax.set_xlabel("grazing angle [deg]")
        ax.set_ylabel("sigma0 [dB]")
        ax.set_title(f"X band 9.3 GHz, sea state {ss} (U10 = {u10} m/s)", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=6.5, ncol=2, loc="lower right")
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "scattering_sigma0_facets_vs_grazing.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main(*sys.argv[1:]))
