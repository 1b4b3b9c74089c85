"""Mean-plane scattering coefficients of a wind sea: one entry point for all models.

:func:`sea_sigma` evaluates the paper's models for the mean sea plane (angles about +z),
taking the sea state as a ``DirectionalSpectrum`` and splitting it at
``k_cut = cut_ratio * k`` (default :data:`seaecho.ocean.twoscale.TWO_SCALE_CUT_RATIO`,
``k / 3``): waves longer than ``k_cut`` give the
large-scale slopes (Kirchhoff/GO, two-scale tilts), shorter ones the Bragg roughness
(two-scale). This is what ``seaecho sigma`` and the Fig. 3 / Fig. 4 examples use.

============  ===========================================================
``model``     what it computes
============  ===========================================================
kirchhoff     eq 7 (GO), slopes of K < k_cut (Gaussian) or Cox & Munk
spm           eqs 8-9 with the full height spectrum at the Bragg vector
two-scale     SPM averaged over the slopes of K < k_cut (Khenchaf & Airiau)
blend         eqs 10-11 with the ``kirchhoff`` and ``spm`` rows above
X+breaking    ``two-scale`` or ``blend`` plus breaking zones (Kudryavtsev et
              al. 2003; :mod:`.breaking`, eq BR1), wind U10 from U19.5 by :mod:`seaecho.ocean.wind`
============  ===========================================================

References
----------
.. [1] A. Arnold-Bos, A. Martin and A. Khenchaf, "A versatile bistatic & polarimetric
   marine radar simulator", Proc. 2006 IEEE Conference on Radar, Verona, NY, 2006,
   doi:10.1109/RADAR.2006.1631862 ("the paper"), section III; docs/scattering.md.
"""

from __future__ import annotations

import warnings

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import C0
from ..geometry import frames
from ..ocean.twoscale import (
    ROUGHNESS_K_MAX_RATIO,
    TWO_SCALE_CUT_RATIO,
    height_variance,
    slope_variances,
)
from ..ocean.wind import u12_5_from_u19_5
from .blend import blend
from .kirchhoff import KIRCHHOFF_DOMAIN_DEG, kirchhoff_sigma
from .slopes import cox_munk_parameters
from .spm import spm_sigma
from .twoscale import check_spm_validity, two_scale_sigma
from .validity import KirchhoffValidityWarning

MEAN_PLANE_MODELS = ("kirchhoff", "spm", "two-scale", "blend", "two-scale+breaking",
                     "blend+breaking")
SLOPE_MODELS = ("gaussian", "cox-munk")


