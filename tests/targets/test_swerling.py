"""Swerling targets against the closed forms of their statistics.

The cases (P. Swerling, IRE Trans. Inform. Theory IT-6(2), 269-308, 1960; M. I. Skolnik,
*Introduction to Radar Systems*, 3rd ed. 2001, section 2.8): F = sigma / mean sigma is
exponential (chi-square with 2 degrees of freedom, unit mean: E F = 1, E F^2 = 2, P(F >
x) = exp(-x)) for cases 1 and 2, chi-square with 4 degrees of freedom of unit mean (E F =
1, E F^2 = 3/2, P(F > x) = (1 + 2x) exp(-2x)) for cases 3 and 4; 1 and 3 keep F over a
dwell and draw independently from dwell to dwell, 2 and 4 draw at every pulse.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from seaecho.build import build_radar
from seaecho.config import SceneError, parse_scene
from seaecho.radar.system import RadarSystem
from seaecho.targets.swerling import dwell_index, swerling_factor

N = 100_000  # draws: the standard error of a mean of F is 1 / sqrt(N) = 0.003 (m = 1)


def _draws(case, n=N, dwell=1):
    # one target per column, n pulses: the counter runs over pulses (or dwells)
    return swerling_factor(7, [case], np.arange(n)[:, None], dwell)[:, 0]


@pytest.mark.parametrize(("case", "second"), [(1, 2.0), (2, 2.0), (3, 1.5), (4, 1.5)])
def test_moments_are_chi_square_closed_forms(case, second):
    # cases 1, 3 with a dwell of one pulse draw at every pulse: N independent draws
    f = _draws(case)
    assert f.min() >= 0.0
    assert f.mean() == pytest.approx(1.0, abs=5 / np.sqrt(N))  # E F = 1
    # E F^2 = 1 + 1/m; sd of F^2 is sqrt(20) (m = 1) or sqrt(4.5 ... ) < 5: 5 sigma
    assert np.mean(f**2) == pytest.approx(second, abs=25 / np.sqrt(N))


@pytest.mark.parametrize("case", [1, 2, 3, 4])
def test_distribution_is_chi_square(case):
    # Kolmogorov-Smirnov against the closed-form CDF (exponential; gamma of shape 2,
    # scale 1/2): the draws are not distinguishable at the 1e-3 level (fixed seed)
    f = _draws(case, 20_000)
    dist = stats.expon() if case in (1, 2) else stats.gamma(2, scale=0.5)
    assert stats.kstest(f, dist.cdf).pvalue > 1e-3


def test_case_0_is_steady():
    assert np.all(_draws(0, 100) == 1.0)


@pytest.mark.parametrize("case", [1, 3])
def test_scan_to_scan_constant_within_a_dwell_independent_between(case):
    dwell = 16
    f = _draws(case, 16 * 4000, dwell).reshape(4000, dwell)
    assert np.all(f == f[:, :1])  # one value per dwell
    per_dwell = f[:, 0]
    r = np.corrcoef(per_dwell[:-1], per_dwell[1:])[0, 1]
    assert abs(r) < 5 / np.sqrt(per_dwell.size)  # successive dwells uncorrelated


@pytest.mark.parametrize("case", [2, 4])
def test_pulse_to_pulse_uncorrelated(case):
    f = _draws(case, N, dwell=16)  # the dwell does not matter for cases 2 and 4
    r = np.corrcoef(f[:-1], f[1:])[0, 1]
    assert abs(r) < 5 / np.sqrt(N)


def test_draws_depend_only_on_seed_target_and_index():
    # any order of pulses, any subset of targets: the same numbers
    cases = np.array([1, 2, 3, 4, 0, 2])
    p = np.arange(50)
    full = swerling_factor(3, cases, p[:, None], 5)
    rev = swerling_factor(3, cases, p[::-1, None], 5)[::-1]
    np.testing.assert_array_equal(full, rev)
    one = swerling_factor(3, cases[3:4], p[:, None], 5, target=[3])
    np.testing.assert_array_equal(one[:, 0], full[:, 3])
    # another seed, other numbers; targets of the same case are independent
    assert not np.array_equal(swerling_factor(4, cases, p[:, None], 5), full)
    assert not np.array_equal(full[:, 1], full[:, 5])


def test_dwell_index():
    np.testing.assert_array_equal(dwell_index([0, 3, 4, 9], 4), [0, 0, 1, 2])
    with pytest.raises(ValueError, match="dwell_pulses"):
        dwell_index(0, 0)


def _scene(swerling, n_pulses=400, **target):
    t = {"position_m": (5.0, 0.0, 0.0), "rcs_m2": 3.0, **target}
    if swerling is not None:
        t["swerling"] = swerling
    return parse_scene({
        "sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64},
        "radar": {"carrier_frequency_hz": 9.4e9, "sampling_rate_hz": 50e6, "prf_hz": 1e3,
                  "n_pulses": n_pulses, "sea_clutter": False, "cpi_pulses": 8,
                  "waveform": {"kind": "lfm", "bandwidth_hz": 40e6, "duration_s": 2e-6}},
        "transmitter": {"position_m": (-500, 0, 300),
                        "antenna": {"pattern": "isotropic", "look_at_m": (0, 0, 0)}},
        "targets": [t]})


@pytest.mark.parametrize("case", [1, 2, 3, 4])
def test_mean_received_power_equals_the_steady_targets(case):
    # E |echo|^2 = |steady echo|^2 E F = |steady echo|^2: the mean RCS is rcs_m2
    steady = RadarSystem(build_radar(_scene(0)))
    fluct = RadarSystem(build_radar(_scene(case)))
    geo = steady.geometry(0)
    a0 = steady.target_echo(geo, pulse=0).amplitudes
    p0 = float(np.sum(np.abs(np.asarray(a0)) ** 2))
    p = [float(np.sum(np.abs(np.asarray(fluct.target_echo(geo, pulse=i).amplitudes)) ** 2))
         for i in range(400 * 8 if case in (1, 3) else 400) if case in (2, 4) or i % 8 == 0]
    f = np.array(p) / p0
    assert f.mean() == pytest.approx(1.0, abs=5 / np.sqrt(f.size))
    # the per-pulse factor is the model's draw (the phase kept: only |s| scales)
    t = fluct.model.targets
    np.testing.assert_allclose(f[:5], t.rcs_factor(np.arange(5) * (8 if case in (1, 3)
                                                                     else 1))[:, 0],
                               rtol=1e-12)


def test_presets_take_the_published_rcs_and_refuse_other_bands():
    # IMO MSC.192(79) table 2, notes: a 10 m boat without reflector 2.5 m^2 at X band
    sc = _scene(None, preset="small-boat", rcs_m2=None)
    t = build_radar(sc).targets
    assert abs(t.scattering[0, 0, 0]) ** 2 == pytest.approx(2.5)
    assert t.swerling[0] == 1  # the preset's case unless given
    with pytest.raises(SceneError, match="preset"):
        parse_scene({**sc.model_dump(mode="json"),
                     "radar": {**sc.radar.model_dump(mode="json"),
                               "carrier_frequency_hz": 35e9}})
    with pytest.raises(SceneError, match="preset"):
        _scene(None, preset="small-boat")  # and rcs_m2 too
