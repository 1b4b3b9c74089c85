"""CFAR detectors against their closed forms in exponential noise (fixed seeds).

Noise-only false-alarm rates are counted on cells whose windows do not overlap (every
(2 (G + T) + 1)-th cell of a row, rows independent), so the count is binomial and the
bounds below are exact binomial intervals of probability 1 - 1e-6: a failure is a wrong
threshold, not bad luck.

References: Richards (2014), Fundamentals of Radar Signal Processing, 2nd ed., ch. 6-7
(CA-CFAR P_FA = (1 + T)^-N with T = alpha / N; Swerling 1 P_D; Marcum's Q); Rohling (1983),
IEEE Trans. AES-19(4) 608-621 (OS-CFAR); Gandhi and Kassam (1988), IEEE Trans. AES-24(4)
427-445 (GO and SO).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from seaecho.detection import CFAR, theory


def _noise(shape, seed):
    return np.random.default_rng(seed).exponential(1.0, shape)


def _independent(cfar: CFAR, shape):
    """Mask of tested cells whose windows do not overlap (1-D along the last axis, or
    every window-th row and column in 2-D)."""
    tested = np.array(cfar.tested(shape))
    keep = np.zeros(shape, bool)
    w = [2 * (g + t) + 1 for g, t in zip(cfar.guard, cfar.train, strict=True)]
    if cfar.ndim == 1:
        keep[..., ::w[-1]] = True
    else:
        keep[..., ::w[0], ::w[1]] = True
    return tested & keep


def _within(count, n, p, level=1e-6):
    lo, hi = stats.binom.interval(1.0 - level, n, p)
    return lo <= count <= hi, (count, n * p, lo, hi)


def test_ca_scale_is_richards_closed_form():
    # Richards (2014), ch. 7: alpha = N (P_FA^(-1/N) - 1) on the training mean
    for n in (4, 16, 32):
        cfar = CFAR("ca", train=n // 2, guard=1)
        for pfa in (1e-2, 1e-4, 1e-6):
            assert cfar.scale(pfa) == pytest.approx(n * (pfa ** (-1.0 / n) - 1.0), rel=1e-12)
            t = cfar.scale(pfa) / n
            assert (1.0 + t) ** (-n) == pytest.approx(pfa, rel=1e-10)


def test_go_so_one_cell_per_half_closed_form():
    # n = 1: Z = max or min of two unit exponentials; E[e^-T min] = 2 / (2 + T) and
    # E[e^-T max] = 2 / (1 + T) - 2 / (2 + T) (Gandhi & Kassam 1988 with n = 1)
    t = np.array([0.5, 3.0, 40.0])
    assert theory.pfa_so(t, 1) == pytest.approx(2.0 / (2.0 + t), rel=1e-12)
    assert theory.pfa_go(t, 1) == pytest.approx(2.0 / (1.0 + t) - 2.0 / (2.0 + t), rel=1e-12)


def test_os_rank_one_of_one_is_ca():
    # Rohling (1983): with N = k = 1 the order statistic is the cell itself: 1 / (1 + alpha)
    a = np.array([1.0, 9.0, 99.0])
    assert theory.pfa_os(a, 1, 1) == pytest.approx(theory.pfa_ca(a, 1), rel=1e-14)


@pytest.mark.parametrize("kind", ["ca", "go", "so", "os"])
def test_false_alarm_rate_1d_equals_design(kind):
    cfar = CFAR(kind, train=8, guard=2)
    pfa = 1e-3
    power = _noise((6000, 210), seed=11)
    hits = cfar.detect(power, pfa)
    keep = _independent(cfar, power.shape)
    ok, info = _within(int(hits[keep].sum()), int(keep.sum()), pfa)
    assert ok, info
    # and over every tested cell (correlated counts): within 15 % of the design
    rate = hits[np.array(cfar.tested(power.shape))].mean()
    assert rate == pytest.approx(pfa, rel=0.15)


@pytest.mark.parametrize("kind", ["ca", "go", "so", "os"])
def test_false_alarm_rate_2d_equals_design(kind):
    cfar = CFAR(kind, train=(2, 4), guard=(1, 1))
    pfa = 1e-2
    power = _noise((8, 400, 260), seed=12)
    hits = cfar.detect(power, pfa)
    keep = _independent(cfar, power.shape)
    ok, info = _within(int(hits[keep].sum()), int(keep.sum()), pfa)
    assert ok, info


def test_circular_azimuth_tests_every_azimuth():
    cfar = CFAR("ca", train=(2, 4), guard=(1, 1), circular=True)
    power = _noise((3, 90, 60), seed=13)
    noise = cfar.noise(power)
    assert np.isfinite(noise[:, :, 5:-5]).all()
    # the first azimuth's window wraps onto the last ones: the direct sum
    fp = cfar.footprints[0]
    rows = np.r_[np.arange(-3, 0) % 90, np.arange(0, 4)]
    direct = (power[0][np.ix_(rows, np.arange(20 - 5, 20 + 6))] * fp).sum() / cfar.n_train
    assert noise[0, 0, 20] == pytest.approx(direct, rel=1e-12)


def _targets(power, cfar, snr, seed, swerling):
    """Power with a target every window along range: Swerling 1 (exponential of mean
    1 + S) or Swerling 0 (|sqrt(S) e^{j phi} + n|^2); returns the power and the mask."""
    rng = np.random.default_rng(seed)
    h = cfar.guard[-1] + cfar.train[-1]
    mask = np.zeros(power.shape, bool)
    mask[..., h:power.shape[-1] - h:2 * h + 1] = True
    m = int(mask.sum())
    if swerling == 1:
        power[mask] = rng.exponential(1.0 + snr, m)
    else:
        n = (rng.standard_normal(m) + 1j * rng.standard_normal(m)) / np.sqrt(2.0)
        power[mask] = np.abs(np.sqrt(snr) * np.exp(2j * np.pi * rng.random(m)) + n) ** 2
    return power, mask


@pytest.mark.parametrize("kind", ["ca", "go", "so", "os"])
def test_swerling1_pd_closed_form(kind):
    cfar = CFAR(kind, train=8, guard=2)
    pfa, snr = 1e-4, 10.0 ** (15.0 / 10.0)
    power, mask = _targets(_noise((3000, 210), seed=21), cfar, snr, seed=22, swerling=1)
    hits = cfar.detect(power, pfa)
    pd = float(cfar.pd_swerling1(cfar.scale(pfa), snr))
    if kind == "ca":  # Richards (2014): (1 + T / (1 + S))^-N, T = Pfa^(-1/N) - 1
        t = pfa ** (-1.0 / 16) - 1.0
        assert pd == pytest.approx((1.0 + t / (1.0 + snr)) ** -16, rel=1e-10)
    ok, info = _within(int(hits[mask].sum()), int(mask.sum()), pd)
    assert ok, info


def test_swerling0_pd_marcum_q():
    cfar = CFAR("ca", train=8, guard=2)
    pfa, snr = 1e-4, 10.0 ** (13.0 / 10.0)
    alpha = cfar.scale(pfa)
    power, mask = _targets(_noise((3000, 210), seed=31), cfar, snr, seed=32, swerling=0)
    hits = cfar.detect(power, pfa)
    pd = theory.pd_ca_swerling0(alpha, cfar.n_train, snr)
    ok, info = _within(int(hits[mask].sum()), int(mask.sum()), pd)
    assert ok, info
    # Limits of the averaged Marcum Q: S = 0 gives the CA false-alarm law; many training
    # cells give the known-noise detector Q_1(sqrt(2 S), sqrt(-2 ln P_FA))
    assert theory.pd_ca_swerling0(alpha, 16, 0.0) == pytest.approx(pfa, rel=1e-6)
    big = 20000
    a_big = big * (pfa ** (-1.0 / big) - 1.0)
    known = stats.ncx2.sf(-2.0 * np.log(pfa), 2, 2.0 * snr)
    assert theory.pd_ca_swerling0(a_big, big, snr) == pytest.approx(known, rel=2e-3)


def test_cfar_loss_ordering():
    # In homogeneous noise the CA-CFAR is the best of the four (the least CFAR loss):
    # GO, SO and OS pay for their robustness (Rohling 1983; Gandhi and Kassam 1988)
    pfa, snr = 1e-6, 10.0 ** 1.5
    pd = {k: float(CFAR(k, train=8, guard=2).pd_swerling1(
        CFAR(k, train=8, guard=2).scale(pfa), snr)) for k in ("ca", "go", "so", "os")}
    assert pd["ca"] > pd["go"] and pd["ca"] > pd["os"] and pd["ca"] > pd["so"]


@pytest.mark.parametrize("bad", [dict(kind="xx"), dict(train=0), dict(train=(2, 3, 4)),
                                 dict(train=(2, 3), guard=1), dict(kind="os", rank=17),
                                 dict(kind="ca", rank=3), dict(guard=-1)])
def test_bad_parameters_name_the_field(bad):
    with pytest.raises(ValueError, match=list(bad)[-1]):
        CFAR(**{"train": 8, "guard": 2, **bad})


def test_bad_pfa():
    with pytest.raises(ValueError, match="pfa"):
        CFAR("ca", 8, 2).scale(1.5)
