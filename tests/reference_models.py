"""Published empirical sea-clutter models, used as references by the validation tests.

Each function is written from its published form, with the coefficients as published;
the provenance notes say where each was taken from. None of these is used by seaecho
itself: they are what its physics is compared against.

* :func:`cmod5n` - C-band VV geophysical model function CMOD5.N (Hersbach 2010, ECMWF
  Tech. Memo. 620; the CMOD5 form of Hersbach, Stoffelen & de Haan 2007, JGR 112,
  C03006, with the neutral-wind coefficients). Coefficients c1..c28 as distributed by
  KNMI/ECMWF and reproduced identically in the open implementations of the
  scatterometer community (e.g. the NERSC/KNMI Python port by Dagestad of the KNMI
  Fortran code).
* :func:`mouche_pr` - C-band polarisation ratio VV/HH of Mouche, Hauser, Daloze & Guerin
  (2005), IEEE TGRS 43(4), 753-769: ``PR(theta) = A exp(B theta) + C`` for upwind,
  crosswind and downwind looks (theta in degrees), with their coefficients.
* :func:`git_sigma0` - the Georgia Tech low-grazing-angle model (Horst, Dyer & Tuley
  1978), in the form coded by Gregers-Hansen & Mital (NRL) for their 2012 comparison
  (NRL/MR/5310--12-9346), frequencies up to 12 GHz. Checked coefficient by coefficient
  against that code as published with the report (``GTI_SigmaSea.m``, whose header says it
  implements Horst, Dyer & Tuley's model) and against an independent implementation
  (N. Pinel 2015, citing Horst et al. 1978 and DSTO restatements): the same constants
  (4.52e-3 U^2.5; 14.4 lambda + 5.5; 0.2, 2.8, 0.015 and -0.4 in the wind factor; 1.1,
  1.94 and 15.4 in the wind-speed factor; 3.9e-6 and psi^0.4; the VV corrections 1.05,
  1.09, 1.27, 9.70 above 3 GHz and 1.73, 3.76, 2.46, 22.2 below). They differ twice:
  NRL takes ``|cos phi|`` in the wind factor (downwind as upwind), Pinel ``cos phi``
  (used here); and the interference factor's argument is divided by ``lambda + 0.015``
  in NRL's code (used here) but by ``lambda`` in Pinel's (and in a third, student
  implementation found with it, and a fourth, of a Bragg/whitecap/spike clutter model,
  whose comment calls it "Eq. 9" of the text it follows), which raises GIT at 9.3 GHz
  by up to 6.6 dB below 1 deg grazing in light winds (0.3 deg: +5.9 dB at U = 7.7 m/s,
  +2.5 dB at 10 m/s; < 0.5 dB above 3 deg). Horst et al.'s own text was not read, nor
  a restatement that prints the interference factor (Nathanson, Reilly & Cohen 1991,
  section 7.8, "a mathematical description of the GIT model is given at the end of this
  section", and Ward, Tough & Watts 2006, chapter 8, describe it; neither text was
  reachable). The NRL report itself (read, with the code) gives in its text only the
  model's inputs, average wave height and wind speed (its eq 1 relates them for a fully
  risen sea), and the whole model as the code in its appendix; it cites the model as
  "M. M. Horst, F. B. Dyer, and M. Tuley, 'Radar sea clutter model,' College Park, MD:
  1978, pp. 6-10", says Nathanson describes it in detail, and notes that Horst et al.
  put the frequency break at 10 GHz, later moved to 12 GHz (used here). So which
  divisor Horst et al. printed is not settled here, and NRL's is kept.
* :func:`nrl_sigma0` - the NRL model of Gregers-Hansen & Mital (2012), a five-parameter
  fit to Nathanson's tables (0.1-60 deg grazing, 0.5-35 GHz, sea states 0-6).
* :data:`NATHANSON_XBAND` - Nathanson's tables (Radar Design Principles, 2nd ed., 1991)
  at 9.3 GHz, as tabulated by Gregers-Hansen & Mital with their model code.
"""

from __future__ import annotations

import numpy as np

# --- CMOD5.N ---------------------------------------------------------------------------

#: CMOD5.N coefficients c1..c28 (index 0 unused), Hersbach (2010), table 1.
CMOD5N_C = np.array([
    0.0, -0.6878, -0.7957, 0.3380, -0.1728, 0.0000, 0.0040, 0.1103, 0.0159, 6.7329,
    2.7713, -2.2885, 0.4971, -0.7250, 0.0450, 0.0066, 0.3222, 0.0120, 22.7000, 2.0813,
    3.0000, 8.3659, -3.3428, 1.3236, 6.2437, 2.3893, 0.3249, 4.1590, 1.6930,
])


