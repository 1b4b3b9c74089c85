"""Sea clutter of a scanning X-band radar at low grazing against the published models.

Run: ``python examples/low_grazing_clutter.py [--part nrcs|ppi|edge|scenes|all] [--quick]
[--multipath] [--no-apron] [--seeds N] [OUTDIR]`` (default ``all`` into
``docs/figures``). Every number of docs/scanning.md's "Validation at low grazing" and
"Propagation over the sea" comes from here.

``--multipath`` turns on the sea's two-ray propagation factor (``[propagation]
multipath = "two-ray"``, ``seaecho.radar.propagation``) with its reflected legs shadowed
by the waves (``multipath_shadowing``, the default): part 1 adds the apparent NRCS
that a radar 35 m up (at h / tan psi) sees, each facet's sigma_mn weighted by
|F_m F_n|^2 at its own height (``low_grazing_sigma0_multipath.csv``); part 2 runs the
sea with the factor and calibrates by the target in free space, so that the PPI's
sigma0 is the apparent one, as the published models' (``low_grazing_ppi_multipath.csv``,
``low_grazing_falloff_multipath.csv``). Part 2 traces the tile with its periodic apron
(``[tracing] periodic_apron``); ``--no-apron``: the tile alone (``*_alone.csv``).

3. **The tile's edge** (``--part edge``): the run's facet NRCS map (ray-traced
   occlusion) in the quarter of the tile nearest the radar against the farthest
   quarter, at 0.3, 0.5 and 1 deg (the PPI part's radar, sea state 4, eight
   realisations), the tile traced alone and with its apron
   (``low_grazing_tile_edge.csv``).
4. **The apron in the bundled scenes** (``--part scenes``): the visible fraction and the
   mean NRCS of Simulations 1-4 (the ``paper_sim*`` scenes) and of the low-grazing
   scenes without and with the apron (``low_grazing_apron_scenes.csv``).

1. **Per-facet NRCS** (``--part nrcs``): the simulation's sea NRCS at 9.4 GHz, grazing
   0.3-3 deg, sea states 2-5 (U10 = 4.5, 7, 10, 12.5 m/s, ``tests/reference_models.py``),
   HH and VV: the facet sums of one Elfouhaily surface (256 m tile, 1 m grid, breaking
   zones, Smith's shadowing; ``sigma0_facets_vs_grazing.simulated``, averaged over the
   looks upwind, crosswind (x2) and downwind) beside the NRL model (Gregers-Hansen &
   Mital 2012), the GIT model (Horst, Dyer & Tuley 1978) and Nathanson's table (1991).
   Writes ``low_grazing_sigma0.csv`` and ``low_grazing_sigma0.png``.
2. **From the PPI** (``--part ppi``): the coastal VTS scene's radar (35 m up, 2 m Taylor
   antenna, 100 ns pulse, 9.41 GHz), flat Earth, no targets, no noise, HH and VV, sea
   state 4 on a 128 m tile at 1, 2, 4 and 8 km (grazing 2.0-0.25 deg), one sector scan
   over the tile, four sea realisations per range. The PPI's energy (the
   range-compressed power summed over the rays and the gates: the two-way azimuth
   pattern integrated over the scan) is calibrated by the run of a 1 m^2 point target at
   the tile's centre (the radar equation with sigma = 1 m^2, through the same antenna,
   scan and range compression), and divided by the tile's area weighted by (R_0 / R)^4:

       sigma0_PPI = (E_sea / E_target) x 1 m^2 / sum_f A_f (R_0 / R_f)^4          (V1)

   beside the run's own facet NRCS map weighted alike (the same surface: the chain from
   facets to PPI must return it) and the references. The clutter power of a
   beam-limited cell (area R theta_az c tau / 2) is then ``sigma0(psi(R)) R^-3``
   (Nathanson 1991, ch. 7; Skolnik 2001, sec. 7.3): the fall-off exponent between
   two ranges is ``3 + log(sigma0_1 / sigma0_2) / log(R_2 / R_1)``, against 3 (a
   constant sigma0) and 7 (below the critical angle, sigma0 ~ psi^4: GIT's
   interference factor). Writes ``low_grazing_ppi.csv``.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
sys.path.insert(0, str(ROOT / "tests"))

from reference_models import (  # noqa: E402
    NATHANSON_XBAND,
    SEA_STATE_WIND,
    git_sigma0,
    nrl_sigma0,
)

F_HZ = 9.4e9
GRAZING_DEG = (0.3, 0.5, 1.0, 2.0, 3.0)
SEA_STATES = (2, 3, 4, 5)
LOOKS_DEG = (0.0, 90.0, 180.0, 270.0)
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"
PPI_RANGES_M = (1000.0, 2000.0, 4000.0, 8000.0)
PPI_SEA_STATE = 4
#: sea realisations averaged per range: a 128 m tile at 8 km is about ten independent
#: cells of K clutter, one realisation a +-2.5 dB estimate
PPI_SEEDS = (3, 4, 5, 6)
RADAR_HEIGHT_M = 35.0
#: realisations of the tile-edge comparison: a quarter of a 128 m tile holds a third of
#: the dominant wave at sea state 4, so one realisation's quarters differ by a factor 2-10
EDGE_SEEDS = tuple(range(3, 11))


def db(x):
    return 10.0 * np.log10(np.maximum(np.asarray(x, dtype=float), 1e-30))


def references(sea_state: int, grazing_deg: float, pol: str, f_ghz: float = F_HZ / 1e9,
               looks_deg=LOOKS_DEG) -> dict[str, float]:
    """NRL, GIT (look-averaged) and Nathanson (at its tabulated angles, else NaN) [dB]."""
    u10 = SEA_STATE_WIND[sea_state]
    git = float(db(np.mean([10 ** (git_sigma0(f_ghz, u10, grazing_deg, pol, p) / 10)
                            for p in looks_deg])))
    nat = NATHANSON_XBAND[(pol, sea_state)].get(float(grazing_deg), float("nan"))
    return {"nrl_db": float(nrl_sigma0(f_ghz, sea_state, grazing_deg, pol)),
            "git_db": git, "nathanson_db": float(nat)}


# --- 1. the per-facet NRCS ---------------------------------------------------------------

def facet_table(sea_states=SEA_STATES, grazing_deg=GRAZING_DEG, seed: int = 1,
                multipath: bool = False, shadowing: bool = True) -> list[dict]:
    from sigma0_facets_vs_grazing import simulated

    rows = []
    for ss in sea_states:
        t = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = simulated(SEA_STATE_WIND[ss], seed=seed, grazing_deg=grazing_deg,
                            f_hz=F_HZ,
                            radar_height_m=RADAR_HEIGHT_M if multipath else None,
                            multipath_shadowing=shadowing)
        sim, apparent = sim if multipath else (sim, None)
        for i, g in enumerate(grazing_deg):
            for pol, j in (("H", 0), ("V", 3)):
                ref = references(ss, g, pol)
                mp = ({"sim_multipath_db": round(float(db(apparent[i, j])), 2)}
                      if multipath else {})
                rows.append({"sea_state": ss, "u10_m_s": SEA_STATE_WIND[ss],
                             "grazing_deg": g, "pol": pol + pol,
                             "sim_db": round(float(db(sim[i, j])), 2), **mp,
                             **{k: round(v, 2) for k, v in ref.items()}})
        print(f"sea state {ss}: {time.perf_counter() - t:.0f} s", flush=True)
    return rows


def print_facet_table(rows: list[dict]) -> None:
    mp = "sim_multipath_db" in rows[0]
    print("| sea state (U10) | grazing [deg] | simulation HH / VV | "
          + ("with multipath HH / VV | " if mp else "")
          + "NRL HH / VV | GIT HH / VV | Nathanson HH / VV |")
    print("|---|---|---|---|---|---|" + ("---|" if mp else ""))
    key = {(r["sea_state"], r["grazing_deg"], r["pol"]): r for r in rows}
    for ss in sorted({r["sea_state"] for r in rows}):
        for g in sorted({r["grazing_deg"] for r in rows}):
            h, v = key[(ss, g, "HH")], key[(ss, g, "VV")]

            def pair(k, h=h, v=v):
                if math.isnan(h[k]):
                    return "-"
                return f"{h[k]:.1f} / {v[k]:.1f}"
            extra = f"{pair('sim_multipath_db')} | " if mp else ""
            print(f"| {ss} ({SEA_STATE_WIND[ss]}) | {g:g} | {pair('sim_db')} | {extra}"
                  f"{pair('nrl_db')} | {pair('git_db')} | {pair('nathanson_db')} |")


def plot_facet_table(rows: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    states = sorted({r["sea_state"] for r in rows})
    fig, axes = plt.subplots(1, len(states), figsize=(4.0 * len(states), 4.2),
                             sharey=True, constrained_layout=True)
    axes = np.atleast_1d(axes)
    gg = np.geomspace(0.2, 4.0, 60)
    for ax, ss in zip(axes, states, strict=True):
        for pol, c in (("H", "C0"), ("V", "C3")):
            sel = sorted((r["grazing_deg"], r["sim_db"]) for r in rows
                         if r["sea_state"] == ss and r["pol"] == pol + pol)
            ax.plot(*np.array(sel).T, "o-", color=c, label=f"simulation {pol}{pol}")
            ax.plot(gg, nrl_sigma0(F_HZ / 1e9, ss, gg, pol), color=c, lw=2.5, alpha=0.35,
                    label=f"NRL {pol}{pol}")
            ax.plot(gg, [references(ss, g, pol)["git_db"] for g in gg], "-.", color=c,
                    lw=0.9, label=f"GIT {pol}{pol}")
            pts = NATHANSON_XBAND[(pol, ss)]
            g = np.array([k for k in sorted(pts) if k <= 4.0])
            ax.plot(g, [pts[k] for k in g], "s", color=c, mfc="none",
                    label=f"Nathanson {pol}{pol}")
        ax.set_xscale("log")
        ax.set_ylim(-90, -25)
        ax.set_xlabel("grazing angle [deg]")
        ax.set_title(f"sea state {ss} (U10 = {SEA_STATE_WIND[ss]} m/s), 9.4 GHz",
                     fontsize=9)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("sigma0 [dB]")
    axes[0].legend(fontsize=6.5, loc="lower right")
    fig.savefig(path, dpi=100)
    plt.close(fig)


# --- 2. from the PPI of a scanning run ---------------------------------------------------

def ppi_scene(range_m: float, sea_state: int = PPI_SEA_STATE, tile_m: float = 128.0,
              n: int = 128, target: bool = False, seed: int = 3, multipath: bool = False,
              apron: bool = False, shadowing: bool = True):
    """The coastal scene's radar, a sector scan over a tile ``range_m`` north of it
    (the sea with the two-ray factor when ``multipath``; the calibration target always
    in free space)."""
    import seaecho
    from seaecho.ocean.wind import u19_5_from_u10

    half_deg = math.degrees(math.atan2(0.5 * tile_m * math.sqrt(2.0), range_m)) + 5.0
    step_deg = 24.0 * 360.0 / 60.0 / 1000.0  # 24 rpm, PRF 1 kHz
    n_pulses = int(math.ceil(2.0 * half_deg / step_deg)) + 1
    ov = {"transmitter.antenna.scan": {"mode": "sector", "rate_rpm": 24.0,
                                       "sector_deg": [half_deg, -half_deg]},
          "transmitter.position_m": [0.0, -range_m, RADAR_HEIGHT_M],
          "radar.n_pulses": n_pulses, "radar.sea_update_pulses": n_pulses,
          "radar.channels": ["HH", "VV"], "radar.thermal_noise": False,
          "radar.window_start_m": range_m - 0.75 * tile_m - 60.0,
          "radar.window_end_m": range_m + 0.75 * tile_m + 60.0,
          "propagation.earth": "flat", "run.seed": seed,
          "tracing.periodic_apron": apron,
          "land": [],  # the open sea: the scene's headland would hide the tile beyond 5 km
          "propagation.multipath": "two-ray" if multipath and not target else "none",
          "propagation.multipath_shadowing": shadowing,
          "sea.size_x_m": tile_m, "sea.nx": n,
          "sea.wind_speed_m_s": float(u19_5_from_u10(SEA_STATE_WIND[sea_state])),
          "targets": ([{"name": "calibration", "position_m": [0.0, 0.0, 0.0],
                        "rcs_m2": 1.0}] if target else [])}
    if target:
        ov["radar.sea_clutter"] = False
    return seaecho.with_overrides(seaecho.load_scene(SCENE), ov)


def edge_table(grazing_deg=(0.3, 0.5, 1.0), sea_state: int = PPI_SEA_STATE,
               tile_m: float = 128.0, n: int = 128, seeds=EDGE_SEEDS) -> list[dict]:
    """The tile-edge under-shadowing: the run's facet NRCS map (ray-traced occlusion) in
    the quarter of the tile nearest the radar against the farthest quarter, the tile
    traced alone and with its periodic apron (``[tracing] periodic_apron``), averaged
    over the sea realisations ``seeds`` [dB]."""
    from seaecho.simulation import Simulation

    rows = []
    for g in grazing_deg:
        range_m = RADAR_HEIGHT_M / math.tan(math.radians(g))
        row = {"grazing_deg": g, "range_m": round(range_m, 1), "sea_state": sea_state}
        for apron in (False, True):
            acc, vis, wall = 0.0, 0.0, 0.0
            for seed in seeds:
                sc = ppi_scene(range_m, sea_state, tile_m, n, seed=seed, apron=apron)
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    sim = Simulation(sc)
                    t = time.perf_counter()
                    truth = sim.sea_truth()  # (pol, y, x): y north, the radar south
                    wall += time.perf_counter() - t
                acc = acc + truth["sigma0"] / len(seeds)
                vis = vis + truth["visibility"] / len(seeds)
            q = acc.shape[1] // 4
            tag = "apron" if apron else "alone"
            for pol, j in (("HH", 0), ("VV", 3)):
                row[f"{tag}_near_{pol}_db"] = round(float(db(acc[j, :q].mean())), 2)
                row[f"{tag}_far_{pol}_db"] = round(float(db(acc[j, -q:].mean())), 2)
                row[f"{tag}_all_{pol}_db"] = round(float(db(acc[j].mean())), 2)
            row[f"{tag}_visible_near"] = round(float(vis[:q].mean()), 4)
            row[f"{tag}_visible_far"] = round(float(vis[-q:].mean()), 4)
            row[f"{tag}_wall_s"] = round(wall / len(seeds), 2)
        rows.append(row)
        print(row, flush=True)
    return rows


APRON_SCENES = ("paper_sim1_bistatic_64m", "paper_sim2_sar_128m_wind55",
                "paper_sim3_sar_128m_wind0", "paper_sim4_sar_500m_u10",
                "ship_low_grazing_80m", "coastal_vts_xband")


def apron_scenes_table(names=APRON_SCENES) -> list[dict]:
    """What the periodic apron changes in the bundled scenes: the visible fraction and the
    mean NRCS of the sea-truth map (the sigma-map pulse), without and with
    ``[tracing] periodic_apron``."""
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation

    rows = []
    for name in names:
        path = ROOT / "scenes" / f"{name}.toml"
        scene = load_scene(path)
        res = []
        for apron in (False, True):
            sc = scene.model_copy(update={"tracing": scene.tracing.model_copy(
                update={"periodic_apron": apron})})
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                truth = Simulation(sc, base_dir=path.parent).sea_truth()
            res.append((truth["sigma0"].mean(axis=(1, 2)), float(truth["visibility"].mean())))
        (s0, v0), (s1, v1) = res
        row = {"scene": name, "visible_alone": round(v0, 6), "visible_apron": round(v1, 6)}
        for j, ch in enumerate(("HH", "HV", "VH", "VV")):
            row[f"change_{ch}_db"] = round(float(db(s1[j]) - db(s0[j])), 4)
        rows.append(row)
        print(row, flush=True)
    return rows


def _energy(ds) -> np.ndarray:
    """Range-compressed energy summed over rays and gates, per channel [W]."""
    c = ds["compressed"].values
    return (np.abs(c) ** 2).sum(axis=(0, 2))


def ppi_sigma0(range_m: float, sea_state: int = PPI_SEA_STATE, tile_m: float = 128.0,
               n: int = 128, seeds=PPI_SEEDS, multipath: bool = False,
               apron: bool = True, shadowing: bool = True) -> dict:
    """Eq (V1): the PPI-calibrated NRCS, HH and VV [linear], and the run's own map,
    both averaged over the sea realisations ``seeds``."""
    import seaecho

    e_sea, s0_map, wall = 0.0, 0.0, 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for seed in seeds:
            t = time.perf_counter()
            sea = seaecho.simulate(ppi_scene(range_m, sea_state, tile_m, n, seed=seed,
                                             multipath=multipath, apron=apron,
                                             shadowing=shadowing),
                                   progress=False)
            wall += time.perf_counter() - t
            e_sea = e_sea + _energy(sea) / len(seeds)
            # (polarisation, y_cell, x_cell): sigma_mn x visibility
            s0_map = s0_map + sea["sigma0"].values / len(seeds)
        tgt = seaecho.simulate(ppi_scene(range_m, sea_state, tile_m, n, target=True),
                               progress=False)
    e_tgt = _energy(tgt)
    # the facets' cells: horizontal area and slant range from the radar
    xc, yc = np.meshgrid(sea["x_cell"].values, sea["y_cell"].values)
    cell = float(sea["x_cell"].values[1] - sea["x_cell"].values[0]) ** 2
    r_f = np.sqrt(xc**2 + (yc + range_m) ** 2 + RADAR_HEIGHT_M**2)
    r_0 = math.hypot(range_m, RADAR_HEIGHT_M)
    w = cell * (r_0 / r_f) ** 4
    pols = list(sea["polarisation"].values)
    out = {"range_m": range_m, "grazing_deg": math.degrees(math.atan2(RADAR_HEIGHT_M,
                                                                       range_m)),
           "sea_state": sea_state, "pulses": int(sea.sizes["pulse"]), "wall_s": wall}
    for ci, ch in enumerate(sea["channel"].values):
        out[f"ppi_{ch}"] = float(e_sea[ci] / e_tgt[ci] * 1.0 / w.sum())
        out[f"map_{ch}"] = float((s0_map[pols.index(ch)] * w).sum() / w.sum())
    return out


def ppi_table(ranges_m=PPI_RANGES_M, sea_state: int = PPI_SEA_STATE, tile_m: float = 128.0,
              n: int = 128, seeds=PPI_SEEDS, multipath: bool = False,
              apron: bool = True, shadowing: bool = True) -> list[dict]:
    rows = []
    for r in ranges_m:
        res = ppi_sigma0(r, sea_state, tile_m, n, seeds, multipath, apron, shadowing)
        row = {"range_m": r, "grazing_deg": round(res["grazing_deg"], 3),
               "sea_state": sea_state, "pulses": res["pulses"],
               "wall_s": round(res["wall_s"], 1)}
        for ch in ("HH", "VV"):
            ref = references(sea_state, res["grazing_deg"], ch[0])
            row.update({f"ppi_{ch}_db": round(float(db(res[f"ppi_{ch}"])), 2),
                        f"map_{ch}_db": round(float(db(res[f"map_{ch}"])), 2),
                        f"nrl_{ch}_db": round(ref["nrl_db"], 2),
                        f"git_{ch}_db": round(ref["git_db"], 2)})
        rows.append(row)
        print(row, flush=True)
    return rows


def falloff_exponents(rows: list[dict]) -> list[dict]:
    """Exponent n of P ~ R^-n of a beam-limited cell between successive ranges."""
    out = []
    for a, b in zip(rows[:-1], rows[1:], strict=True):
        lr = math.log10(b["range_m"] / a["range_m"])
        e = {"from_m": a["range_m"], "to_m": b["range_m"]}
        for ch in ("HH", "VV"):
            for src in ("ppi", "map", "nrl", "git"):
                k = f"{src}_{ch}_db"
                e[f"{src}_{ch}"] = round(3.0 + (a[k] - b[k]) / 10.0 / lr, 2)
        out.append(e)
    return out


def write_csv(rows: list[dict], path: Path) -> None:
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("outdir", nargs="?", default=str(ROOT / "docs" / "figures"))
    ap.add_argument("--part", choices=("nrcs", "ppi", "edge", "scenes", "all"),
                    default="all")
    ap.add_argument("--quick", action="store_true",
                    help="a 64 m tile and two sea states (a smoke run)")
    ap.add_argument("--multipath", action="store_true",
                    help="the sea's two-ray propagation factor (module docstring)")
    ap.add_argument("--no-shadowing", action="store_true",
                    help="with --multipath: the mean sea as the mirror ([propagation] "
                    "multipath_shadowing = false; files *_mean_sea.csv)")
    ap.add_argument("--no-apron", action="store_true",
                    help="part 2: the tile traced alone, without its periodic apron "
                    "([tracing] periodic_apron = false; files *_alone.csv)")
    ap.add_argument("--seeds", type=int, default=len(PPI_SEEDS),
                    help=f"sea realisations per range of part 2 (default {len(PPI_SEEDS)})")
    a = ap.parse_args(argv)
    tag = "_multipath" + ("_mean_sea" if a.no_shadowing else "") if a.multipath else ""
    ppi_tag = tag + ("_alone" if a.no_apron else "")
    out = Path(a.outdir)
    out.mkdir(parents=True, exist_ok=True)
    if a.part in ("nrcs", "all"):
        rows = facet_table(sea_states=(3,) if a.quick else SEA_STATES,
                           grazing_deg=(0.5, 3.0) if a.quick else GRAZING_DEG,
                           multipath=a.multipath, shadowing=not a.no_shadowing)
        write_csv(rows, out / f"low_grazing_sigma0{tag}.csv")
        if not a.multipath:
            plot_facet_table(rows, out / "low_grazing_sigma0.png")
        print_facet_table(rows)
    if a.part in ("scenes", "all"):
        write_csv(apron_scenes_table(), out / "low_grazing_apron_scenes.csv")
    if a.part in ("edge", "all"):
        rows = edge_table(seeds=(3,) if a.quick else EDGE_SEEDS)
        write_csv(rows, out / "low_grazing_tile_edge.csv")
    if a.part in ("ppi", "all"):
        tile, n = (64.0, 64) if a.quick else (128.0, 128)
        ranges = (1000.0, 2000.0) if a.quick else PPI_RANGES_M
        rows = ppi_table(ranges, tile_m=tile, n=n, seeds=(3,) if a.quick else PPI_SEEDS[:a.seeds],
                         multipath=a.multipath, apron=not a.no_apron,
                         shadowing=not a.no_shadowing)
        write_csv(rows, out / f"low_grazing_ppi{ppi_tag}.csv")
        ex = falloff_exponents(rows)
        write_csv(ex, out / f"low_grazing_falloff{ppi_tag}.csv")
        for e in ex:
            print(e)


if __name__ == "__main__":
    main()
