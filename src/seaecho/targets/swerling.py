"""Fluctuating point targets: the Swerling cases 0 to 4.

A Swerling target presents, at each draw, the radar cross section

.. math::

    \\sigma = \\bar\\sigma\\, F, \\qquad
    p(F) = \\frac{m^m F^{m-1}}{\\Gamma(m)} e^{-m F}\\quad (F \\ge 0)               (T1)

a chi-square variable with 2m degrees of freedom scaled to unit mean (Swerling 1954;
Skolnik 2001, section 2.8): m = 1 (exponential power, Rayleigh amplitude: many
scatterers of comparable size) for cases 1 and 2, m = 2 (one dominant scatterer plus
small ones) for cases 3 and 4. Cases 1 and 3 draw F once per dwell (scan-to-scan: the
pulses of a dwell share it, successive dwells are independent); cases 2 and 4 draw it
at every pulse (pulse-to-pulse). Case 0 (also called 5) is the steady target, F = 1.
The moments of eq T1 are E[F] = 1 and E[F^2] = 1 + 1/m (exponential: 2; chi-square-4:
3/2).

Draws. F of target ``k`` at fluctuation index ``j`` (its dwell for cases 1 and 3, its
pulse for 2 and 4) comes from the ``"target-fluctuation"`` stream by Philox4x32 with the
counter (k, j mod 2^32, j div 2^32, 0) (:func:`seaecho.rng.uniform_pair`), so a pulse's
draws depend only on (seed, target, index): pulses can be computed in any order. With
two uniforms u1, u2 in (0, 1]: m = 1, F = -ln u1; m = 2, F = -(ln u1 + ln u2) / 2 (the
sum of two exponentials of mean 1/2 is the chi-square-4 of unit mean; Devroye 1986,
section IX.3).

What fluctuates is the magnitude of the scattering matrix: s_mn -> sqrt(F) s_mn, its
phases kept (the Swerling models specify the cross section, not the phase).

The dwell. :func:`dwell_index` maps a pulse to its dwell: consecutive blocks of
``dwell_pulses`` pulses (``[radar] cpi_pulses``; the builder chooses that number in one
place, ``seaecho.build.dwell_pulses``).

References
----------
.. [1] P. Swerling, "Probability of detection for fluctuating targets", RAND Research
   Memorandum RM-1217 (1954); IRE Trans. Inform. Theory IT-6(2), 269-308 (1960).
.. [2] M. I. Skolnik, *Introduction to Radar Systems*, 3rd ed., McGraw-Hill (2001),
   section 2.8 (the four cases, their densities eqs 2.42 and 2.43).
.. [3] L. Devroye, *Non-Uniform Random Variate Generation*, Springer (1986), section
   IX.3 (gamma variates of integer shape as sums of exponentials).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..rng import uniform_pair

#: Swerling cases and their (degrees of freedom / 2, fluctuation: "dwell" or "pulse").
SWERLING_CASES: dict[int, tuple[int, str]] = {
    0: (0, "steady"),
    1: (1, "dwell"),
    2: (1, "pulse"),
    3: (2, "dwell"),
    4: (2, "pulse"),
}

#: The random stream of the fluctuations (:data:`seaecho.rng.STREAMS`).
STREAM = "target-fluctuation"


def dwell_index(pulse: ArrayLike, dwell_pulses: int) -> NDArray[np.int64]:
    """The dwell of ``pulse``: ``pulse // dwell_pulses`` [-] (module docstring)."""
    dwell_pulses = int(dwell_pulses)
    if dwell_pulses < 1:
        raise ValueError(f"dwell_pulses = {dwell_pulses}: must be >= 1")
    return np.asarray(pulse, dtype=np.int64) // dwell_pulses


def chi2_unit_mean(m: ArrayLike, u1: ArrayLike, u2: ArrayLike) -> NDArray[np.float64]:
    """F of eq T1 from two uniforms in (0, 1] [-]: 1 for m = 0, -ln u1 for m = 1,
    -(ln u1 + ln u2) / 2 for m = 2 (Devroye 1986, IX.3)."""
    m = np.asarray(m)
    l1, l2 = -np.log(u1), -np.log(u2)
    return np.where(m == 0, 1.0, np.where(m == 1, l1, 0.5 * (l1 + l2)))


def swerling_factor(seed: int, cases: ArrayLike, pulse: ArrayLike, dwell_pulses: int,
                    target: ArrayLike | None = None) -> NDArray[np.float64]:
    """RCS factors F = sigma / sigma_mean of targets at pulses (eq T1) [-].

    Parameters
    ----------
    seed : int
        The scene's seed.
    cases : array_like of int, shape (K,)
        Swerling case of each target (0 to 4).
    pulse : array_like of int
        Pulse indices, broadcast against the targets: e.g. shape (P, 1) for a (P, K)
        result, or a scalar for (K,).
    dwell_pulses : int
        Pulses per dwell (cases 1 and 3).
    target : array_like of int, shape (K,), optional
        The targets' indices in the scene (default 0..K-1): the counter of their draws.

    Returns
    -------
    ndarray, the broadcast shape of ``pulse`` and ``cases``
    """
    cases = np.asarray(cases, dtype=np.int64)
    bad = ~np.isin(cases, list(SWERLING_CASES))
    if bad.any():
        raise ValueError(f"Swerling case {int(cases[bad][0])}: allowed {list(SWERLING_CASES)}")
    k = np.arange(cases.size) if target is None else np.asarray(target, dtype=np.int64)
    m = np.array([SWERLING_CASES[int(c)][0] for c in cases.ravel()]).reshape(cases.shape)
    by_pulse = np.isin(cases, (2, 4))
    p = np.asarray(pulse, dtype=np.int64)
    if np.any(p < 0):
        raise ValueError("pulse indices must be >= 0")
    j = np.where(by_pulse, p, dwell_index(p, dwell_pulses))
    k, j, m = np.broadcast_arrays(k, j, m)
    u1, u2 = uniform_pair(seed, STREAM, (k, j & 0xFFFFFFFF, j >> 32, 0))
    return chi2_unit_mean(m, u1, u2)


__all__ = ["STREAM", "SWERLING_CASES", "chi2_unit_mean", "dwell_index", "swerling_factor"]