def cmod5n(u10, phi_deg, theta_deg):
    """CMOD5.N sigma0 VV [linear], equivalent-neutral wind ``u10`` [m/s].

    ``phi_deg`` is the angle between the radar look direction and the direction the wind
    comes from (0: the radar looks upwind), ``theta_deg`` the incidence angle (valid
    18-58 deg).
    """
    c = CMOD5N_C
    v = np.asarray(u10, dtype=float)
    x = (np.asarray(theta_deg, dtype=float) - 40.0) / 25.0
    cphi = np.cos(np.radians(phi_deg))
    y0, pn = c[19], c[20]
    a = y0 - (y0 - 1.0) / pn
    b = 1.0 / (pn * (y0 - 1.0) ** (pn - 1.0))
    a0 = c[1] + c[2] * x + c[3] * x**2 + c[4] * x**3
    a1 = c[5] + c[6] * x
    a2 = c[7] + c[8] * x
    gam = c[9] + c[10] * x + c[11] * x**2
    s0 = c[12] + c[13] * x
    s = a2 * v
    a3 = 1.0 / (1.0 + np.exp(-np.maximum(s, s0)))
    with np.errstate(divide="ignore", invalid="ignore"):  # branch unused where s0 <= 0
        a3 = np.where(s < s0, a3 * (s / s0) ** (s0 * (1.0 - a3)), a3)
    b0 = a3**gam * 10.0 ** (a0 + a1 * v)
    b1 = c[15] * v * (0.5 + x - np.tanh(4.0 * (x + c[16] + c[17] * v)))
    b1 = (c[14] * (1.0 + x) - b1) / (np.exp(0.34 * (v - c[18])) + 1.0)
    v0 = c[21] + c[22] * x + c[23] * x**2
    d1 = c[24] + c[25] * x + c[26] * x**2
    d2 = c[27] + c[28] * x
    v2 = v / v0 + 1.0
    v2 = np.where(v2 < y0, a + b * (v2 - 1.0) ** pn, v2)
    b2 = (-d1 + d2 * v2) * np.exp(-v2)
    return b0 * (1.0 + b1 * cphi + b2 * (2.0 * cphi**2 - 1.0)) ** 1.6


# --- Mouche et al. (2005) polarisation ratio ------------------------------------------

#: (A, B, C) of PR = A exp(B theta_deg) + C for upwind, crosswind, downwind looks.
MOUCHE_PR = {
    0.0: (0.00650704, 0.128983, 0.992839),
    90.0: (0.00782194, 0.121405, 0.992839),
    180.0: (0.00598416, 0.140952, 0.992885),
}


def mouche_pr(theta_deg, phi_deg):
    """Polarisation ratio sigma0_VV / sigma0_HH [linear], C band (Mouche et al. 2005).

    ``phi_deg``: look relative to upwind (0 upwind, 90 crosswind, 180 downwind); the
    three fits are joined by their Fourier series ``C0 + C1 cos phi + C2 cos 2 phi``.
    """
    t = np.asarray(theta_deg, dtype=float)
    p0, p90, p180 = (a * np.exp(b * t) + c for a, b, c in MOUCHE_PR.values())
    c0 = (p0 + p180 + 2.0 * p90) / 4.0
    c1 = (p0 - p180) / 2.0
    c2 = (p0 + p180 - 2.0 * p90) / 4.0
    ph = np.radians(phi_deg)
    return c0 + c1 * np.cos(ph) + c2 * np.cos(2.0 * ph)


# --- GIT (Horst, Dyer & Tuley 1978) -----------------------------------------------------

def git_average_wave_height(u):
    """GIT average wave height h_av = 4.52e-3 U^2.5 [m] for wind speed U [m/s]."""
    return 4.52e-3 * np.asarray(u, dtype=float) ** 2.5


