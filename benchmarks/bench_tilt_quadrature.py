"""Eq P6's average over the unresolved tilts by rules of fewer or more planes, against a
converged Gauss-Hermite rule: is a cheaper rule as good as the default?

Simulation 2's facet model (its wavenumber, permittivity, Bragg spectrum and unresolved
slope variances of the scene's grid), the Bragg part alone (``model = "spm"``, eq P2
averaged by eq P6), monostatic at 45 and 70 deg incidence, every 15 deg of azimuth from
the wind, on a flat facet and on facets tilted by 0.1 along either wind axis or both.
Each rule's sigma_mn is compared with a 21 x 21 tensor-product Gauss-Hermite rule
(``TiltQuadrature.gauss_hermite``), in dB: the largest and the rms difference per
channel. The rules: the default five-plane unscented rule (``TiltQuadrature.unscented``),
two four-plane rules exact for the polynomials of degree 3 (the 2 x 2 Gauss-Hermite
product rule at (+-s_u, +-s_c), and the cubature rule at (+-sqrt(2) s_u, 0),
(0, +-sqrt(2) s_c), Arasaratnam & Haykin 2009), 3 x 3 and 7 x 7 Gauss-Hermite.
The kernel evaluates the Bragg term once per plane (about 7 ms of CPU per plane and
Simulation 2 pulse, ``docs/performance.md``).
"""

from __future__ import annotations

import argparse
import math
import os
import warnings
from pathlib import Path

import numpy as np
from _smoke import GRID, add_option, small_scene

ROOT = Path(__file__).resolve().parents[1]
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"


def four_planes(su2: float, sc2: float, nodes: list) -> object:
    """A rule of four tilted planes of weight 1/4 (area factor included), no centre."""
    from seaecho.scattering.facet import TiltQuadrature

    return TiltQuadrature(tuple(nodes), (0.0,) + tuple(
        0.25 * math.sqrt(1.0 + u * u + c * c) for u, c in nodes))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=512, help="the scene's grid (sets the "
                    "unresolved slope variances)")
    add_option(ap)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from seaecho.config import load_scene
    from seaecho.scattering.facet import TiltQuadrature, facet_terms
    from seaecho.simulation import Simulation

    path = small_scene(SIM2, grid=GRID if args.smoke else args.grid, pulses=10**6)
    sim = Simulation(load_scene(path), base_dir=path.parent)
    fm = sim.sea_model.facet_model.with_(model="spm")
    su2, sc2 = fm.tilt.slopes[0][0] ** 2 / 3.0, fm.tilt.slopes[2][1] ** 2 / 3.0
    su, sc = math.sqrt(su2), math.sqrt(sc2)
    rules = {
        "unscented, 5 planes (default)": TiltQuadrature.unscented(su2, sc2),
        "Gauss-Hermite 2 x 2, 4 planes": four_planes(
            su2, sc2, [(a * su, b * sc) for a in (1, -1) for b in (1, -1)]),
        "cubature +-sqrt(2) s, 4 planes": four_planes(
            su2, sc2, [(math.sqrt(2) * su, 0.0), (-math.sqrt(2) * su, 0.0),
                       (0.0, math.sqrt(2) * sc), (0.0, -math.sqrt(2) * sc)]),
        "Gauss-Hermite 3 x 3, 9 planes": TiltQuadrature.gauss_hermite(su2, sc2, 3),
        "Gauss-Hermite 7 x 7, 49 planes": TiltQuadrature.gauss_hermite(su2, sc2, 7),
    }
    ref = TiltQuadrature.gauss_hermite(su2, sc2, 5 if args.smoke else 21)
    geo = []
    for inc in np.deg2rad((45.0, 70.0)):
        for az in np.deg2rad(np.arange(0.0, 360.0, 15.0)):
            phi = fm.wind_direction + az
            for tu, tc in ((0.0, 0.0), (0.1, 0.0), (0.0, 0.1), (-0.1, 0.07)):
                n = np.array([-tu, -tc, 1.0])
                geo.append((np.array([np.sin(inc) * np.cos(phi), np.sin(inc) * np.sin(phi),
                                      -np.cos(inc)]), n / np.linalg.norm(n)))
    n_i = np.array([g[0] for g in geo])
    normal = np.array([g[1] for g in geo])

    def sigma(q):
        return facet_terms(n_i, -n_i, normal, fm.with_(tilt=q), backend="numpy").sigma()

    s_ref = sigma(ref)
    print(f"bench_tilt_quadrature: {path.stem}, {sim.sea.surface.shape[0]}^2 grid, "
          f"unresolved mss upwind {su2:.4g}, crosswind {sc2:.4g}; {len(geo)} geometries; "
          f"load {os.getloadavg()[0]:.2f}")
    print(f"  {'rule':32s} sigma - sigma(GH 21 x 21) [dB]: max |.| (rms)")
    print(f"  {'':32s} {'HH':>14s} {'HV':>14s} {'VV':>14s}")
    for name, q in rules.items():
        d = 10.0 * np.log10(sigma(q) / s_ref)
        cells = [f"{np.abs(d[:, c]).max():.3f} ({np.sqrt(np.mean(d[:, c] ** 2)):.3f})"
                 for c in (0, 1, 3)]
        print(f"  {name:32s} " + " ".join(f"{c:>14s}" for c in cells))


if __name__ == "__main__":
    main()
