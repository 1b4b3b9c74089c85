"""Doppler spectra of evolving sea clutter against the composite-surface model.

Run: ``python examples/sea_doppler.py [OUTDIR]`` (default ``docs/figures``). Monostatic
X band (10 GHz), Elfouhaily sea on a 128 m tile with a 1 m grid (the unresolved waves
are carried statistically: sigma0 is grid-independent, docs/scattering.md), sea_motion =
"evolving" with the geometry updated every 8 pulses, PRF 500 Hz, 128 pulses,
range-compressed, 0.75 m range cells; Doppler spectrum = DP1 summed over the clutter cells
(docs/dynamics.md). Cases: wind 5, 8, 12 m/s looking upwind at 45 deg incidence; 8 m/s
downwind and crosswind; 8 m/s upwind at 10 deg grazing with and without breaking zones.

For each case and channel it prints the centroid and rms width and, beside them, the
composite-surface model's predictions (Thompson 1989): the Bragg centroid
``(2 p+ - 1) f_B + q . U / 2 pi`` (``f_B`` the Bragg line, ``p+`` the fraction of Bragg
waves travelling towards the radar, ``U`` the surface drift of the default ``[sea]
wind_drift``, 3 % of U10 along the wind on this evolving sea) and the width
``sqrt(sigma_orb^2 + 4 p+ p- f_B^2)`` with ``sigma_orb = sqrt(q^T C q) / (2 pi)`` the
Doppler spread of the orbital velocities of all the waves of the tile (eq U2). Writes
``dynamics_doppler_spectra.png`` and ``dynamics_doppler.csv``.
"""

from __future__ import annotations

import csv
import sys
import time
import warnings
from pathlib import Path

import numpy as np

from seaecho.config import parse_scene  # noqa: E402
from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.twoscale import orbital_velocity_covariance  # noqa: E402
from seaecho.ocean.wind import u10_from_u19_5  # noqa: E402
from seaecho.processing.doppler import (  # noqa: E402
    clutter_cells,
    doppler_moments,
    doppler_spectrum,
    range_doppler,
)
from seaecho.scattering.dynamics import bragg_frequency, travel_fraction  # noqa: E402
from seaecho.simulation import Simulation  # noqa: E402

CASES = (  # label, U19.5 [m/s], look (0 = radar looks upwind), incidence [deg], model
    ("U 5, upwind, 45", 5.0, 0.0, 45.0, "blend+breaking"),
    ("U 8, upwind, 45", 8.0, 0.0, 45.0, "blend+breaking"),
    ("U 12, upwind, 45", 12.0, 0.0, 45.0, "blend+breaking"),
    ("U 8, downwind, 45", 8.0, 180.0, 45.0, "blend+breaking"),
    ("U 8, crosswind, 45", 8.0, 90.0, 45.0, "blend+breaking"),
    ("U 8, upwind, 80 (10 grazing)", 8.0, 0.0, 80.0, "blend+breaking"),
    ("U 8, upwind, 80, no breaking", 8.0, 0.0, 80.0, "blend"),
)
F = 10e9
PRF = 500.0
N_PULSES = 128


def scene(u, look_deg, inc_deg, model, size=128.0, n=128, seed=1, update=8,
          n_pulses=N_PULSES, prf=PRF, motion="evolving", freq_hz=F,
          spreading="elfouhaily", wind_drift=None):
    """Monostatic radar (X band, ``freq_hz`` [Hz], by default) 1 km from the tile centre;
    wind towards +x; look 0: the radar east of the tile looking west (upwind); ``motion``
    None: the default ``[scattering] sea_motion``; ``spreading`` None: the default
    ``[sea] spreading`` (Longuet-Higgins, s = 1); ``wind_drift`` None: the default
    ``[sea] wind_drift`` ("auto": 3 % of U10 along the wind on an evolving sea)."""
    th, az = np.radians(inc_deg), np.radians(look_deg)
    r = 1000.0
    pos = (r * np.sin(th) * np.cos(az), r * np.sin(th) * np.sin(az), r * np.cos(th))
    return parse_scene({
        "sea": {"spectrum": "elfouhaily", "wind_speed_m_s": u, "size_x_m": size, "nx": n,
                **({"spreading": spreading} if spreading else {}),
                **({"wind_drift": wind_drift} if wind_drift else {})},
        "run": {"seed": seed},
        "scattering": {"model": model, **({"sea_motion": motion} if motion else {})},
        "tracing": {"mode": "analytic", "shadowing": "smith"},
        "radar": {"carrier_frequency_hz": freq_hz, "sampling_rate_hz": 240e6, "prf_hz": prf,
                  "n_pulses": n_pulses, "sea_update_pulses": update,
                  "channels": ["HH", "VV"],
                  "waveform": {"kind": "lfm", "bandwidth_hz": 200e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": pos, "antenna": {"pattern": "isotropic",
                                                       "look_at_m": [0, 0, 0]}},
    })


def orbital_doppler_spread_hz(spectrum, q, k_min: float, k_max: float):
    """Doppler spread [Hz] of the orbital velocities of the waves k_min < K < k_max
    [rad/m] seen along the scattering vector(s) ``q`` [rad/m], shape (..., 3):
    ``sqrt(q^T C q) / (2 pi)``, ``C`` their velocity covariance (eq U2; Thompson 1989)."""
    c = orbital_velocity_covariance(spectrum, k_min, k_max)
    q = np.asarray(q, dtype=float)
    return np.sqrt(np.einsum("...i,ij,...j->...", q, c, q)) / (2 * np.pi)