def git_sigma0(f_ghz, u, grazing_deg, pol, phi_deg=0.0):
    """GIT sigma0 [dB] for f <= 12 GHz, wind speed ``u`` [m/s] (fully developed sea).

    ``phi_deg`` is the look direction relative to upwind (0 upwind); the wind factor is
    ``exp(0.2 cos phi (1 - 2.8 psi) (lambda + 0.015)^-0.4)`` as in Horst et al. (1978).
    """
    if f_ghz > 12.0:
        raise ValueError("this GIT branch is for f <= 12 GHz")
    lam = 0.299792458 / f_ghz
    psi = np.radians(grazing_deg)
    hav = git_average_wave_height(u)
    a = (14.4 * lam + 5.5) * psi * hav / (lam + 0.015)
    g_a = a**4 / (1.0 + a**4)
    g_u = np.exp(0.2 * np.cos(np.radians(phi_deg)) * (1.0 - 2.8 * psi) / (lam + 0.015) ** 0.4)
    q = 1.1 / (lam + 0.015) ** 0.4
    g_w = (1.94 * u / (1.0 + u / 15.4)) ** q
    hh = 10.0 * np.log10(3.9e-6 * lam * psi**0.4 * g_a * g_u * g_w)
    if pol == "H":
        return hh
    if f_ghz >= 3.0:
        return (hh - 1.05 * np.log(hav + 0.015) + 1.09 * np.log(lam)
                + 1.27 * np.log(psi + 1e-4) + 9.70)
    return (hh - 1.73 * np.log(hav + 0.015) + 3.76 * np.log(lam)
            + 2.46 * np.log(psi + 1e-4) + 22.2)


# --- NRL (Gregers-Hansen & Mital 2012) ------------------------------------------------

NRL_COEFFS = {"H": (-73.0, 20.781, 7.351, 25.65, 0.0054),
              "V": (-50.796, 25.93, 0.7093, 21.588, 0.00211)}


def nrl_sigma0(f_ghz, sea_state, grazing_deg, pol):
    """NRL sea-clutter model sigma0 [dB] (Gregers-Hansen & Mital 2012)."""
    c1, c2, c3, c4, c5 = NRL_COEFFS[pol]
    psi = np.asarray(grazing_deg, dtype=float)
    ss = float(sea_state)
    return (c1 + c2 * np.log10(np.sin(np.radians(psi)))
            + (27.5 + c3 * psi) * np.log10(f_ghz) / (1.0 + 0.95 * psi)
            + c4 * (ss + 1.0) ** (1.0 / (2.0 + 0.085 * psi + 0.033 * ss)) + c5 * psi**2)


# --- Nathanson's tables at 9.3 GHz ------------------------------------------------------

#: sigma0 [dB] at 9.3 GHz: {(pol, sea_state): {grazing_deg: value}} (Nathanson 1991,
#: as tabulated with the NRL model code of Gregers-Hansen & Mital 2012).
NATHANSON_XBAND = {
    ("H", 1): {0.1: -71.0, 0.3: -66.0, 1.0: -51.0, 3.0: -50.0, 10.0: -51.0, 30.0: -44.0,
               60.0: -24.0},
    ("H", 2): {0.1: -59.0, 0.3: -56.0, 1.0: -46.0, 3.0: -43.0, 10.0: -43.0, 30.0: -38.0,
               60.0: -23.0},
    ("H", 3): {0.1: -53.0, 0.3: -46.0, 1.0: -40.0, 3.0: -39.0, 10.0: -37.0, 30.0: -34.0,
               60.0: -21.0},
    ("H", 4): {0.1: -48.0, 0.3: -42.0, 1.0: -36.0, 3.0: -35.0, 10.0: -34.0, 30.0: -29.0,
               60.0: -15.0},
    ("H", 5): {0.1: -42.0, 0.3: -39.0, 1.0: -34.0, 3.0: -33.0, 10.0: -30.0, 30.0: -26.0,
               60.0: -14.0},
    ("V", 1): {0.1: -65.0, 0.3: -58.0, 1.0: -50.0, 3.0: -45.0, 10.0: -42.0, 30.0: -36.0,
               60.0: -24.0},
    ("V", 2): {0.1: -56.0, 0.3: -52.0, 1.0: -44.0, 3.0: -41.0, 10.0: -36.0, 30.0: -32.0,
               60.0: -18.0},
    ("V", 3): {0.1: -51.0, 0.3: -45.0, 1.0: -39.0, 3.0: -38.0, 10.0: -32.0, 30.0: -26.0,
               60.0: -16.0},
    ("V", 4): {0.1: -48.0, 0.3: -43.0, 1.0: -37.0, 3.0: -35.0, 10.0: -29.0, 30.0: -24.0,
               60.0: -14.0},
    ("V", 5): {0.1: -44.0, 0.3: -39.0, 1.0: -33.0, 3.0: -33.0, 10.0: -25.0, 30.0: -22.0,
               60.0: -13.0},
}

#: Wind speed U10 [m/s] taken for each sea state in the comparisons (the mid-range
#: values of the project's reference table: SS2 4.5, SS3 7.0, SS5 12.5 m/s; SS1 and SS4
#: by the same scale).
SEA_STATE_WIND = {1: 2.5, 2: 4.5, 3: 7.0, 4: 10.0, 5: 12.5}
