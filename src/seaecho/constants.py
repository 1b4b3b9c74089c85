"""Physical constants [SI]."""

#: Standard acceleration of gravity [m/s^2] (CGPM 1901).
G = 9.80665
#: Speed of light in vacuum [m/s] (exact, SI 2019).
C0 = 299_792_458.0
#: Boltzmann constant [J/K] (exact, SI 2019).
K_B = 1.380649e-23
#: Reference noise temperature [K] (IEEE Std 145).
T0 = 290.0
#: Knot [m/s] (exact).
KNOT = 1852.0 / 3600.0
#: Density of sea water [kg/m^3] (typical surface value).
RHO_SEA_WATER = 1025.0
#: Kinematic surface tension tau/rho of sea water [m^3/s^2]: 0.0735 N/m over 1025 kg/m^3,
#: which puts the minimum phase speed at k_m = sqrt(g rho / tau) = 370 rad/m as in
#: Elfouhaily et al. (1997), section 3.
SURFACE_TENSION_OVER_DENSITY = 7.17e-5

__all__ = ["C0", "G", "KNOT", "K_B", "RHO_SEA_WATER", "SURFACE_TENSION_OVER_DENSITY", "T0"]
