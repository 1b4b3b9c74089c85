"""Damping of the Bragg waves by the surfactant film of the turbulent wake (eqs W16, W17).

A ship's wake gathers the sea's natural surface-active material into films: the bubbles
of the wake scour it from the water column and the wake's vortices sweep it into bands
whose surface tension is several mN/m below the ambient (Kaiser et al. 1988, WAKEX 86;
Peltzer et al. 1992 measured the film pressure and elasticity across ship wakes). A film
damps the short waves by the Marangoni effect: its elasticity resists the surface
dilation of the wave, a viscous boundary layer forms beneath it and dissipates the wave.

**Damping ratio** (Lucassen-Reynders & Lucassen 1969, as written by Alpers & Huehnerfuss
1989): the ratio y of the damping coefficient of a wave of wavenumber k under a purely
elastic film of dilational modulus E to that of clean water,

.. math::

    y(k; E) = \\frac{1 + X + X Y}{1 + 2X + 2X^2},\\quad
    X = \\frac{E k^2}{\\rho \\sqrt{2 \\nu \\omega^3}},\\quad
    Y = \\frac{E k}{4 \\rho \\nu \\omega}                                        (W16)

(their general form with the film's phase angle theta, here 0: a purely elastic film),
omega(k) the capillary-gravity dispersion relation, nu the kinematic viscosity and rho
the density of sea water. E -> 0 gives the clean surface, y = 1; E -> infinity the
inextensible film, y = Y / (2X) = sqrt(2 omega / nu) / (8 k), the ratio of Lamb's (1932,
art. 351) amplitude damping k sqrt(nu omega / 8) of an inextensible surface to the clean
2 nu k^2 (art. 348). Between the two the ratio peaks at the frequency where the film's
longitudinal (Marangoni) wave resonates with the transverse wave: near 8 Hz for a
dilational modulus of the order of 0.01 N/m (Alpers & Huehnerfuss 1988), the range of
radar Bragg waves at X and Ku band.

**Spectral contrast of the film** (Alpers & Huehnerfuss 1989): with the wind input and the
nonlinear transfers to the short waves unchanged by the film, the balance of the wave
energy makes the damping rate times the spectral density the same on clean and filmed
water, so the film divides the Bragg spectrum by y:

.. math::

    \\frac{\\Psi_{film}(k_B)}{\\Psi(k_B)} = \\frac{1}{y(k_B; E)},\\quad
    C_f = -10 \\log_{10} y(k_B; E)\\ \\mathrm{dB}                              (W17)

k_B the radar's Bragg wavenumber, so the contrast depends on the radar band and the
incidence. Within Bragg scattering it is the same for every polarisation (the
polarisation factors cancel in the ratio); UAVSAR measurements over oil films confirm
that Bragg theory holds for the slick-covered sea (Alpers, Holt & Zeng 2017), while the
non-Bragg (breaking) echo, which the film damps differently, makes the measured VV and HH
contrasts differ at moderate winds (Ermakov et al. 2018, 2022).

*Film elasticity of a ship wake.* ``DEFAULT_WAKE_FILM_ELASTICITY`` = 0.010 N/m: Alpers &
Huehnerfuss (1988) find that damping maxima observed near 8 Hz are those of surface-active
material "of medium to low wave damping ability with a dilational modulus of the order
of 0.01 N/m"; monolayers measured at film pressures and strain rates comparable to
natural films in ship-generated surface currents have an elastic modulus of about
8 mN/m at surface pressures below 1 mN/m (Phys. Fluids 6(8), 2606-2616, 1994). A measured
elasticity of a ship-wake film, and its decay with the wake's age, were not found (the
abstract of Peltzer et al. 1992 reports the measurement but no value): the film is taken
as persistent over the turbulent strip.

*Not modelled: the wind.* Alpers & Huehnerfuss's balance (W17) has no wind speed; measured
slick contrasts are lower at higher winds (Gade et al. 1998), but their numbers could not
be read here. The balance of the wind input alone (the growth rate of Plant 1982) against
the film's damping is too sensitive to the film's modulus to be used without a measured
one: at Ku band and 3.5-4.4 m/s it passes from no contrast to complete suppression of the
Bragg waves between E = 0 and 3-10 mN/m (docs/wake.md).

References
----------
.. [1] E. H. Lucassen-Reynders and J. Lucassen, "Properties of capillary waves", Adv.
   Colloid Interface Sci. 2, 347-395 (1969).
.. [2] W. Alpers and H. Huehnerfuss, "The damping of ocean waves by surface films: a new
   look at an old problem", J. Geophys. Res. 94(C5), 6251-6265 (1989).
.. [3] W. Alpers and H. Huehnerfuss, "Radar signatures of oil films floating on the sea
   surface and the Marangoni effect", J. Geophys. Res. 93(C4), 3642-3648 (1988).
.. [4] H. Lamb, *Hydrodynamics*, 6th ed., Cambridge University Press (1932), arts. 348,
   351.
.. [5] H. Huehnerfuss, W. Alpers and W. L. Jones, "Measurements at 13.9 GHz of the radar
   backscattering cross section of the North Sea covered with an artificial surface
   film", Radio Sci. 13 (1978).
.. [6] "Surface strain modulation of insoluble surface film properties", Phys. Fluids
   6(8), 2606-2616 (1994), doi:10.1063/1.868150.
.. [7] J. A. C. Kaiser, W. D. Garrett, S. E. Ramberg, R. D. Peltzer and D. M. Andrews,
   "WAKEX 86: a ship wake/films exploratory experiment", NRL report (1988).
.. [8] R. D. Peltzer, O. M. Griffin, W. R. Barger and J. A. C. Kaiser, "High-resolution
   measurement of surface-active film redistribution in ship wakes", J. Geophys. Res.
   97 (1992), doi:10.1029/91JC01875.
.. [9] W. Alpers, B. Holt and K. Zeng, "Oil spill detection by imaging radars: challenges
   and pitfalls", Remote Sens. Environ. 201, 133-147 (2017).
.. [10] S. A. Ermakov et al., "Remote sensing of organic films on the water surface using
   dual co-polarized ship-based X-/C-/S-band radar and TerraSAR-X", Remote Sens. 10(7),
   1097 (2018); "New features of Bragg and non-polarized radar backscattering from film
   slicks on the sea surface", J. Mar. Sci. Eng. 10(9), 1262 (2022).
.. [11] M. Gade, W. Alpers, H. Huehnerfuss, H. Masuko and T. Kobayashi, "Imaging of
   biogenic and anthropogenic ocean surface films by the multifrequency/multipolarization
   SIR-C/X-SAR", J. Geophys. Res. 103(C9), 18851-18866 (1998).
.. [12] W. J. Plant, "A relationship between wind stress and wave slope", J. Geophys.
   Res. 87(C3), 1961-1967 (1982).
.. [13] M. H. Sharqawy, J. H. Lienhard and S. M. Zubair, "Thermophysical properties of
   seawater: a review of existing correlations and data", Desalin. Water Treat. 16,
   354-380 (2010).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..constants import NU_SEA_WATER, RHO_SEA_WATER
from ..ocean.dispersion import angular_frequency

#: Dilational modulus of the ship wake's natural surfactant film [N/m]: "of the order of
#: 0.01 N/m" (Alpers & Huehnerfuss 1988); about 8 mN/m measured for monolayers at the
#: film pressures of natural films in ship-generated currents (Phys. Fluids 6, 2606, 1994).
DEFAULT_WAKE_FILM_ELASTICITY = 0.010


def marangoni_damping_ratio(
    k: ArrayLike,
    elasticity: float,
    nu: float = NU_SEA_WATER,
    rho: float = RHO_SEA_WATER,
) -> NDArray[np.float64]:
    """Damping ratio y of a purely elastic surface film (eq W16) [-].

    Parameters
    ----------
    k : array_like
        Wavenumber > 0 [rad/m].
    elasticity : float
        Dilational modulus of the film E >= 0 [N/m]; 0 is clean water.
    nu : float
        Kinematic viscosity of the water [m^2/s].
    rho : float
        Density of the water [kg/m^3].

    Returns
    -------
    ndarray
        y = damping coefficient with the film / without it, same shape as ``k``;
        1 at E = 0, sqrt(2 omega / nu) / (8 k) for an inextensible film.

    References
    ----------
    Lucassen-Reynders & Lucassen (1969); Alpers & Huehnerfuss (1989), their damping ratio
    with the film's phase angle 0.
    """
    if not (np.isfinite(elasticity) and elasticity >= 0.0):
        raise ValueError(f"elasticity = {elasticity!r} N/m: must be a finite number >= 0")
    if not (np.isfinite(nu) and nu > 0.0 and np.isfinite(rho) and rho > 0.0):
        raise ValueError(f"nu = {nu!r} m^2/s, rho = {rho!r} kg/m^3: must be > 0")
    k = np.asarray(k, dtype=np.float64)
    if not np.all(np.isfinite(k) & (k > 0.0)):
        raise ValueError("k: wavenumbers must be finite and > 0 [rad/m]")
    omega = angular_frequency(k)
    # Eq W16
    big_x = elasticity * k**2 / (rho * np.sqrt(2.0 * nu * omega**3))
    big_y = elasticity * k / (4.0 * rho * nu * omega)
    return (1.0 + big_x + big_x * big_y) / (1.0 + 2.0 * big_x + 2.0 * big_x**2)


def film_contrast_db(bragg_wavenumber: float, elasticity: float = DEFAULT_WAKE_FILM_ELASTICITY,
                     nu: float = NU_SEA_WATER, rho: float = RHO_SEA_WATER) -> float:
    """Contrast of the film's Bragg spectrum against clean water, -10 log10 y (eq W17) [dB].

    Parameters
    ----------
    bragg_wavenumber : float
        Bragg wavenumber k_B >= 0 of the radar geometry [rad/m] (0, a specular geometry,
        gives 0 dB: y -> 1 as k -> 0).
    elasticity : float
        Dilational modulus of the film E >= 0 [N/m].
    nu, rho : float
        As :func:`marangoni_damping_ratio`.

    Returns
    -------
    float
        C_f <= 0 [dB]. For films weaker than about 1 mN/m, W16 dips below 1 by at most
        a few per cent (a truncation of the boundary-layer expansion it rests on); the
        contrast is then clipped to 0 dB.

    References
    ----------
    Alpers & Huehnerfuss (1989).
    """
    if not (np.isfinite(bragg_wavenumber) and bragg_wavenumber >= 0.0):
        raise ValueError(f"bragg_wavenumber = {bragg_wavenumber!r} rad/m: must be >= 0")
    if bragg_wavenumber == 0.0:  # specular geometry: W16 tends to 1 as k -> 0
        return 0.0
    y = float(marangoni_damping_ratio(bragg_wavenumber, elasticity, nu, rho))
    # Eq W17
    return float(min(0.0, -10.0 * np.log10(y)))


__all__ = ["DEFAULT_WAKE_FILM_ELASTICITY", "NU_SEA_WATER", "film_contrast_db",
           "marangoni_damping_ratio"]
