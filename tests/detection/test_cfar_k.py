"""CA-CFAR in K-distributed clutter: the closed forms D7-D8 (docs/detection.md).

References: the compound K model (gamma texture x exponential speckle) of Ward, Tough &
Watts (2013), ch. 4; CA-CFAR in K clutter with the texture constant over the window or
independent from cell to cell (Watts 1985; Armstrong & Griffiths 1991, whose worst case
is the spatially uncorrelated texture; Watts 1996); Tricomi's U (Abramowitz & Stegun
13.2.5) and the exponential integral E1 (A&S 5.1.1).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate, special, stats

from seaecho.detection.theory import k_intensity_laplace, pfa_ca, pfa_ca_k, scale_for_pfa


def _laplace_quad(s: float, nu: float) -> float:
    def f(x):
        return np.exp(nu * np.log(nu) - special.gammaln(nu) + (nu - 1.0) * np.log(x)
                      - nu * x) / (1.0 + s * x)
    return (integrate.quad(f, 0.0, 1.0, limit=500, epsabs=0.0, epsrel=1e-11)[0]
            + integrate.quad(f, 1.0, np.inf, limit=500, epsabs=0.0, epsrel=1e-11)[0])


@pytest.mark.parametrize("nu", [0.1, 0.5, 2.5, 10.0, 60.0])
def test_k_laplace_transform_against_quadrature(nu):
    """Eq D7 (Tricomi's U, its asymptotic series and the Gauss-Laguerre fallback) equals
    E_x[1/(1 + s x)] over the gamma texture by adaptive quadrature, 1e-7 relative."""
    s = np.array([1e-6, 1e-3, 0.1, 1.0, 10.0, 1e3])
    got = k_intensity_laplace(s, nu)
    want = np.array([_laplace_quad(v, nu) for v in s])
    np.testing.assert_allclose(got, want, rtol=1e-7)
    assert float(k_intensity_laplace(0.0, nu)) == 1.0


def test_k_laplace_transform_exponential_texture():
    """nu = 1: E[1/(1 + s x)], x ~ Exp(1), is (1/s) e^(1/s) E1(1/s) (A&S 5.1.1)."""
    s = np.array([0.05, 0.5, 2.0, 20.0])
    np.testing.assert_allclose(k_intensity_laplace(s, 1.0),
                               np.exp(1.0 / s) * special.exp1(1.0 / s) / s, rtol=1e-10)


def test_ca_cfar_in_k_clutter_against_monte_carlo():
    """Eq D8 against a Monte Carlo CA-CFAR over independent K cells (N = 16, nu = 0.5,
    threshold of design 1e-2 in exponential noise): within the exact binomial interval
    of probability 1 - 1e-6."""
    rng = np.random.default_rng(20261127)
    n, nu, trials = 16, 0.5, 100_000
    alpha = scale_for_pfa(pfa_ca, 1e-2, n)
    z = rng.gamma(nu, 1.0 / nu, (trials, n + 1)) * rng.exponential(1.0, (trials, n + 1))
    k = int(np.sum(z[:, 0] > alpha * z[:, 1:].mean(axis=1)))
    p = float(pfa_ca_k(alpha, n, nu))
    lo, hi = stats.binom.ppf([0.5e-6, 1.0 - 0.5e-6], trials, p)
    assert lo <= k <= hi, (k / trials, p)
    assert p > 5.0 * 1e-2  # spiky clutter: five times the design and more


def test_ca_cfar_in_k_clutter_limits():
    """The texture constant over the window gives eq D1 exactly; independent textures
    give more false alarms, the more the spikier, and tend to eq D1 as nu grows."""
    n = 16
    alpha = scale_for_pfa(pfa_ca, 1e-4, n)
    assert float(pfa_ca_k(alpha, n, 0.3, texture="constant")) == pytest.approx(1e-4,
                                                                                 rel=1e-9)
    nus = np.array([0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0])
    p = np.array([float(pfa_ca_k(alpha, n, v)) for v in nus])
    assert np.all(np.diff(p) < 0.0)
    assert np.all(p > 1e-4)
    assert p[-1] / 1e-4 - 1.0 < 0.25  # nu = 100: within 25 % of the design
    assert p[0] / 1e-4 > 100.0        # nu = 0.1: over a hundred times the design
    # the threshold that holds the design in independent K clutter is higher
    a_k = scale_for_pfa(pfa_ca_k, 1e-4, n, 1.0)
    assert float(pfa_ca_k(a_k, n, 1.0)) == pytest.approx(1e-4, rel=1e-8)
    assert a_k > alpha


@pytest.mark.parametrize("kw, msg", [({"nu": 0.0}, "nu = 0.0"), ({"nu": 150.0}, "(0, 100]"),
                                     ({"nu": 1.0, "texture": "swell"}, "texture")])
def test_ca_cfar_in_k_clutter_refuses(kw, msg):
    with pytest.raises(ValueError, match=msg.replace("(", r"\(").replace("]", r"\]")):
        pfa_ca_k(5.0, 16, **kw)
