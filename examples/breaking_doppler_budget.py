"""The breaking zones' Doppler velocity, term by term, against the published model.

Run: ``python examples/breaking_doppler_budget.py`` (prints a table; a few seconds of CPU).
X band (10 GHz), the default sea (Elfouhaily spectrum, Longuet-Higgins spreading s = 1),
U19.5 = 5, 8 and 12 m/s, the velocity component along the wind (a radar looking upwind
at grazing incidence sees it whole). A breaking zone's Doppler in seaecho is the sum of

* the fronts' own velocity relative to the water, the Lambda-weighted mean of
  ``c(k) cos(phi)`` over KHCC03's breakers (Hansen et al. 2012 eq 19;
  :func:`seaecho.scattering.breaking.breaking_statistics`),
* the orbital velocity of the resolved surface where the zones sit (on the crests of a
  1 m and a 0.25 m grid): its mean over the zones is eq BR8
  (:func:`~seaecho.scattering.breaking.placement_orbital_velocity`), of which the zones
  ride on the part of the long waves ``k < k_wb / 10`` (eq BR7) and leave out that of
  the shorter resolved waves, breakers themselves (eq BR10; before this version they
  rode on both),
* the surface drift (not in this table: 3 % of U10 by default on an evolving sea).

Beside them: the long-wave term of the published model, Hansen et al. (2012) eq 5 with
K05's modulation transfer function (eq BR9,
:func:`~seaecho.scattering.breaking.breaking_modulation_velocity`), and the sea-spike
speeds measured at X band and low grazing by Hwang, Sletten & Toporkov (2008, J.
Geophys. Res. 113, C02003, abstract): "an average speed between 2.0 and 2.6 m/s in mixed
seas with wind speeds between 7 and 14.5 m/s", which include the drift. The threshold of
the placement, ``gamma g`` of Phillips' criterion ``-a_z > gamma g`` on the long waves,
is printed too (Srokosz 1986: ``sqrt(2 m4) erfcinv(2 q)``), and the share of the
breaking area that the simulation's placement (the whole resolved sea's crests) has in
common with a placement by the long waves alone, on realisations of a 1 m and a 0.25 m
grid.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import erfcinv

from seaecho.constants import C0, G
from seaecho.ocean.dispersion import angular_frequency
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.ocean.wind import SURFACE_DRIFT_OVER_U10, u10_from_u19_5
from seaecho.scattering.breaking import (
    breaking_modulation_velocity,
    breaking_placement,
    breaking_statistics,
    modulating_wavenumber_limit,
    placement_orbital_velocity,
)
from seaecho.sea import vertical_acceleration

F_HZ = 10e9
WINDS = (5.0, 8.0, 12.0)


def threshold_over_g(spectrum: DirectionalSpectrum, q: float, k_max: float) -> float:
    """``gamma = sqrt(2 m4) erfcinv(2 q) / g`` of the waves ``k < k_max`` [-]."""
    k = np.geomspace(spectrum.peak_wavenumber() / 50.0, k_max, 3000)
    m4 = np.trapezoid(angular_frequency(k) ** 4 * spectrum.omni(k), k)
    return math.sqrt(2.0 * m4) * float(erfcinv(2.0 * q)) / G


def budget(u19_5: float) -> dict[str, float]:
    k_r = 2.0 * math.pi * F_HZ / C0
    u10 = float(u10_from_u19_5(u19_5))
    spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", u19_5)
    st = breaking_statistics(u10, k_r)
    k_mod = modulating_wavenumber_limit(st.k_wb)
    out = {"u10": u10, "q": st.q, "k_mod": k_mod, "fronts": st.mean_velocity}
    for name, dx in (("1m", 1.0), ("025m", 0.25)):  # the simulation's placement
        whole = placement_orbital_velocity(spec, st.q, math.pi / dx, 0.0)
        out[f"long_{name}"] = placement_orbital_velocity(spec, st.q, math.pi / dx, 0.0,
                                                         k_velocity=k_mod)
        out[f"short_{name}"] = whole - out[f"long_{name}"]
    out.update({
           "linear": breaking_modulation_velocity(spec, u10, k_r, 0.0),
           "drift": SURFACE_DRIFT_OVER_U10 * u10,
           "gamma": threshold_over_g(spec, st.q, math.pi / 1.0)})
    return out


def overlap(u19_5: float, size_m: float, n: int, seeds=(1, 2)) -> list[float]:
    """Fraction of the breaking area that a placement on the long waves (eq BR7) and the
    simulation's, on the whole resolved sea, share, per realisation [-]."""
    k_r = 2.0 * math.pi * F_HZ / C0
    st = breaking_statistics(float(u10_from_u19_5(u19_5)), k_r)
    k_mod = modulating_wavenumber_limit(st.k_wb)
    spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", u19_5)
    out = []
    for seed in seeds:
        surf = SeaSurface(spec, (size_m, size_m), (n, n), np.random.default_rng(seed))
        new, old = (breaking_placement(-vertical_acceleration(surf, 0.0, k).ravel(),
                                       np.ones(n * n), st.q) for k in (k_mod, None))
        out.append(float(np.minimum(new, old).sum() / new.sum()))
    return out


def main() -> None:
    print("U19.5 (U10) | q | fronts eq 19 | zones' orbital BR8, 1 m grid: long waves "
          "(ridden) / shorter (left out, BR10) | 0.25 m grid: same | K05 linear BR9 | "
          "fronts + BR8 long (+ drift) | fronts + BR9 (+ drift) | gamma (1 m grid)")
    for u in WINDS:
        b = budget(u)
        f, lo, lin, d = b["fronts"], b["long_1m"], b["linear"], b["drift"]
        print(f"{u:4.1f} ({b['u10']:4.1f}) | {100 * b['q']:.2f} % | {f:.2f} | "
              f"{lo:.2f} / {b['short_1m']:.2f} | {b['long_025m']:.2f} / "
              f"{b['short_025m']:.2f} | {lin:.2f} | {f + lo:.2f} ({f + lo + d:.2f}) | "
              f"{f + lin:.2f} ({f + lin + d:.2f}) | {b['gamma']:.2f}")
    for u in (8.0, 12.0):
        for size, n in ((128.0, 128), (64.0, 256)):
            print(f"U19.5 {u:4.1f}, {size / n:.2f} m grid: the placements on the long waves "
                  "and on the whole sea share "
                  + ", ".join(f"{100 * x:.0f} %" for x in overlap(u, size, n))
                  + " of the breaking area (seeds 1, 2)")
    print("k_mod = k_wb / 10 =", f"{budget(8.0)['k_mod']:.2f} rad/m; Hwang et al. (2008a): "
          "sea spikes at 2.0-2.6 m/s, winds 7-14.5 m/s")


if __name__ == "__main__":
    main()
