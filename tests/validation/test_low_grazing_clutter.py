"""Sea clutter at low grazing against the published X-band models (docs/scanning.md,
"Validation at low grazing"; ``examples/low_grazing_clutter.py``).

References (``tests/reference_models.py``):

* NRL model: Gregers-Hansen, V. and Mital, R. (2012). An improved empirical model for
  radar sea clutter reflectivity. *IEEE Trans. Aerosp. Electron. Syst.* 48(4),
  3512-3524 (NRL/MR/5310--12-9346): sigma0 = c1 + c2 log10 sin psi + (27.5 + c3 psi)
  log10 f / (1 + 0.95 psi) + c4 (SS + 1)^(1 / (2 + 0.085 psi + 0.033 SS)) + c5 psi^2,
  coefficients as in Gregers-Hansen's own code (NRL_SigmaSea.m, 2010).
* GIT model: Horst, M. M., Dyer, F. B. and Tuley, M. T. (1978), in the form of the NRL
  code (GTI_SigmaSea.m), averaged over the looks upwind, crosswind and downwind.
* Nathanson, F. E. (1991). *Radar Design Principles*, 2nd ed., tables at 9.3 GHz.

Tolerance: the simulation agrees where it lies within 3 dB of the envelope of the three
references. The 3 dB is the accuracy of sigma0 measurements (+-3 dB at 2 sigma for the
TAGSEA campaign: Nathanson & Brooks 1976, DTIC ADA037249); the envelope is the models'
own disagreement (GIT and NRL differ by up to 28 dB at sea state 2 and 0.3 deg, the
"large deviation between the GIT model and this database, in particular at lower sea
states" of Gregers-Hansen & Mital's abstract). The sea-state-to-wind mapping adds 2-3 dB
of its own that the tolerance does not include.

Known disagreements, asserted as bounds or strict xfails: below 1 deg at sea states 2-3
the simulated HH falls off too slowly with the grazing angle (no multipath interference
or other propagation factor: the references are "apparent" reflectivities, which include
them); VV lies up to 1-2 dB above the envelope (the Bragg part's X-band excess, docs/
scattering.md).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))
sys.path.insert(0, str(ROOT / "tests"))

pytestmark = pytest.mark.slow

TOL_DB = 3.0
GRAZING = (0.3, 1.0, 3.0)


@pytest.fixture(scope="module")
def table():
    from low_grazing_clutter import facet_table

    rows = facet_table(sea_states=(2, 3, 4, 5), grazing_deg=GRAZING)
    return {(r["sea_state"], r["grazing_deg"], r["pol"]): r for r in rows}


def _outside(r) -> float:
    """dB by which the simulation lies outside the references' envelope +- TOL_DB."""
    refs = [r[k] for k in ("nrl_db", "git_db", "nathanson_db") if not np.isnan(r[k])]
    return max(r["sim_db"] - (max(refs) + TOL_DB), (min(refs) - TOL_DB) - r["sim_db"],
               0.0)


def test_hh_within_the_published_models_from_1_to_3_deg(table):
    """HH, sea states 2-5, 1 and 3 deg: within 3 dB of the NRL/GIT/Nathanson envelope
    (measured: inside it everywhere; Nathanson -1.5 to +0.9 dB, GIT -1.2 to +2.9 dB
    except sea state 2 at 1 deg, NRL +1.2 to +3.5 dB)."""
    bad = {k: round(_outside(r), 2) for k, r in table.items()
           if k[2] == "HH" and k[1] >= 1.0 and _outside(r) > 0.0}
    assert not bad, bad


def test_hh_falls_off_below_3_deg_but_too_slowly(table):
    """Known disagreement, bounded: from 3 to 0.3 deg the simulated HH falls (shadowing:
    more than 1 dB; measured 2.3-3.7 dB) but less than NRL's 6.5-8.6 dB and Nathanson's
    6-13 dB, so that at 0.3 deg it lies above NRL, by less than 10 dB (measured
    4.0-7.8 dB). The agreement itself is the strict xfail below."""
    for ss in (2, 3, 4, 5):
        hi, lo = table[(ss, 3.0, "HH")], table[(ss, 0.3, "HH")]
        assert hi["sim_db"] - lo["sim_db"] > 1.0, (ss, hi, lo)
        assert lo["sim_db"] - lo["nrl_db"] < 10.0, (ss, lo)


