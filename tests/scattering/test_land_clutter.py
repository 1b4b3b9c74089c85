"""The constant-gamma land clutter law and its Weibull amplitudes.

References: Barton, "Land clutter models for radar design and analysis", Proc. IEEE
73(2) (1985) (sigma0 = gamma sin psi, gamma by terrain at 10 GHz, gamma ~ f^(1/2));
Willis, *Bistatic Radar* (2005), section 9.2 (the bistatic form); Billingsley,
*Low-Angle Radar Land Clutter* (2002), chapter 2 (Weibull shape a_w).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from seaecho.rng import generator
from seaecho.scattering.land import (
    GAMMA_DB,
    constant_gamma_sigma0,
    terrain_gamma_db,
    weibull_power,
)


@pytest.mark.parametrize("psi_deg", [0.5, 1.0, 5.0, 30.0])
def test_sigma0_is_gamma_sin_psi_at_a_known_grazing(psi_deg):
    gamma = 10 ** (-15 / 10)  # farmland (Barton 1985)
    psi = np.deg2rad(psi_deg)
    assert constant_gamma_sigma0(gamma, np.sin(psi)) == pytest.approx(gamma * np.sin(psi),
                                                                      rel=1e-15)
    # the bistatic form is the monostatic one when both grazing angles are equal, and
    # the geometric mean of the two otherwise (Willis 2005)
    assert constant_gamma_sigma0(gamma, np.sin(psi), np.sin(psi)) == pytest.approx(
        gamma * np.sin(psi), rel=1e-15)
    assert constant_gamma_sigma0(gamma, np.sin(psi), np.sin(2 * psi)) == pytest.approx(
        gamma * math.sqrt(np.sin(psi) * np.sin(2 * psi)), rel=1e-15)
    assert constant_gamma_sigma0(gamma, -0.1) == 0.0  # not lit


def test_gamma_table_and_its_frequency_law():
    # at 10 GHz: farmland -15, wooded hills -10, flatland -20 dB (Nathanson, Reilly &
    # Cohen 1999, as restated by MATLAB's surfacegamma; Barton 1985 not read), mountains
    # -5 dB (Barton 1985, not checked); gamma grows as f^(1/2): +5 log10(f / 10 GHz) dB
    # (the same surfacegamma, citing Barton 1985)
    assert terrain_gamma_db("farmland", 10e9) == GAMMA_DB["farmland"] == -15.0
    assert terrain_gamma_db("mountains", 10e9) == -5.0
    assert terrain_gamma_db("flatland", 10e9) == -20.0
    assert terrain_gamma_db("wooded-hills", 10e9) == -10.0
    assert terrain_gamma_db("wooded-hills", 40e9) == pytest.approx(-10.0 + 3.0103, abs=1e-4)
    assert terrain_gamma_db("urban", 3e9) == pytest.approx(-5.0 - 2.6144, abs=1e-4)
    with pytest.raises(ValueError, match="terrain"):
        terrain_gamma_db("marsh", 10e9)


@pytest.mark.parametrize("shape", [1.0, 2.0, 3.0])
def test_weibull_power_has_unit_mean_and_billingsleys_distribution(shape):
    w = weibull_power(shape, 40_000, generator(2, "land", 0))
    b = 1.0 / math.gamma(1.0 + shape)
    # P(w > x) = exp(-(x / b)^(1 / a_w)) (Billingsley 2002): Kolmogorov-Smirnov
    ks = stats.kstest(w, lambda x: 1.0 - np.exp(-(np.maximum(x, 0) / b) ** (1.0 / shape)))
    assert ks.pvalue > 0.01
    # mean 1; its standard error sqrt(Var / n), Var = Gamma(1 + 2 a) / Gamma(1 + a)^2 - 1
    var = math.gamma(1 + 2 * shape) / math.gamma(1 + shape) ** 2 - 1
    assert abs(w.mean() - 1.0) < 4 * math.sqrt(var / w.size)
    if shape == 1.0:  # Rayleigh amplitudes: exponential power
        assert stats.kstest(w, "expon").pvalue > 0.01
