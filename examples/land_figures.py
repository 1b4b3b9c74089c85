"""Figures and numbers of docs/land.md: the coastal scene's PPI with its coast, and the
land clutter against the radar equation.

Run: ``python examples/land_figures.py [OUTDIR] [--quick]`` (default ``docs/figures``).
Writes

- ``land_ppi_revolution.png``: a revolution of ``scenes/coastal_vts_xband.toml`` with
  the sea clutter off (land, targets and noise), PRF 500 Hz (1250 pulses): seaecho's PPI
  of the sweep with the coastline and the targets' truth;
- ``land_range_profile.png``: a flat patch of farmland (a 1 m plateau) seen by an
  isotropic radar 30 m up: the range-compressed power against range, one pulse, and its
  mean over the land's draws (gamma sin(psi) in the radar equation, summed over the
  facets of each range cell: eq L6 of docs/land.md);

and prints the targets' truth (hidden or not, and why), the land's facet counts, the
revolution's wall clock and CPU per pulse with and without the land, and the flat
patch's power ratio (simulated over expected).
``--quick``: 60 pulses of the revolution.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from _gallery import first_ppi  # noqa: E402

import seaecho  # noqa: E402
from seaecho.constants import C0  # noqa: E402
from seaecho.radar.equation import bistatic_received_power  # noqa: E402
from seaecho.simulation import Simulation  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "coastal_vts_xband.toml"


def revolution(out: Path, quick: bool) -> Path:
    base = seaecho.load_scene(SCENE)
    rev = {"radar.sea_clutter": False, "radar.prf_hz": 500.0,
           "radar.n_pulses": 60 if quick else 1250}
    scene = seaecho.with_overrides(base, rev)
    start, cpu = time.perf_counter(), time.process_time()
    bare = seaecho.simulate(scene.model_copy(update={"land": ()}), progress=False,
                            base_dir=SCENE.parent)
    wall0, cpu0 = time.perf_counter() - start, time.process_time() - cpu
    start, cpu = time.perf_counter(), time.process_time()
    ds = seaecho.simulate(scene, progress=False, base_dir=SCENE.parent)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    n = ds.sizes["pulse"]
    print(f"revolution without sea: {n} pulses; without the land {wall0:.1f} s wall, "
          f"{1e3 * cpu0 / n:.1f} ms CPU per pulse; with it {wall:.1f} s wall, "
          f"{1e3 * cpu / n:.1f} ms CPU per pulse (load {os.getloadavg()[0]:.1f}); "
          f"{bare.sizes['pulse']} pulses each; land facets "
          + ", ".join(f"{n}: {int(c)}" for n, c in zip(ds["land"].values,
                                                       ds["land_facets"].values, strict=True))
          + "; gamma " + ", ".join(f"{g:.2f} dB" for g in ds["land_gamma"].values))
    reasons = ds["truth_hidden_reason"].attrs["flag_meanings"].split()
    for i, name in enumerate(ds["object"].values):
        r = ds["truth_hidden_reason"].values[:, i]
        print(f"  {name}: {reasons[int(np.bincount(r).argmax())]}")
    return first_ppi(ds, out, "land_ppi_revolution")


def flat_patch(out: Path) -> Path:
    scene = seaecho.parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.41e9, "sampling_rate_hz": 20e6, "prf_hz": 1e3,
                  "n_pulses": 1, "sea_clutter": False, "thermal_noise": False,
                  "transmit_power_w": 25e3, "channels": ["HH"],
                  "waveform": {"kind": "pulse", "duration_s": 1e-7}},
        "transmitter": {"position_m": (0.0, -2000.0, 30.0), "yaw_deg": 90.0, "antenna": {
            "pattern": "isotropic", "azimuth_deg": 0.0, "depression_deg": 0.0}},
        "land": [{"name": "fields", "outline_m": [[-600, -1000], [600, -1000], [600, 1000],
                                                  [-600, 1000]],
                  "height_m": 1.0, "resolution_m": 5.0, "terrain": "farmland",
                  "weibull_shape": 2.0}]})
    sim = Simulation(scene)
    geo = sim.radar.geometry(0)
    land = sim.land
    echo = land.echo(geo)
    raw = sim.radar.receive(0, [echo])
    comp = sim.compress(raw[None])[0, 0]
    r = 0.5 * C0 * (sim.radar.window.t0 + np.arange(comp.size) / sim.radar.window.sampling_rate)
    # the mean: each facet's radar equation with <sigma_f> = gamma sin(psi) A_f (E[w] = 1),
    # put through the same pulse and compression (powers add on average: random phases)
    tx = geo.tx.position
    sigma = land.rcs(tx, tx)
    seen = sigma > 0
    mean_rcs = (sigma / land.power)[seen]
    p_mean = bistatic_received_power(25e3, echo.g_t, echo.g_r, sim.radar.wavelength,
                                     mean_rcs, echo.r_t, echo.r_r)
    p_sim = np.abs(echo.amplitudes[0]) ** 2
    print(f"flat farmland patch: {seen.sum()} facets lit; received power over its mean "
          f"(eq R2 with gamma sin psi): {p_sim.sum() / p_mean.sum():.4f}")
    edges = np.concatenate([r - 0.5 * (r[1] - r[0]), [r[-1] + 0.5 * (r[1] - r[0])]])
    rng_f = 0.5 * (echo.r_t + echo.r_r)
    mean_cell = np.histogram(rng_f, bins=edges, weights=p_mean)[0]
    sim_cell = np.histogram(rng_f, bins=edges, weights=p_sim)[0]
    fig, ax = plt.subplots(figsize=(6.4, 3.8), constrained_layout=True)
    ok = mean_cell > 0
    ax.plot(r / 1e3, 10 * np.log10(np.maximum(np.abs(comp) ** 2, 1e-30)), lw=0.6,
            color="0.6", label="range-compressed power, one pulse")
    ax.plot(r[ok] / 1e3, 10 * np.log10(sim_cell[ok]), lw=1.0,
            label="sum of the facets' |a_f|^2 per range cell")
    ax.plot(r[ok] / 1e3, 10 * np.log10(mean_cell[ok]), "k--", lw=1.0,
            label="mean: radar equation, sigma0 = gamma sin(psi)")
    ax.set_xlabel("range [km]")
    ax.set_ylabel("power [dB re 1 W]")
    ax.set_title("1.2 km x 2 km of farmland (gamma -15 dB) seen from 30 m, isotropic",
                 fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    top = 10 * np.log10(mean_cell[ok].max())
    ax.set_ylim(top - 60, top + 15)
    path = out / "land_range_profile.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> list[Path]:
    argv = sys.argv[1:] if argv is None else argv
    quick = "--quick" in argv
    rest = [a for a in argv if a != "--quick"]
    out = Path(rest[0]) if rest else ROOT / "docs" / "figures"
    out.mkdir(parents=True, exist_ok=True)
    return [flat_patch(out), revolution(out, quick)]


if __name__ == "__main__":
    for p in main():
        print(f"wrote {p}")
