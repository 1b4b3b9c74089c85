"""Complex relative permittivity of sea water (paper section III-A: "dielectric constants").

Two empirical models, selectable by name in :data:`PERMITTIVITY_MODELS`:

- ``"klein-swift"``: single Debye relaxation plus ionic conductivity, Klein & Swift
  (1977), fitted to L- and S-band measurements; the classic choice below X band.
- ``"meissner-wentz"``: double Debye relaxation plus conductivity, Meissner & Wentz
  (2004), fitted to laboratory data and SSM/I brightness temperatures up to 90 GHz
  (their 2004 coefficients; RSS's later update of two of them is not applied).

Both return ``eps_r = eps' - j eps''`` (``eps'' >= 0``), the sign that goes with the
project's ``exp(+j omega t)`` time convention.

Symbols: ``f`` frequency [Hz], ``t`` temperature [degC], ``s`` salinity [psu],
``eps_s`` static permittivity, ``eps_inf`` high-frequency permittivity, ``tau``
relaxation time [s], ``sigma`` ionic conductivity [S/m].

"The paper" is A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic &
polarimetric marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona,
NY, USA, 2006, doi:10.1109/RADAR.2006.1631862.

References
----------
.. [1] Klein, L. A. and Swift, C. T. (1977). An improved model for the dielectric
   constant of sea water at microwave frequencies. *IEEE Trans. Antennas Propag.*
   AP-25(1), 104-111.
.. [2] Meissner, T. and Wentz, F. J. (2004). The complex dielectric constant of pure and
   sea water from microwave satellite observations. *IEEE Trans. Geosci. Remote Sens.*
   42(9), 1836-1849.
.. [3] Stogryn, A. P., Bull, H. T., Rubayi, K. and Iravanchy, S. (1995). The microwave
   dielectric properties of sea and fresh water. GenCorp Aerojet report (conductivity
   and static permittivity used by [2]).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import EPS0
from ..warnings import ValidityWarning


def _check(frequency: NDArray, temperature_c: NDArray, salinity_psu: NDArray,
           model: str, f_max: float, t_range: tuple[float, float]) -> None:
    import warnings

    if np.any(frequency <= 0):
        raise ValueError(f"frequency must be > 0 Hz, got min {np.min(frequency)} Hz")
    if np.any(salinity_psu < 0) or np.any(salinity_psu > 45):
        raise ValueError(f"salinity_psu must be in [0, 45] psu, got {salinity_psu}")
    if np.any(temperature_c < -5) or np.any(temperature_c > 45):
        raise ValueError(f"temperature_c must be in [-5, 45] degC, got {temperature_c}")
    if np.any(frequency > f_max):
        warnings.warn(f"{model}: frequency above {f_max / 1e9:g} GHz is outside the fitted "
                      "range", ValidityWarning, stacklevel=3)
    if np.any(temperature_c < t_range[0]) or np.any(temperature_c > t_range[1]):
        warnings.warn(f"{model}: temperature outside the fitted range {t_range} degC",
                      ValidityWarning, stacklevel=3)


def klein_swift(frequency: ArrayLike, temperature_c: ArrayLike,
                salinity_psu: ArrayLike) -> NDArray:
    """Sea-water permittivity of Klein & Swift (1977).

    .. math::
        \\varepsilon_r = \\varepsilon_\\infty + \\frac{\\varepsilon_s - \\varepsilon_\\infty}
        {1 + j\\omega\\tau} - j\\frac{\\sigma}{\\omega\\varepsilon_0} \\qquad \\text{(W1)}

    with ``eps_inf = 4.9`` and their regressions for ``eps_s(t, s)``, ``tau(t, s)`` and
    ``sigma(t, s)`` (the latter after Weyl's conductivity law).

    Parameters
    ----------
    frequency : array_like
        Frequency [Hz]; fitted below about 10 GHz (a ValidityWarning above 40 GHz).
    temperature_c : array_like
        Water temperature [degC], fitted for -2..30 degC.
    salinity_psu : array_like
        Salinity [psu] (parts per thousand in the paper), 4..35 fitted.

    Returns
    -------
    ndarray of complex
        ``eps' - j eps''`` [-].

    References
    ----------
    .. [1] Klein and Swift (1977), sec. II-III.
    """
    f = np.asarray(frequency, dtype=float)
    t = np.asarray(temperature_c, dtype=float)
    s = np.asarray(salinity_psu, dtype=float)
    _check(f, t, s, "klein-swift", 40e9, (-2.0, 30.0))
    omega = 2.0 * np.pi * f
    eps_inf = 4.9
    # Static permittivity: pure water times a salinity factor.
    eps_s_t = 87.134 - 1.949e-1 * t - 1.276e-2 * t**2 + 2.491e-4 * t**3
    a = 1.0 + 1.613e-5 * s * t - 3.656e-3 * s + 3.210e-5 * s**2 - 4.232e-7 * s**3
    eps_s = eps_s_t * a
    # Relaxation time [s], pure water times a salinity factor.
    tau_t = 1.768e-11 - 6.086e-13 * t + 1.104e-14 * t**2 - 8.111e-17 * t**3
    b = 1.0 + 2.282e-5 * s * t - 7.638e-4 * s - 7.760e-6 * s**2 + 1.105e-8 * s**3
    tau = tau_t * b
    # Ionic conductivity [S/m] at 25 degC, then its temperature law.
    sigma_25 = s * (0.182521 - 1.46192e-3 * s + 2.09324e-5 * s**2 - 1.28205e-7 * s**3)
    delta = 25.0 - t
    beta = (2.033e-2 + 1.266e-4 * delta + 2.464e-6 * delta**2
            - s * (1.849e-5 - 2.551e-7 * delta + 2.551e-8 * delta**2))
    sigma = sigma_25 * np.exp(-delta * beta)
    # Eq W1 (Debye relaxation + conduction), exp(+j omega t) sign.
    return eps_inf + (eps_s - eps_inf) / (1.0 + 1j * omega * tau) - 1j * sigma / (omega * EPS0)


#: Meissner & Wentz (2004): pure-water fit coefficients a_1..a_11.
_MW_A = (5.7230e00, 2.2379e-02, -7.1237e-04, 5.0478e00, -7.0315e-02, 6.0059e-04,
         3.6143e00, 2.8841e-02, 1.3652e-01, 1.4825e-03, 2.4166e-04)
#: Meissner & Wentz (2004): salinity coefficients b_0..b_12.
_MW_B = (-3.56417e-03, 4.74868e-06, 1.15574e-05, 2.39357e-03, -3.13530e-05, 2.52477e-07,
         -6.28908e-03, 1.76032e-04, -9.22144e-05, -1.99723e-02, 1.81176e-04, -2.04265e-03,
         1.57883e-04)


def meissner_wentz(frequency: ArrayLike, temperature_c: ArrayLike,
                   salinity_psu: ArrayLike) -> NDArray:
    """Sea-water permittivity of Meissner & Wentz (2004), double Debye.

    .. math::
        \\varepsilon_r = \\frac{\\varepsilon_s - \\varepsilon_1}{1 + j f/\\nu_1}
        + \\frac{\\varepsilon_1 - \\varepsilon_\\infty}{1 + j f/\\nu_2}
        + \\varepsilon_\\infty - j\\frac{\\sigma}{2\\pi\\varepsilon_0 f} \\qquad \\text{(W2)}

    Pure-water relaxation parameters and their salinity dependence from Meissner &
    Wentz's fits (2004 coefficients), static permittivity and conductivity of Stogryn
    et al. (1995) as they use them.

    Parameters
    ----------
    frequency : array_like
        Frequency [Hz]; fitted up to 90 GHz (a ValidityWarning above 500 GHz).
    temperature_c : array_like
        Water temperature [degC]; -2..29 degC fitted for sea water.
    salinity_psu : array_like
        Salinity [psu], 0..40.

    Returns
    -------
    ndarray of complex
        ``eps' - j eps''`` [-].

    References
    ----------
    .. [1] Meissner and Wentz (2004), sec. IV (double Debye model and fit coefficients).
    """
    f = np.asarray(frequency, dtype=float)
    t = np.asarray(temperature_c, dtype=float)
    s = np.asarray(salinity_psu, dtype=float)
    _check(f, t, s, "meissner-wentz", 500e9, (-2.0, 34.0))
    a = _MW_A
    b = _MW_B
    f_ghz = f * 1e-9
    # Stogryn et al. (1995): static permittivity of pure water.
    eps_s0 = (3.70886e4 - 8.2168e1 * t) / (4.21854e2 + t)
    # Pure-water relaxation parameters (nu in GHz).
    eps_10 = a[0] + a[1] * t + a[2] * t**2
    nu_10 = (45.0 + t) / (a[3] + a[4] * t + a[5] * t**2)
    eps_inf0 = a[6] + a[7] * t
    nu_20 = (45.0 + t) / (a[8] + a[9] * t + a[10] * t**2)
    # Salinity dependence.
    eps_s = eps_s0 * np.exp(b[0] * s + b[1] * s**2 + b[2] * t * s)
    nu_1 = nu_10 * (1.0 + s * (b[3] + b[4] * t + b[5] * t**2))
    eps_1 = eps_10 * np.exp(b[6] * s + b[7] * s**2 + b[8] * t * s)
    nu_2 = nu_20 * (1.0 + s * (b[9] + b[10] * t))
    eps_inf = eps_inf0 * (1.0 + s * (b[11] + b[12] * t))
    # Stogryn et al. (1995): conductivity [S/m].
    sigma35 = (2.903602 + 8.607e-2 * t + 4.738817e-4 * t**2 - 2.991e-6 * t**3
               + 4.3047e-9 * t**4)
    r15 = s * (37.5109 + 5.45216 * s + 1.4409e-2 * s**2) / (1004.75 + 182.283 * s + s**2)
    alpha0 = (6.9431 + 3.2841 * s - 9.9486e-2 * s**2) / (84.850 + 69.024 * s + s**2)
    alpha1 = 49.843 - 0.2276 * s + 0.198e-2 * s**2
    rtr15 = 1.0 + (t - 15.0) * alpha0 / (alpha1 + t)
    sigma = sigma35 * r15 * rtr15
    # Eq W2 (double Debye + conduction), exp(+j omega t) sign.
    return (
        (eps_s - eps_1) / (1.0 + 1j * f_ghz / nu_1)
        + (eps_1 - eps_inf) / (1.0 + 1j * f_ghz / nu_2)
        + eps_inf
        - 1j * sigma / (2.0 * np.pi * EPS0 * f)
    )


#: Permittivity models by name: ``model(frequency [Hz], temperature_c, salinity_psu)``.
PERMITTIVITY_MODELS: dict[str, Callable[..., NDArray]] = {
    "klein-swift": klein_swift,
    "meissner-wentz": meissner_wentz,
}


def sea_water_permittivity(frequency: ArrayLike, temperature_c: ArrayLike = 20.0,
                           salinity_psu: ArrayLike = 35.0,
                           model: str = "meissner-wentz") -> NDArray:
    """Complex relative permittivity of sea water, ``eps' - j eps''`` [-].

    Parameters
    ----------
    frequency : array_like
        Frequency [Hz].
    temperature_c : array_like
        Temperature [degC].
    salinity_psu : array_like
        Salinity [psu].
    model : {"meissner-wentz", "klein-swift"}
        Model name (:data:`PERMITTIVITY_MODELS`).

    Returns
    -------
    ndarray of complex

    References
    ----------
    .. [1] Klein and Swift (1977); Meissner and Wentz (2004).
    """
    try:
        fn = PERMITTIVITY_MODELS[model]
    except KeyError:
        raise ValueError(f"model = {model!r}: unknown permittivity model; choose from "
                         f"{sorted(PERMITTIVITY_MODELS)}") from None
    return fn(frequency, temperature_c, salinity_psu)


__all__ = ["EPS0", "PERMITTIVITY_MODELS", "klein_swift", "meissner_wentz",
           "sea_water_permittivity"]
