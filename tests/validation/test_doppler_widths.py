"""Sea-clutter Doppler widths against what measurements publish (docs/dynamics.md,
"Doppler widths against measurements"; ``examples/doppler_widths.py``).

No published X-band sea-clutter Doppler width was found as a number (the measurements
searched for and what of them was readable: ``WIDTH_MEASUREMENTS`` in
``tests/validation/doppler_references.py``), so the widths are compared with the one
published width law that could be read:

* Hicks et al. (1960). The spectrum of X-band radiation backscattered from the sea
  surface. *J. Geophys. Res.* 65(3), 825: the clutter spectrum's width is proportional to
  H/T, the sea's wave height over its period (quoted by a citing article; second-hand,
  without its coefficient, polarisation or grazing angles). Here H = H_s and T = T_p of
  the wave spectrum (``doppler_references.hicks_velocity_scale_m_s``), so the law says
  that ``sigma_v / (H_s / T_p)`` (``sigma_v = lambda w / 2`` the rms width as
  line-of-sight velocity) does not change with the sea state.

Tolerances: the published scatter of the proportionality was not read. The composite
model's ratio (a deterministic integral) is held to 3 %; the simulated ratios (the mean
of seeds 1 and 2 of a 128 m tile for 0.19 s per wind) to 15 % of their mean over the
winds: the half-range of the two seeds' VV widths, up to 10 %
(``docs/figures/dynamics_doppler_widths.csv``), plus 5 %.

What the simulation gives (docs/dynamics.md, "Doppler widths against measurements"):
VV follows H_s / T_p at 3, 10 and 30 deg grazing (ratios within 9 % of their mean over
U19.5 = 5-12 m/s). HH is not tested at 3 deg, where one tile is too small for its
breaking-dominated width (the two seeds differ by 41 % of their mean at 12 m/s). Known
disagreement, kept visible (strict xfail): HH at 10 deg widens more slowly than H_s / T_p
(ratios 2.87, 2.19, 1.96 at 5, 8, 12 m/s: +23 % and -16 % of their mean).
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))
sys.path.insert(0, str(ROOT / "tests" / "validation"))

from doppler_references import hicks_velocity_scale_m_s  # noqa: E402

from seaecho.build import TWO_SCALE_CUT_RATIO  # noqa: E402
from seaecho.constants import C0  # noqa: E402
from seaecho.ocean.spectra import DirectionalSpectrum  # noqa: E402

F = 10e9
WINDS = (5.0, 8.0, 12.0)  # U19.5 [m/s]
#: the composite model's ratio is a deterministic integral: 3 %
COMPOSITE_TOL = 0.03
#: one realisation per wind (module docstring): 15 % of the mean ratio
SIMULATED_TOL = 0.15


def _spread(ratios) -> float:
    """Largest relative deviation of ``ratios`` from their mean."""
    r = np.asarray(ratios, dtype=float)
    return float(np.max(np.abs(r / r.mean() - 1.0)))


# --- fast: the composite model against Hicks et al.'s proportionality -----------------

def test_composite_orbital_width_is_proportional_to_h_over_t():
    # the composite model's width looking upwind (p+ = 1: the Bragg line adds no width)
    # is the orbital Doppler spread of all the waves up to the two-scale split (eq U2),
    # here of the open sea (no tile): sigma_v / (H_s / T_p) the same at every wind, at
    # 3, 10 and 30 deg grazing
    from doppler_widths import sea_scales
    from sea_doppler import orbital_doppler_spread_hz

    lam = C0 / F
    k = 2.0 * np.pi / lam
    psi = np.radians([3.0, 10.0, 30.0])
    q = 2.0 * k * np.stack([np.cos(psi), 0.0 * psi, np.sin(psi)], axis=-1)
    ratios = []  # [wind, grazing]
    for u in WINDS:
        spec = DirectionalSpectrum("elfouhaily", "longuet-higgins", u)
        sigma_v = orbital_doppler_spread_hz(spec, q, 1e-3, TWO_SCALE_CUT_RATIO * k) * lam / 2
        ratios.append(sigma_v / float(hicks_velocity_scale_m_s(*sea_scales(u))))
    ratios = np.array(ratios)
    # measured: 1.60-1.61 at 3 deg, 1.62-1.63 at 10 deg, 1.78-1.80 at 30 deg
    for per_grazing in ratios.T:
        assert _spread(per_grazing) < COMPOSITE_TOL, ratios
    # the width is the orbital velocity's, of order H_s / T_p (a wave of height H and
    # period T moves its particles at pi H / T at most)
    assert np.all((0.5 < ratios) & (ratios < np.pi)), ratios


# --- slow: the simulated widths ---------------------------------------------------------

@pytest.fixture(scope="module")
def width_rows(tmp_path_factory):
    from doppler_widths import width_comparison

    cases = tuple((g, u, 0.0, (1, 2)) for g in (3.0, 10.0) for u in WINDS)
    path = width_comparison(str(tmp_path_factory.mktemp("widths")), cases=cases)
    with open(path) as fh:
        rows = [{k: (v if k == "published" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(fh)]
    return {(r["grazing_deg"], r["u19_5_m_s"]): r for r in rows}


def _ratios(rows, grazing_deg, ch):
    return [rows[(grazing_deg, u)][f"hicks_ratio_{ch}"] for u in WINDS]


@pytest.mark.slow
@pytest.mark.parametrize("grazing_deg", [3.0, 10.0])
def test_simulated_vv_width_is_proportional_to_h_over_t(width_rows, grazing_deg):
    # Hicks et al. (1960): the width grows as H/T. Measured (docs/figures/
    # dynamics_doppler_widths.csv): VV width / (H_s / T_p) 2.90, 2.72, 2.48 at 3 deg and
    # 2.14, 2.24, 2.19 at 10 deg for U19.5 = 5, 8, 12 m/s
    ratios = _ratios(width_rows, grazing_deg, "vv")
    assert _spread(ratios) < SIMULATED_TOL, ratios
    # and the widths grow with the wind (the orbital velocities; Walker 2001)
    w = [width_rows[(grazing_deg, u)]["width_vv_hz"] for u in WINDS]
    assert w[0] < w[1] < w[2]


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="HH at 10 deg grazing widens more slowly than "
                   "H_s/T_p: width/(H_s/T_p) 2.87, 2.19, 1.96 at U19.5 = 5, 8, 12 m/s, +23 % "
                   "and -16 % of their mean for 15 % allowed (docs/dynamics.md)")
def test_simulated_hh_width_at_10_deg_is_proportional_to_h_over_t(width_rows):
    assert _spread(_ratios(width_rows, 10.0, "hh")) < SIMULATED_TOL
