"""K shape of the simulated clutter against the empirical law, and CA-CFAR's false alarms
in it against the closed forms (docs/detection.md "CFAR in simulated K clutter";
``examples/cfar_k_clutter.py``).

The clutter: a 10 GHz real-aperture radar looking upwind at 1 and 3 deg grazing over an
evolving Elfouhaily sea (U19.5 = 10 m/s, 128 m tile, breaking zones, ray-traced
shadowing), 0.75 m and 3 m range cells, 48 pulses 50 ms apart.

References:

* the empirical K-shape law (eq ST6, ``processing.statistics.k_shape_empirical``) of
  Watts & Wicks (1990) as restated by Ward, Tough & Watts (2013), log10 nu = 2/3 log10
  psi_deg + 5/8 log10 A_c - k_pol (k_pol = 1.39 VV, 2.09 HH; no swell). The book was
  not read here; the exponents and k_pol are as restated by M. Farshchian's NRL
  sea-clutter generator (2010, ``shapefactor`` in ``gammageneratortime.m``, which cites
  Ward, Tough & Watts 2006, p. 237). Tolerance: half a decade (a factor 3.16), the
  scatter of measured nu about such laws; nu also varies sinusoidally with the look
  direction to the wind waves (Crisp, Rosenberg, Stacy & Dong 2009, abstract read; the
  size of that variation, about a factor of 2, is not checked against their text).
* CA-CFAR in K clutter (``detection.theory.pfa_ca_k``, eqs D1 and D8): the texture
  constant over the window keeps the design P_FA; independent textures (Armstrong &
  Griffiths 1991's worst case) raise it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))

pytestmark = pytest.mark.slow

N_PULSES = 48


@pytest.fixture(scope="module")
def clutter():
    import clutter_statistics as cs

    cs.N_PULSES = N_PULSES
    out = {}
    for g in (1.0, 3.0):
        sim, rc, r, _ = cs.simulate(g)
        for frac in (1, 4):
            x = cs.coarser(rc, frac)
            rr = r[:: max(1, int(round(1.2 * frac)))] if frac > 1 else r
            cells = np.abs(rr - cs.RANGE_M) < 0.5 * cs.SIZE * np.cos(np.radians(g)) - 2 * frac
            for ci, ch in enumerate(sim.radar.channel_names):
                if ch in ("HH", "VV"):
                    out[(g, 0.75 * frac, ch)] = np.abs(x[:, ci][:, cells]) ** 2
    return out, cs.SIZE


def _nu(p):
    from seaecho.processing.statistics import fit_k

    return float(fit_k((p / p.mean()).ravel()).nu)


def test_k_shape_against_the_empirical_law(clutter):
    """nu (maximum likelihood) within half a decade of eq ST6 at 1 and 3 deg, 0.75 and
    3 m cells, HH and VV (measured ratios 0.5-3.1), HH spikier than VV."""
    from seaecho.processing.statistics import k_shape_empirical

    data, size = clutter
    nus = {k: _nu(p) for k, p in data.items()}
    for (g, res, ch), nu in nus.items():
        emp = float(k_shape_empirical(g, res / np.cos(np.radians(g)) * size, ch))
        assert abs(np.log10(nu / emp)) < 0.5, ((g, res, ch), nu, emp)
    for g in (1.0, 3.0):
        for res in (0.75, 3.0):
            assert nus[(g, res, "HH")] < nus[(g, res, "VV")]


def test_k_shape_grows_with_the_cell_more_slowly_than_the_law(clutter):
    """Known disagreement, bounded: nu grows with the cell area, but as A_c^b with b of
    0.2-0.35 rather than the law's 5/8 (the 128 m tile holds none of the longer waves
    whose modulation is the texture of larger cells, and no swell)."""
    data, _ = clutter
    for g in (1.0, 3.0):
        for ch in ("HH", "VV"):
            b = np.log(_nu(data[(g, 3.0, ch)]) / _nu(data[(g, 0.75, ch)])) / np.log(4.0)
            assert 0.0 < b < 5.0 / 8.0 - 0.1, (g, ch, b)


def test_ca_cfar_false_alarms_in_simulated_clutter(clutter):
    """A CA-CFAR (2 x 8 training cells, 2 guard) at the design P_FA = 1e-2 of exponential
    noise, on the 0.75 m cells: above the design beyond binomial noise in both channels
    (the clutter is not exponential), more in HH (spikier) than in VV; in HH within a
    factor 2 of eq D8 with the measured nu (independent textures: the spikes of breaking
    crests decorrelate from cell to cell; measured 1.2 times eq D8, 5-7 times the
    design); in VV below twice eq D8 (measured 0.6 times: the texture partly
    correlated over the 12 m window). The factor 2 covers the K fit's nu (+-20 %
    from these samples) and the departure of the simulated tail from K."""
    from scipy import stats

    from seaecho.detection import CFAR
    from seaecho.detection.theory import pfa_ca, pfa_ca_k, scale_for_pfa

    data, _ = clutter
    cf = CFAR("ca", 8, 2)
    alpha = scale_for_pfa(pfa_ca, 1e-2, 16)
    for g in (1.0, 3.0):
        measured = {}
        for ch in ("HH", "VV"):
            p = data[(g, 0.75, ch)]
            s = cf(p)
            ok = np.isfinite(s)
            k, n = int((s[ok] > alpha).sum()), int(ok.sum())
            lo = float(stats.beta.ppf(0.001, k, n - k + 1))
            pfa = k / n
            d8 = float(pfa_ca_k(alpha, 16, min(_nu(p), 100.0)))
            assert lo > 1e-2, (g, ch, pfa)  # above the design: the clutter is not exponential
            assert pfa < 2.0 * d8, (g, ch, pfa, d8)
            if ch == "HH":
                assert pfa > 0.5 * d8, (g, ch, pfa, d8)
            measured[ch] = pfa
        # the spikier channel has the more false alarms
        assert measured["HH"] > measured["VV"], (g, measured)