def sea_sigma(
    model: str,
    theta_i: ArrayLike,
    phi_i: ArrayLike,
    theta_s: ArrayLike,
    phi_s: ArrayLike,
    frequency: float,
    spectrum,
    eps_r: complex,
    slopes: str = "gaussian",
    cut_ratio: float = TWO_SCALE_CUT_RATIO,
) -> NDArray:
    """Mean-plane bistatic ``sigma_mn`` of a wind sea, shape (..., 4), HH, HV, VH, VV.

    Parameters
    ----------
    model : {"kirchhoff", "spm", "two-scale", "blend", "two-scale+breaking", "blend+breaking"}
    theta_i, phi_i, theta_s, phi_s : array_like
        Mean-plane angles [rad] (broadcast together).
    frequency : float
        Radar frequency [Hz].
    spectrum : seaecho.ocean.spectra.DirectionalSpectrum
        Sea state (its ``height_spectrum`` and wind direction are used).
    eps_r : complex
        Sea-water permittivity [-].
    slopes : {"gaussian", "cox-munk"}
        Slope density of the Kirchhoff part: Gaussian with the spectrum's slope
        variances below ``k_cut``, or Cox & Munk (1954) at U12.5 from U19.5.
    cut_ratio : float
        ``k_cut / k`` [-] (default the two-scale split of
        :mod:`seaecho.ocean.twoscale`, 1/3).

    Returns
    -------
    ndarray, shape (..., 4)
        ``sigma_mn`` [m^2/m^2].

    Warns
    -----
    KirchhoffValidityWarning
        ``model="kirchhoff"`` more than 20 deg from specular.
    SPMValidityWarning
        ``model="spm"`` (k h of the whole sea) or ``"two-scale"`` (k h of K > k_cut)
        above 0.3.
    """
    if model not in MEAN_PLANE_MODELS:
        raise ValueError(f"model = {model!r}: choose from {MEAN_PLANE_MODELS}")
    if slopes not in SLOPE_MODELS:
        raise ValueError(f"slopes = {slopes!r}: choose from {SLOPE_MODELS}")
    if not 0.0 < cut_ratio <= 1.0:
        raise ValueError(f"cut_ratio = {cut_ratio}: must be in (0, 1]")
    if model.endswith("+breaking"):
        from ..ocean.wind import u10_from_u19_5
        from .breaking import add_breaking, breaking_sigma_mean_plane

        regular = sea_sigma(model.removesuffix("+breaking"), theta_i, phi_i, theta_s, phi_s,
                            frequency, spectrum, eps_r, slopes, cut_ratio)
        s_wb, q = breaking_sigma_mean_plane(theta_i, phi_i, theta_s, phi_s,
                                            float(u10_from_u19_5(spectrum.u19_5)),
                                            2.0 * np.pi * frequency / C0,
                                            float(spectrum.wind_direction))
        return add_breaking(regular, s_wb, q)
    k = 2.0 * np.pi * frequency / C0
    k_cut = cut_ratio * k
    wind = float(spectrum.wind_direction)
    w = spectrum.height_spectrum
    mss_u, mss_c = slope_variances(spectrum, 0.0, k_cut)
    cm = cox_munk_parameters(float(u12_5_from_u19_5(spectrum.u19_5))) if (
        slopes == "cox-munk") else None

    if model == "two-scale":
        return two_scale_sigma(theta_i, phi_i, theta_s, phi_s, k, eps_r, w, mss_u, mss_c,
                               wind, k_cut, n_nodes=24,
                               small_scale_height_variance=height_variance(
                                   spectrum, k_cut, ROUGHNESS_K_MAX_RATIO * k))
    if model == "spm":
        check_spm_validity(k, height_variance(spectrum, 0.0, ROUGHNESS_K_MAX_RATIO * k))
        return spm_sigma(theta_i, phi_i, theta_s, phi_s, k, eps_r, w)
    if model == "kirchhoff":
        n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
        beta = np.degrees(frames.beta_angle(n_i, n_s))
        if np.any(beta > KIRCHHOFF_DOMAIN_DEG):
            warnings.warn(
                f"Kirchhoff/GO used up to {np.max(beta):.1f} deg from specular (valid within "
                f"about {KIRCHHOFF_DOMAIN_DEG:g} deg): the diffuse part is missing",
                KirchhoffValidityWarning, stacklevel=2)
        return kirchhoff_sigma(theta_i, phi_i, theta_s, phi_s, eps_r, mss_u, mss_c, wind,
                               cox_munk=cm, warn=False)
    # Blend, eqs 10-11.
    n_i, n_s = frames.directions_from_angles(theta_i, phi_i, theta_s, phi_s)
    beta = np.degrees(frames.beta_angle(n_i, n_s))
    s_spm = spm_sigma(theta_i, phi_i, theta_s, phi_s, k, eps_r, w)
    s_k = kirchhoff_sigma(theta_i, phi_i, theta_s, phi_s, eps_r, mss_u, mss_c, wind,
                          cox_munk=cm, warn=False)
    return blend(s_spm, s_k, beta)


__all__ = ["MEAN_PLANE_MODELS", "SLOPE_MODELS", "sea_sigma"]
