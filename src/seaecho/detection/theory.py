"""Closed forms of detection in exponential (square-law, complex Gaussian) noise.

Every threshold a detector of :mod:`seaecho.detection` applies is solved from these
formulas, and the tests compare the detectors' measured rates with them. Notation (the
symbols of docs/detection.md):

==============  ================================================================  ======
symbol          meaning                                                           name
==============  ================================================================  ======
N               training cells of a cell-averaging CFAR                          ``n``
n               training cells of one half (leading or lagging) of a GO/SO CFAR   ``n_half``
m, n            the two halves of a censored GO/SO window (D9)                   ``n_half, n_lag``
k               rank of the order statistic of an OS-CFAR (1 = smallest)          ``k``
alpha           threshold multiplier on the detector's noise estimate             ``alpha``
S               signal-to-noise ratio of the cell under test (linear)             ``snr``
w               clutter-map weight of the newest scan                             ``w``
==============  ================================================================  ======

The noise in a cell is exponential of mean 1 (the power of circular complex Gaussian
noise); the estimates are the *mean* of the training cells (CA), the larger or smaller of
the two half means (GO, SO), the k-th smallest cell (OS), the exponentially weighted mean
over past scans (clutter map). A Swerling 1 or 2 target makes the power of its cell
exponential of mean 1 + S, so its probability of detection is the false-alarm formula with
alpha / (1 + S) (Richards 2014, sec. 7.2): one law, used once.

References
----------
Richards, M. A. (2014). *Fundamentals of Radar Signal Processing*, 2nd ed. McGraw-Hill:
ch. 6 (Marcum Q, Swerling targets, binary integration), ch. 7 (CA, GO, SO and OS CFAR,
clutter maps).
Rohling, H. (1983). Radar CFAR thresholding in clutter and multiple target situations.
*IEEE Trans. Aerosp. Electron. Syst.* AES-19(4), 608-621.
Gandhi, P. P. and Kassam, S. A. (1988). Analysis of CFAR processors in nonhomogeneous
background. *IEEE Trans. Aerosp. Electron. Syst.* 24(4), 427-445 (GO and SO in homogeneous
noise, after Hansen and Weiss).
Ward, K. D., Tough, R. J. A. and Watts, S. (2013). *Sea Clutter: Scattering, the K
Distribution and Radar Performance*, 2nd ed. IET: the compound (K) model of sea clutter,
gamma texture times exponential speckle (ch. 4), and CFAR detection in it, where the
texture is either constant over the CFAR window or varies within it.
Watts, S. (1985). Radar detection prediction in sea clutter using the compound
K-distribution model. *IEE Proc. F* 132(7), 613-620.
Watts, S. (1996). Cell-averaging CFAR gain in spatially correlated K-distributed
clutter. *IEE Proc. Radar Sonar Navig.* 143(5), 321-327.
Armstrong, B. C. and Griffiths, H. D. (1991). CFAR detection of fluctuating targets in
spatially correlated K-distributed clutter. *IEE Proc. F* 138(2), 139-152.
Abramowitz, M. and Stegun, I. A. (1964). *Handbook of Mathematical Functions*, NBS:
13.2.5 (Tricomi's U as an integral), 13.5.2 (its asymptotic series).
Nitzberg, R. (1986). Clutter map CFAR analysis. *IEEE Trans. Aerosp. Electron. Syst.*
AES-22(4), 419-421 (the exponentially weighted map; the clutter-map idea goes back to
Nitzberg's and others' work of the late 1970s).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import integrate, optimize, special, stats

__all__ = ["k_intensity_laplace", "pd_ca_swerling0", "pd_swerling1", "pfa_ca",
           "pfa_ca_k", "pfa_clutter_map", "pfa_go", "pfa_m_of_n", "pfa_os", "pfa_so",
           "scale_for_pfa"]


def pfa_ca(alpha: ArrayLike, n: int) -> NDArray:
    """False-alarm probability of a cell-averaging CFAR (Richards 2014, ch. 7).

    .. math:: P_{FA} = (1 + \\alpha / N)^{-N}

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the mean of the N training cells [-].
    n : int
        Training cells N.
    """
    return (1.0 + np.asarray(alpha, dtype=float) / n) ** (-float(n))


def k_intensity_laplace(s: ArrayLike, nu: float) -> NDArray:
    """E[exp(-s z)] of a K-distributed intensity z of unit mean and shape ``nu``.

    z = x y, texture x ~ Gamma(nu, mean 1), speckle y ~ Exp(1) (Ward, Tough & Watts 2013,
    ch. 4), so E[exp(-s z)] = E_x[1 / (1 + s x)], and with Tricomi's U (Abramowitz &
    Stegun 13.2.5, t = s x):

    phi(s) = nu^nu / Gamma(nu) int_0^inf x^(nu-1) exp(-nu x) / (1 + s x) dx
           = (nu / s)^nu U(nu, nu, nu / s)                                       (D7)

    Parameters
    ----------
    s : array_like
        Laplace variable, s >= 0 [-].
    nu : float
        K shape parameter (> 0) [-].
    """
    s = np.asarray(s, dtype=float)
    out = np.ones_like(s)
    pos = s > 0.0
    z = nu / s[pos]
    # z^nu U(nu, nu, z) -> 1 as z -> infinity, where scipy's hyperu underflows: the
    # asymptotic series 1 - nu/z + nu (nu + 1)/z^2 - ... (A&S 13.5.2) takes over, its
    # error below (nu + 3)^4 / z^4 < 1e-12
    big = z > 1e3 * (nu + 3.0) ** 2
    u = np.empty_like(z)
    zs = z[~big]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        us = np.exp(nu * np.log(zs) + np.log(special.hyperu(nu, nu, zs)))
    bad = ~np.isfinite(us) | (us <= 0.0)
    if bad.any():
        # scipy's hyperu fails (NaN, or 0 by underflow) for z below about nu when
        # nu >~ 3: there the gamma texture sits near 1, far from the pole at x = -1/s,
        # and generalised Gauss-Laguerre quadrature of E_x[1/(1 + s x)] converges fast
        y, w = special.roots_genlaguerre(160, nu - 1.0)
        w = np.exp(np.log(w) - special.gammaln(nu))
        us[bad] = (w / (1.0 + (nu / zs[bad])[:, None] * (y / nu))).sum(axis=-1)
    u[~big] = us
    zb = z[big]
    u[big] = (1.0 - nu / zb + nu * (nu + 1.0) / zb**2
              - nu * (nu + 1.0) * (nu + 2.0) / zb**3)
    out[pos] = u
    return out


def pfa_ca_k(alpha: ArrayLike, n: int, nu: float, texture: str = "independent",
             nodes: int = 160) -> NDArray:
    """False-alarm probability of a CA-CFAR (eq D1's threshold) in K clutter, no noise.

    Every cell's intensity is z = x y (texture x ~ Gamma(nu, mean 1), speckle y ~
    Exp(1)); the CFAR compares the cell under test z_0 with alpha times the mean of N
    training cells. Two limits of the texture's spatial correlation (Watts 1985, 1996;
    Armstrong & Griffiths 1991, whose worst case is the uncorrelated texture; Ward, Tough
    & Watts 2013, CFAR detection in K clutter):

    * ``texture="constant"``: one texture over the CUT and the window (texture
      correlated over the window): conditioned on x the cells are exponential of mean x,
      so P_FA is eq D1 whatever x: the CA-CFAR keeps its design (the loss of a CA-CFAR
      there is in detection, not in false alarms).
    * ``texture="independent"``: an independent texture in every cell. Conditioned on
      x_0 and the training intensities, P(z_0 > alpha mean z_i) = exp(-alpha sum z_i /
      (N x_0)); averaging over the independent z_i (eq D7) and then over x_0,

      P_FA = E_x0[phi(alpha / (N x_0))^N]                                   (D8)

      evaluated by generalised Gauss-Laguerre quadrature over nu x_0 (``nodes`` nodes).
      It tends to eq D1 as nu -> infinity.

    Partly correlated clutter usually lies between the two; it is not a strict bound
    (a texture anti-correlated between the CUT and its neighbours, a lit crest next to
    a shadowed trough, gives more false alarms than independent textures).

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the training mean [-].
    n : int
        Training cells N.
    nu : float
        K shape parameter, 0 < nu <= 100 [-].
    texture : {"independent", "constant"}
        The texture's correlation over the window (the two limits above).
    nodes : int
        Quadrature nodes of eq D8.

    Raises
    ------
    ValueError
        ``nu`` not positive, or an unknown ``texture``.
    """
    if not 0.0 < nu <= 100.0:
        raise ValueError(f"nu = {nu}: the K shape parameter must be in (0, 100] (the "
                         "quadrature of eq D8; beyond, use eq D1's exponential law)")
    if texture == "constant":
        return pfa_ca(alpha, n)
    if texture != "independent":
        raise ValueError(f"texture = {texture!r}: use 'independent' or 'constant'")
    a = np.asarray(alpha, dtype=float)
    y, w = special.roots_genlaguerre(nodes, nu - 1.0)
    x0 = y / nu  # texture of the CUT, Gamma(nu, mean 1)
    phi = k_intensity_laplace(a[..., None] / (n * x0), nu)
    log_w = np.log(w) - special.gammaln(nu)
    return np.exp(special.logsumexp(log_w + n * np.log(np.maximum(phi, 1e-300)), axis=-1))


def _pfa_so_sum(alpha: ArrayLike, m: int, n: int) -> NDArray:
    """E[exp(-alpha min(A, B))], A and B the means of m and n independent unit
    exponentials (the SO statistic; eq D9).

    A has the density m^m t^(m-1) e^(-m t) / (m - 1)! and P(B > t) = sum_{j<n} e^(-n t)
    (n t)^j / j!, so E[e^(-alpha A) 1(A < B)] = sum_{j<n} C(m - 1 + j, j) m^m n^j
    (alpha + m + n)^-(m + j), and the same with m, n swapped for B < A. For m = n it is
    Gandhi & Kassam's sum with T = alpha / n (eq D3).
    """
    a = np.asarray(alpha, dtype=float)[..., None]

    def below(p: int, q: int) -> NDArray:  # E[e^(-alpha A) 1(A < B)], A of p, B of q cells
        j = np.arange(q, dtype=float)
        # C(p - 1 + j, j) in logs: exact for any p without overflow
        log_c = special.gammaln(p + j) - special.gammaln(p) - special.gammaln(j + 1.0)
        return np.exp(log_c + p * np.log(p) + j * np.log(q)
                      - (p + j) * np.log(a + p + q)).sum(axis=-1)

    return below(m, n) + below(n, m)


def _halves(n_half: int, n_lag: int | None) -> tuple[int, int]:
    m, n = int(n_half), int(n_half if n_lag is None else n_lag)
    if m < 1 or n < 1:
        raise ValueError(f"n_half = {n_half}, n_lag = {n_lag}: each half needs at least "
                         "one training cell")
    return m, n


def pfa_so(alpha: ArrayLike, n_half: int, n_lag: int | None = None) -> NDArray:
    """False-alarm probability of a smallest-of CFAR (Gandhi & Kassam 1988, sec. III).

    .. math:: P_{FA} = 2 \\sum_{j=0}^{n-1} \\binom{n-1+j}{j} (2 + T)^{-(n+j)},
              \\quad T = \\alpha / n

    With halves of m and n cells (a window censored unevenly, the land cells left out),
    the estimate is the smaller of the mean of m and the mean of n cells, and

    .. math:: P_{FA} = \\sum_{j<n} \\binom{m-1+j}{j} \\frac{m^m n^j}{(\\alpha+m+n)^{m+j}}
              + \\sum_{i<m} \\binom{n-1+i}{i} \\frac{n^n m^i}{(\\alpha+m+n)^{n+i}}

    (eq D9, :func:`_pfa_so_sum`: the order statistics of two independent gamma
    variables; the first form at m = n).

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the smaller of the two half means [-].
    n_half : int
        Training cells n of each half (the leading half's m with ``n_lag``).
    n_lag : int, optional
        Training cells of the lagging half, if not ``n_half``.
    """
    return _pfa_so_sum(alpha, *_halves(n_half, n_lag))


def pfa_go(alpha: ArrayLike, n_half: int, n_lag: int | None = None) -> NDArray:
    """False-alarm probability of a greatest-of CFAR (Gandhi & Kassam 1988, sec. III).

    Since max + min = A + B, E[e^{-alpha max}] + E[e^{-alpha min}] = E[e^{-alpha A}] +
    E[e^{-alpha B}], each half's mean a CA estimate (eq D1):

    .. math:: P_{FA} = (1 + \\alpha / m)^{-m} + (1 + \\alpha / n)^{-n} - P_{FA,SO}

    (2 (1 + T)^{-n} - P_SO with T = alpha / n for equal halves, eq D2; halves of m and n
    cells: eq D9's P_SO).

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the larger of the two half means [-].
    n_half : int
        Training cells n of each half (the leading half's m with ``n_lag``).
    n_lag : int, optional
        Training cells of the lagging half, if not ``n_half``.
    """
    m, n = _halves(n_half, n_lag)
    return pfa_ca(alpha, m) + pfa_ca(alpha, n) - _pfa_so_sum(alpha, m, n)


def pfa_os(alpha: ArrayLike, n: int, k: int) -> NDArray:
    """False-alarm probability of an ordered-statistic CFAR (Rohling 1983, sec. IV).

    .. math:: P_{FA} = \\prod_{i=0}^{k-1} \\frac{N - i}{N - i + \\alpha}

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the k-th smallest of the N training cells [-].
    n, k : int
        Training cells N and rank k (1 <= k <= N).
    """
    i = np.arange(k, dtype=float)
    a = np.asarray(alpha, dtype=float)[..., None]
    return np.exp(np.sum(np.log(n - i) - np.log(n - i + a), axis=-1))


def pfa_clutter_map(alpha: ArrayLike, w: float) -> NDArray:
    """False-alarm probability of an exponentially weighted clutter map in steady state
    (Nitzberg 1986).

    The map holds q = w sum_{m>=0} (1 - w)^m x_{-1-m} over the past scans, so

    .. math:: P_{FA} = \\prod_{m=0}^{\\infty} \\left[1 + \\alpha w (1 - w)^m\\right]^{-1}

    (terms below 1e-17 dropped).

    Parameters
    ----------
    alpha : array_like
        Threshold multiplier on the map [-].
    w : float
        Weight of the newest scan, 0 < w <= 1.
    """
    a = np.asarray(alpha, dtype=float)
    top = max(float(np.max(a)) * w, 1e-300) if a.size else 1.0
    m_max = 1 if w >= 1.0 else int(np.ceil(np.log(1e-17 / top) / np.log1p(-w))) + 1
    m = np.arange(max(m_max, 1), dtype=float)
    terms = a[..., None] * w * (1.0 - w) ** m
    return np.exp(-np.log1p(terms).sum(axis=-1))


def pd_swerling1(pfa_law, alpha: ArrayLike, snr: ArrayLike, *args) -> NDArray:
    """Probability of detection of a Swerling 1 or 2 target by a CFAR whose false-alarm
    law is ``pfa_law(alpha, *args)`` (Richards 2014, ch. 7, for CA).

    The target's cell is exponential of mean 1 + S, so P_D(alpha, S) =
    P_FA(alpha / (1 + S)); for CA, (1 + alpha / (N (1 + S)))^{-N}.

    Parameters
    ----------
    pfa_law : callable
        :func:`pfa_ca`, :func:`pfa_go`, :func:`pfa_so`, :func:`pfa_os`,
        :func:`pfa_clutter_map`.
    alpha : array_like
        Threshold multiplier [-].
    snr : array_like
        Mean signal-to-noise ratio S of the target's cell (linear) [-].
    """
    return pfa_law(np.asarray(alpha, dtype=float) / (1.0 + np.asarray(snr, dtype=float)),
                   *args)


def pd_ca_swerling0(alpha: float, n: int, snr: float) -> float:
    """Probability of detection of a non-fluctuating (Swerling 0) target by a CA-CFAR.

    For a known noise level the square-law detector's P_D is Marcum's Q,
    Q_1(sqrt(2 S), sqrt(2 tau)) (Richards 2014, ch. 6): 2|x|^2 is non-central
    chi-square with 2 degrees of freedom and non-centrality 2 S. The CA threshold
    tau = alpha Z / N with Z ~ Gamma(N, 1) (the sum of the training cells), so

    .. math:: P_D = \\int_0^\\infty Q_1(\\sqrt{2S}, \\sqrt{2 \\alpha z / N})
              \\frac{z^{N-1} e^{-z}}{(N-1)!} dz

    Parameters
    ----------
    alpha : float
        Threshold multiplier on the training mean [-].
    n : int
        Training cells N.
    snr : float
        Signal-to-noise ratio S (linear) [-].
    """
    def f(z):
        return stats.ncx2.sf(2.0 * alpha * z / n, 2, 2.0 * snr) * stats.gamma.pdf(z, n)

    lo, hi = stats.gamma.ppf([1e-15, 1.0 - 1e-15], n)
    return float(integrate.quad(f, lo, hi, epsabs=1e-13, epsrel=1e-10, limit=200)[0])


def pfa_m_of_n(p: ArrayLike, m: int, n: int) -> NDArray:
    """Probability that at least M of N independent looks cross, each with probability p
    (binary integration, Richards 2014, ch. 6).

    .. math:: P = \\sum_{j=M}^{N} \\binom{N}{j} p^j (1 - p)^{N - j}
    """
    return stats.binom.sf(m - 1, n, np.asarray(p, dtype=float))


def scale_for_pfa(pfa_law, pfa: float, *args) -> float:
    """The threshold multiplier alpha with ``pfa_law(alpha, *args) == pfa``.

    The laws decrease monotonically in alpha; alpha is found by Brent's method on
    log P_FA (CA has the closed form alpha = N (P_FA^{-1/N} - 1), Richards 2014,
    ch. 7, which this reproduces).

    Raises
    ------
    ValueError
        ``pfa`` outside (0, 1).
    """
    if not (0.0 < pfa < 1.0):
        raise ValueError(f"pfa = {pfa}: the design false-alarm probability must be in "
                         "(0, 1)")
    target = np.log(pfa)

    def g(a):
        return float(np.log(pfa_law(a, *args))) - target

    hi = 1.0
    while g(hi) > 0.0:
        hi *= 4.0
        if hi > 1e300:
            raise ValueError(f"pfa = {pfa}: no threshold reaches it with these training "
                             "cells")
    return float(optimize.brentq(g, 0.0, hi, xtol=1e-14 * hi, rtol=1e-14, maxiter=500))
