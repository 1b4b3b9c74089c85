"""Clutter map (Nitzberg 1986) and M-of-N integration (Richards 2014, ch. 6) against
their closed forms, with exact binomial bounds of probability 1 - 1e-6 (fixed seeds)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from seaecho.detection import ClutterMap, m_of_n, theory


def test_clutter_map_pfa_equals_design():
    cm = ClutterMap(weight=0.125)
    assert cm.warmup == 40
    pfa = 1e-2
    power = np.random.default_rng(5).exponential(1.0, (100, 30000))
    hits = cm.detect(power, pfa)
    assert not hits[:40].any()
    # one scan per cell (the map correlates a cell's scans): independent Bernoulli trials
    scan = 40 + np.arange(power.shape[1]) % 60
    x = hits[scan, np.arange(power.shape[1])]
    lo, hi = stats.binom.interval(1 - 1e-6, x.size, pfa)
    assert lo <= x.sum() <= hi, (x.sum(), x.size * pfa)


def test_clutter_map_weight_one_is_one_cell_ca():
    # w = 1: the map is the previous scan, P_FA = 1 / (1 + alpha) (CA with N = 1)
    a = np.array([1.0, 10.0, 1e3])
    assert theory.pfa_clutter_map(a, 1.0) == pytest.approx(theory.pfa_ca(a, 1), rel=1e-14)


def test_clutter_map_small_weight_tends_to_known_noise():
    # w -> 0: the map is the exact mean, P_FA -> exp(-alpha) (Nitzberg 1986)
    assert theory.pfa_clutter_map(6.0, 1e-4) == pytest.approx(np.exp(-6.0), rel=2e-3)


def test_clutter_map_swerling1_pd():
    cm = ClutterMap(weight=0.25)
    pfa, snr = 1e-3, 10.0
    rng = np.random.default_rng(6)
    power = rng.exponential(1.0, (60, 20000))
    cols = np.arange(20000)
    scan = 20 + cols % 40
    power[scan, cols] = rng.exponential(1.0 + snr, cols.size)
    x = cm.detect(power, pfa)[scan, cols]
    pd = float(cm.pd_swerling1(cm.scale(pfa), snr))
    lo, hi = stats.binom.interval(1 - 1e-6, x.size, pd)
    assert lo <= x.sum() <= hi, (x.sum(), x.size * pd)


def test_m_of_n_rate_is_binomial_tail():
    p, m, n = 0.2, 3, 5
    hits = np.random.default_rng(7).random((200000, 10)) < p
    out = m_of_n(hits, m, n, axis=1)
    assert out.shape == (200000, 6)
    x = out[:, 0]  # windows 0..4 of independent rows
    q = float(theory.pfa_m_of_n(p, m, n))
    assert q == pytest.approx(sum(stats.binom.pmf(j, n, p) for j in range(m, n + 1)))
    lo, hi = stats.binom.interval(1 - 1e-6, x.size, q)
    assert lo <= x.sum() <= hi
    # exact on a small case
    h = np.array([1, 0, 1, 1, 0, 0, 1], bool)
    assert m_of_n(h, 2, 3).tolist() == [True, True, True, False, False]


def test_bad_input():
    with pytest.raises(ValueError, match="weight"):
        ClutterMap(weight=0.0)
    with pytest.raises(ValueError, match="M = 4"):
        m_of_n(np.zeros((5, 3), bool), 4, 3)
    with pytest.raises(ValueError, match="warm-up"):
        ClutterMap(weight=0.5).noise(np.ones((5, 3)))