def composite_prediction(sim, inc_deg, look_deg):
    """Bragg centroid (plus the surface drift's ``q . U / 2 pi``, eq C1) and
    composite-model width [Hz] at the tile centre (monostatic)."""
    m = sim.sea_model
    spec = sim.sea.spectrum
    k = m.k
    th, az = np.radians(inc_deg), np.radians(look_deg)
    n_i = -np.array([np.sin(th) * np.cos(az), np.sin(th) * np.sin(az), np.cos(th)])
    q = -2.0 * k * n_i
    kb = q[:2]
    f_b = float(bragg_frequency(np.hypot(*kb)))
    p = float(travel_fraction(spec, kb[0], kb[1], float(u10_from_u19_5(spec.u19_5))))
    lx = sim.sea.x[-1] - sim.sea.x[0] + (sim.sea.x[1] - sim.sea.x[0])
    s_orb = float(orbital_doppler_spread_hz(spec, q, np.pi / lx, m.k_cut))
    # the surface drift of [sea] wind_drift (eq C1: every line moves by q . U / 2 pi)
    dyn = m.dynamics
    f_u = 0.0 if dyn is None else float(kb @ np.asarray(dyn.current, float)) / (2 * np.pi)
    return ((2 * p - 1) * f_b + f_u, float(np.sqrt(s_orb**2 + 4 * p * (1 - p) * f_b**2)),
            f_b, p)


def run_spectra(u, look, inc, model, **kw):
    """The case's simulation, Doppler frequencies [Hz], range-Doppler PSD (eq DP1, all
    pulses in one CPI, (C, N, S)) and clutter cells (within 20 dB of the strongest)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sim = Simulation(scene(u, look, inc, model, **kw))
        rc = np.array([sim.compress(sim.pulse(p)) for p in range(sim.radar.n_pulses)])
    f, psd = range_doppler(rc, sim.radar.prf)
    return sim, f, psd, clutter_cells(psd, 20.0)


def run_case(u, look, inc, model, **kw):
    sim, f, psd, cells = run_spectra(u, look, inc, model, **kw)
    spec = doppler_spectrum(f, psd, cells)
    cen, wid = doppler_moments(f, spec)
    return sim, f, spec, cen, wid


def cell_width_hz(f, psd, cells):
    """Power-weighted mean over the clutter ``cells`` of each range cell's own rms
    Doppler width (eq DP2 of the cell's spectrum) [Hz], per channel: the width of one
    resolution cell over the CPI, without the spread of the centroids from cell to cell
    that widens the clutter spectrum summed over the cells."""
    p = np.asarray(psd)[..., np.asarray(cells, dtype=bool)]  # (C, N, S')
    _, w = doppler_moments(f, np.moveaxis(p, 1, -1))  # (C, S')
    power = p.sum(axis=1)
    return (w * power).sum(axis=-1) / power.sum(axis=-1)


def main(outdir: str = "docs/figures") -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), constrained_layout=True)
    lam = C0 / F
    for label, u, look, inc, model in CASES:
        t = time.perf_counter()
        sim, f, spec, cen, wid = run_case(u, look, inc, model)
        b_cen, b_wid, f_b, p = composite_prediction(sim, inc, look)
        print(f"{label:32s} HH {cen[0]:+6.1f} Hz / {wid[0]:5.1f}   VV {cen[1]:+6.1f} / "
              f"{wid[1]:5.1f}   Bragg f_B {f_b:5.1f}, p+ {p:.2f}: centroid {b_cen:+6.1f}, "
              f"composite width {b_wid:5.1f}   ({time.perf_counter() - t:.0f} s)",
              flush=True)
        rows.append([label, u, look, inc, model, *np.round(cen, 2), *np.round(wid, 2),
                     round(f_b, 2), round(p, 3), round(b_cen, 2), round(b_wid, 2)])
        ax = axes[0] if inc == 45.0 and look == 0.0 else (
            axes[1] if inc == 45.0 else axes[2])
        for ci, ls in ((1, "-"), (0, "--")):
            s = spec[ci] / spec[1].max()
            ax.plot(f * lam / 2, 10 * np.log10(np.maximum(s, 1e-12)), ls,
                    label=f"{label}, {'VV' if ci else 'HH'}")
    for ax, title in zip(axes, ("upwind, 45 deg: wind speed", "8 m/s, 45 deg: look",
                                "8 m/s upwind, 10 deg grazing"), strict=True):
        ax.set_xlabel("line-of-sight velocity lambda f / 2 [m/s]")
        ax.set_ylabel("Doppler spectrum [dB, VV peak]")
        ax.set_ylim(-40, 5)
        ax.set_xlim(-3, 3)
        ax.grid(alpha=0.3)
        ax.set_title(title)
        ax.legend(fontsize=7)
    png = out / "dynamics_doppler_spectra.png"
    fig.savefig(png, dpi=100)
    plt.close(fig)
    with open(out / "dynamics_doppler.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["case", "u19_5_m_s", "look_deg", "incidence_deg", "model",
                    "centroid_hh_hz", "centroid_vv_hz", "width_hh_hz", "width_vv_hz",
                    "bragg_hz", "p_plus", "bragg_centroid_hz", "composite_width_hz"])
        w.writerows(rows)
    print(f"wrote {png}")
    return png


if __name__ == "__main__":
    main(*sys.argv[1:])