@pytest.mark.xfail(strict=True, reason="no multipath/propagation factor: at 0.3 deg, sea "
                   "states 2-4, HH lies 0.2-4.8 dB above the models' envelope + 3 dB")
def test_hh_within_the_published_models_at_0_3_deg(table):
    bad = {k: round(_outside(r), 2) for k, r in table.items()
           if k[2] == "HH" and k[1] == 0.3 and _outside(r) > 0.0}
    assert not bad, bad


def test_vv_above_the_published_models_by_a_bounded_excess(table):
    """Known disagreement, bounded: at 1-3 deg VV lies less than 7 dB above NRL (measured
    3.8-6.2 dB; 4.5-8.6 dB at 0.3 deg, where the propagation factor is missing too). The
    agreement itself is the strict xfail below."""
    for k, r in table.items():
        if k[2] == "VV" and k[1] >= 1.0:
            assert r["sim_db"] - r["nrl_db"] < 7.0, (k, r)


@pytest.mark.xfail(strict=True, reason="the X-band Bragg excess of VV (docs/scattering.md): "
                   "VV up to 1.4 dB beyond the envelope + 3 dB at 1-3 deg, 5 dB at 0.3")
def test_vv_within_the_published_models(table):
    bad = {k: round(_outside(r), 2) for k, r in table.items()
           if k[2] == "VV" and _outside(r) > 0.0}
    assert not bad, bad


def test_scanning_ppi_returns_the_sea_nrcs_and_falls_off_as_r_cubed():
    """A scanning run's PPI calibrated by the radar equation (eq V1 of the example) gives
    the run's own facet NRCS (the chain antenna - scan - radar equation - range
    compression), HH and VV, at 1 and 2 km (grazing 2 and 1 deg; one sea realisation,
    seed 3): within 3 dB, three
    standard deviations of the PPI's estimate (about 60 independent K cells of nu ~ 1
    over a 128 m tile at 1 km; measured 0.05-1.1 dB). The clutter power of the
    beam-limited cell then falls off between 1 and 2 km as R^-n with n within 1 of
    NRL's (measured: HH 3.45 against 3.54, VV 3.86 against 3.75; the error of n from
    two +-1 dB estimates is +-0.5), between the R^-3 of a constant sigma0 and the R^-7
    of the interference region."""
    from low_grazing_clutter import falloff_exponents, ppi_table

    rows = ppi_table((1000.0, 2000.0), sea_state=4, tile_m=128.0, n=128, seeds=(3,))
    for r in rows:
        for ch in ("HH", "VV"):
            assert abs(r[f"ppi_{ch}_db"] - r[f"map_{ch}_db"]) < 3.0, r
    (ex,) = falloff_exponents(rows)
    for ch in ("HH", "VV"):
        assert abs(ex[f"ppi_{ch}"] - ex[f"nrl_{ch}"]) < 1.0, ex
        assert 3.0 - 1.0 < ex[f"ppi_{ch}"] < 7.0, ex


@pytest.fixture(scope="module")
def apparent():
    """The apparent NRCS through the two-ray factor with its reflected legs shadowed
    (``[propagation] multipath_shadowing``, eqs P5-P7 of seaecho.radar.propagation), a
    radar 35 m up; about 2-3 minutes."""
    from low_grazing_clutter import facet_table

    rows = facet_table(sea_states=(2, 3, 4, 5), grazing_deg=(0.3, 3.0), multipath=True)
    return {(r["sea_state"], r["grazing_deg"], r["pol"]): r for r in rows}


def test_apparent_hh_within_the_published_models_at_0_3_deg(apparent):
    """With the shadowed two-ray factor HH at 0.3 deg lies within 3 dB of the models'
    envelope at sea states 2-5 (measured: inside it, 14.5, 3.6, 0.9, 0.4 dB below NRL),
    and falls from 3 to 0.3 deg by at least NRL's fall-off less 1 dB (measured 24.8,
    13.6, 10.1, 8.1 dB against NRL's 8.6, 7.8, 7.1, 6.5): the free-space table's excess
    gone."""
    for ss in (2, 3, 4, 5):
        lo, hi = apparent[(ss, 0.3, "HH")], apparent[(ss, 3.0, "HH")]
        row = dict(lo, sim_db=lo["sim_multipath_db"])
        assert _outside(row) == 0.0, (ss, lo)
        fall = hi["sim_multipath_db"] - lo["sim_multipath_db"]
        assert fall > hi["nrl_db"] - lo["nrl_db"] - 1.0, (ss, fall)
