"""Physical constants [SI], each defined once with its source.

Every module that needs one of these imports it from here; tests/test_single_source.py
fails on a second definition of a constant's literal elsewhere in the source.
"""

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
#: Kinematic viscosity of sea water at 20 degC and 35 g/kg [m^2/s]: dynamic viscosity
#: 1.08e-3 Pa s over 1024.8 kg/m^3 (Sharqawy, Lienhard & Zubair 2010, Desalin. Water
#: Treat. 16, 354-380).
NU_SEA_WATER = 1.05e-6
#: Density of air [kg/m^3] and its kinematic viscosity [m^2/s] at 15 degC, sea level (ISA;
#: the values of Kudryavtsev et al. 2003, JGR 108(C3) 8054, sec. 3).
RHO_AIR = 1.225
NU_AIR = 1.47e-5
#: von Karman constant [-]: 0.41 +- 0.025 from the wind profiles over the sea reviewed by
#: Smith (1988, J. Geophys. Res. 93(C12), 15467-15472), the value of Elfouhaily et al.
#: (1997). Kudryavtsev et al. (2003) round it to 0.4 in their wind growth rate; seaecho
#: uses one value everywhere.
VON_KARMAN = 0.41
#: Vacuum permittivity [F/m] (CODATA 2018).
EPS0 = 8.8541878128e-12

__all__ = ["C0", "EPS0", "G", "KNOT", "K_B", "NU_AIR", "NU_SEA_WATER", "RHO_AIR",
           "RHO_SEA_WATER", "SURFACE_TENSION_OVER_DENSITY", "T0", "VON_KARMAN"]
