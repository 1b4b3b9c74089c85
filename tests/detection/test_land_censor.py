"""Land-censored CFAR: the land's cells left out of the training windows, each estimate
from the sea cells its window keeps and its threshold multiplier from the closed form
for that number of cells (fixed seeds).

False-alarm rates are counted over independent rows (one count per position of the cell
under test, the rows' noise independent), so each count is binomial and the bounds are
exact binomial intervals of probability 1 - 1e-6.

References: Richards (2014), Fundamentals of Radar Signal Processing, 2nd ed., ch. 7
(CA-CFAR: P_FA = (1 + alpha / N)^-N, alpha = N (P_FA^(-1/N) - 1); Swerling 1 P_D with
alpha / (1 + S)); Rohling (1983), IEEE Trans. AES-19(4) 608-621 (OS-CFAR,
prod_{i<k} (N - i) / (N - i + alpha)); Gandhi and Kassam (1988), IEEE Trans. AES-24(4)
427-445 (GO and SO with equal halves; eq D9 of docs/detection.md generalises their sum
to halves of m and n cells).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from seaecho.detection import CFAR, theory

LAND = 22  # first land column of the rows below
ROWS = 20000


def _within(count, n, p, level=1e-6):
    lo, hi = stats.binom.interval(1.0 - level, n, p)
    return lo <= count <= hi, (count, n * p, lo, hi)


def _rows_with_land(seed, cols=LAND + 12, land_power=1e3):
    """ROWS independent rows of unit exponential noise; columns from LAND on are land, a
    thousand times stronger (its cells in a window would swamp the estimate)."""
    rng = np.random.default_rng(seed)
    power = rng.exponential(1.0, (ROWS, cols))
    land = np.zeros(cols, bool)
    land[LAND:] = True
    power[:, land] = rng.exponential(land_power, (ROWS, int(land.sum())))
    return power, land


def test_so_go_unequal_halves_closed_form():
    # m = 1, n = 2 by hand: A ~ Exp(1), B the mean of two, P(A > t) P(B > t) =
    # e^(-3t)(1 + 2t), so E[e^(-a min)] = 1 - a (1/(a + 3) + 2/(a + 3)^2) = (a + 9)/(a + 3)^2;
    # and max = A + B - min: E[e^(-a max)] = 1/(1 + a) + (1 + a/2)^-2 - that
    a = np.array([0.5, 4.0, 60.0])
    so = (a + 9.0) / (a + 3.0) ** 2
    assert theory.pfa_so(a, 1, 2) == pytest.approx(so, rel=1e-12)
    assert theory.pfa_so(a, 2, 1) == pytest.approx(so, rel=1e-12)
    assert theory.pfa_go(a, 1, 2) == pytest.approx(1 / (1 + a) + (1 + a / 2) ** -2 - so,
                                                  rel=1e-12)
    # equal halves: Gandhi & Kassam's sum, 2 sum_j C(n-1+j, j) (2 + T)^-(n+j)
    n, t = 5, a / 5
    direct = 2.0 * np.array([sum(np.prod(np.arange(n, n + k)) / np.prod(np.arange(1, k + 1))
                                 * (2.0 + tt) ** -(n + k) for k in range(n)) for tt in t])
    assert theory.pfa_so(a, n) == pytest.approx(direct, rel=1e-12)
    assert theory.pfa_so(a, n, n) == pytest.approx(direct, rel=1e-12)
    # halves of 3 and 7 cells: a Monte Carlo of E[e^(-a min)], E[e^(-a max)] (fixed seed;
    # the exponential CUT integrated out, so the spread is that of the half means)
    rng = np.random.default_rng(3)
    x, y = rng.gamma(3, size=400_000) / 3, rng.gamma(7, size=400_000) / 7
    for alpha in (2.0, 12.0):
        for law, z in ((theory.pfa_so, np.minimum(x, y)), (theory.pfa_go, np.maximum(x, y))):
            e = np.exp(-alpha * z)
            tol = 6.0 * e.std() / np.sqrt(e.size)
            assert abs(float(law(alpha, 3, 7)) - e.mean()) < tol, (law.__name__, alpha)
    with pytest.raises(ValueError, match="half"):
        theory.pfa_go(1.0, 3, 0)


@pytest.mark.parametrize("kind", ["ca", "go", "so", "os"])
def test_censored_false_alarm_rate_equals_design(kind):
    cfar = CFAR(kind, train=8, guard=2)  # N = 16, a window of 21 cells
    pfa = 1e-2
    power, land = _rows_with_land(seed=41)
    cen = cfar.censored(power, land, pfa)
    hits = power > cen.alpha * cen.noise
    assert not hits[:, land].any() and np.isnan(cen.noise[:, land]).all()
    # CUTs whose lagging window loses 0, 3, 6 and 8 cells to the land
    for lost in (0, 3, 6, 8):
        col = LAND - 11 + lost
        assert cen.n_used[0, col] == 16 - lost
        ok, info = _within(int(hits[:, col].sum()), ROWS, pfa)
        assert ok, (lost, info)
    # the same windows with the land in them: the estimate is swamped, nothing crosses
    if kind != "so":  # (SO takes the sea half: it is the one that keeps its P_FA)
        plain = cfar.detect(power, pfa)
        assert plain[:, LAND - 5].sum() < 0.1 * pfa * ROWS


def test_censored_ca_alpha_is_richards_closed_form_per_count():
    cfar = CFAR("ca", train=8, guard=2)
    power, land = _rows_with_land(seed=42)
    cen = cfar.censored(power[:50], land, 1e-4)
    n = cen.n_used[0]
    ok = np.isfinite(cen.alpha[0])
    np.testing.assert_allclose(cen.alpha[0, ok], n[ok] * (1e-4 ** (-1.0 / n[ok]) - 1.0),
                               rtol=1e-10)
    # the estimate is the mean of the sea cells of the window
    col = LAND - 6  # lagging training cells LAND - 3 .. LAND + 4: 3 of sea
    sea = np.r_[col - 10:col - 2, col + 3:LAND]
    assert n[col] == sea.size == 11
    assert cen.noise[7, col] == pytest.approx(power[7, sea].mean(), rel=1e-12)


def test_too_few_sea_cells_left_untested_and_counted():
    cfar = CFAR("ca", train=8, guard=2)
    power, land = _rows_with_land(seed=43)
    cen = cfar.censored(power[:10], land, 1e-4, min_fraction=0.75)  # 12 of 16 cells
    short = np.flatnonzero(cen.short[0])
    # the lagging half loses (col - LAND + 11) cells from col = LAND - 10 on: 12 are kept
    # up to col = LAND - 7; LAND - 6 .. LAND - 1 keep fewer
    np.testing.assert_array_equal(short, np.arange(LAND - 6, LAND))
    assert np.isnan(cen.alpha[:, short]).all() and (cen.n_used[:, short] == 0).all()
    assert cen.n_censored == 10 * 4  # LAND - 10 .. LAND - 7, one to four cells lost
    with pytest.raises(ValueError, match="min_fraction"):
        cfar.censored(power[:10], land, 1e-4, min_fraction=0.0)
    with pytest.raises(ValueError, match="exclude"):
        cfar.censored(power[:10], land[:30], 1e-4)


def test_target_beside_the_land_detected_with_censoring_masked_without():
    # a Swerling 1 target of 20 dB five cells from the shore: six of its 16 training
    # cells are land. Without censoring the land lifts the threshold above it (masking);
    # with censoring its P_D is Richards' (1 + alpha_n / (n (1 + S)))^-n with n = 10
    cfar = CFAR("ca", train=8, guard=2)
    pfa, snr = 1e-4, 100.0
    power, land = _rows_with_land(seed=44)
    col = LAND - 5
    power[:, col] = np.random.default_rng(45).exponential(1.0 + snr, ROWS)
    cen = cfar.censored(power, land, pfa)
    n = int(cen.n_used[0, col])
    assert n == 10
    alpha_n = n * (pfa ** (-1.0 / n) - 1.0)
    pd = (1.0 + alpha_n / (n * (1.0 + snr))) ** -n
    found = int((power[:, col] > cen.alpha[:, col] * cen.noise[:, col]).sum())
    ok, info = _within(found, ROWS, pd)
    assert ok, info
    assert pd > 0.8
    masked = int(cfar.detect(power, pfa)[:, col].sum())
    assert masked < 0.01 * ROWS  # the uncensored CA finds it (almost) never


@pytest.mark.parametrize("kind", ["ca", "os"])
def test_censored_2d_circular_false_alarm_rate(kind):
    # 2-D windows (azimuth x range) wrapping in azimuth, a land block of a few range
    # columns: the CUT two columns before it loses the block's cells of its window
    cfar = CFAR(kind, train=(2, 4), guard=(1, 1), circular=True)
    pfa = 0.1
    rng = np.random.default_rng(46)
    power = rng.exponential(1.0, (400, 7, 18))
    land = np.zeros((7, 18), bool)
    land[:, 15:] = True
    power[..., land] = 1e3
    cen = cfar.censored(power, land, pfa)
    # CUT at column 12: range window 12 - 6 .. 12 + 6, of which 15, 16, 17 are land,
    # 7 rows each (all azimuths, wrapping)
    assert cen.n_used[0, 3, 12] == cfar.n_train - 3 * 7
    hits = power > cen.alpha * cen.noise
    ok, info = _within(int(hits[:, 3, 12].sum()), 400, pfa)
    assert ok, info
    # and the uncensored estimate where the window holds no land
    np.testing.assert_allclose(cen.noise[:, :, 8], cfar.noise(power)[:, :, 8], rtol=1e-12)
    # the first azimuth's window wraps onto the last ones: its kept cells by hand
    fp = cfar.footprints[0]
    rows = np.r_[np.arange(-3, 0) % 7, np.arange(0, 4)]
    cols = np.arange(12 - 5, 12 + 6)
    window = power[9][np.ix_(rows, cols)]
    kept = window[fp & ~land[np.ix_(rows, cols)]]
    if kind == "ca":
        want = kept.mean()
    else:  # Rohling's rank at the kept cells' share of the window, k(n) = round(k n / N)
        want = np.sort(kept)[round(cfar.rank * kept.size / cfar.n_train) - 1]
    assert cen.noise[9, 0, 12] == pytest.approx(want, rel=1e-12)
