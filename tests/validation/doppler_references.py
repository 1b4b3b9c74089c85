"""Published sea-surface Doppler references, used by the Doppler validation tests and by
``examples/xband_doppler_measured.py`` (docs/dynamics.md, "Against measurements").

Like ``tests/reference_models.py`` (the NRCS references), each is written from its
published form with the published coefficients; none is used by seaecho itself.

* :func:`cdop_hz` - the C-band Doppler geophysical model function CDOP of Mouche, A. A.,
  Collard, F., Chapron, B., Dagestad, K.-F., Guitton, G., Johannessen, J. A., Kerbaol, V.
  and Hansen, M. W. (2012). On the use of Doppler shift for sea surface wind retrieval
  from SAR. *IEEE Trans. Geosci. Remote Sens.* 50(7), 2901-2909: the geophysical Doppler
  anomaly [Hz] at 5.5 GHz of ENVISAT ASAR wide-swath data against ECMWF winds, VV and HH,
  fitted by a neural network with one hidden layer of eleven sigmoids over incidence
  (17-42 deg), wind speed U10 (1-17 m/s) and the wind direction relative to the look
  (0 upwind, 90 crosswind, 180 downwind). The weights and biases are those of the article
  (named lambda, omega, gamma, alpha, beta there) as distributed with Ifremer's CDOP code
  and reproduced identically in open implementations (e.g. the ``mouche12`` function of
  the seastar project, University of Southampton / NOC). Checked value by value and for
  the forward pass (input scaling, direction folded into 0-180 deg, two sigmoid layers,
  ``alpha s + beta``) against Ifremer's ``cdop.py`` (A. Mouche, M. W. Hansen, 2014-2015,
  GPL-3; its header cites the article): the same 2 x (3 + 3 + 11 + 33 + 1 + 11 + 2)
  numbers. Positive: towards the radar.
* :data:`XBAND_WAVE_DOPPLER_FRACTION`, :data:`XBAND_GMF_SPREAD_M_S`,
  :data:`XBAND_BRAGG_SPEED_M_S` - the X-band findings of the TanDEM-X along-track InSAR
  study of Elyouncha, A., Eriksson, L. E. B. et al. (2021). Empirical relationship between
  the Doppler centroid derived from X-band spaceborne InSAR data and wind vectors. *IEEE
  Trans. Geosci. Remote Sens.* (over 300 image pairs; Chalmers research record 523374,
  which shows the title, year and abstract but not the authors, named here as the
  Chalmers group's TanDEM-X Doppler work; the full text was not available here): "the
  wind-induced Doppler velocity contributes to the total Doppler velocity with about 15%
  of the radial wind speed",
  "much larger than the sum of the contributions from the Bragg waves (~0.2 m/s) and the
  wind-induced drift current (~3% of wind speed)"; their GMF agrees "within 0.2 m/s" with
  other models and data sets; the polarisation difference ``|DC_VV| - |DC_HH|`` is
  negative and grows in magnitude with incidence. The velocities are read as horizontal
  (ground-range) surface velocities, ``lambda f_D / (2 sin(theta))``, the convention of
  along-track InSAR current retrieval: the abstract's Bragg value (~0.2 m/s) is the X-band
  Bragg phase speed at 20-45 deg incidence (0.23-0.28 m/s), a horizontal speed, and CDOP
  read the same way gives 0.147 U10 upwind at 35 deg (VV, 7.6 m/s), the same 15 %.

Doppler *widths* (``tests/validation/test_doppler_widths.py``, docs/dynamics.md "Doppler
widths against measurements"): no published X-band sea-clutter width was found as a
number (:data:`WIDTH_MEASUREMENTS` lists what was read, and the conditions at which a
future comparison should be made). The one published width *law* that could be read is
a proportionality without its coefficient:

* :func:`hicks_velocity_scale_m_s` - Hicks et al. (1960). The spectrum of X-band
  radiation backscattered from the sea surface. *J. Geophys. Res.* 65(3), 825,
  doi:10.1029/JZ065i003p00825: a coherent X-band radar, more than 200 recorded clutter
  samples, spectra averaged over patches 3750 feet long (abstract, truncated, read on
  scite.ai).
  That they "empirically established the proportionality of the spectrum width to H/T"
  (H the wave height, T the wave period) is quoted from a citing article's statement on
  the same page, with "in order to adequately explain the total spectrum width, it is
  necessary to take into account the fluctuations of wind-drift velocity": second-hand;
  the coefficient, the polarisation and the grazing angles of the data were not read.
"""

from __future__ import annotations

import numpy as np

#: CDOP carrier frequency [Hz] (ENVISAT ASAR)
CDOP_FREQUENCY_HZ = 5.5e9

#: CDOP neural-network coefficients per polarisation (Mouche et al. 2012): input scaling
#: ``x_i = w1_i v_i + b1_i`` of (incidence [deg], U10 [m/s], relative direction [deg]);
#: hidden layer ``h = sigmoid(W2 x + b2)`` (eleven neurons); output
#: ``alpha sigmoid(w3 . h + b3) + beta`` [Hz].
CDOP_COEFFICIENTS = {
    "VV": {
        "b1": (-0.343935744939, 0.108823529412, 0.15),
        "w1": (0.028213254683, 0.0411764705882, 0.00388888888889),
        "b2": (14.5077150927, -11.4312028555, 1.28692747109, -1.19498666071, 1.778908726,
               11.8880215573, 1.70176062351, 24.7941267067, -8.18756617111, 1.32555779345,
               -9.06560116738),
        "w2": ((19.7873046673, 22.2237414308, 1.27887019276),
               (2.910815875, -3.63395681095, 16.4242081101),
               (1.03269004609, 0.403986575614, 0.325018607578),
               (3.17100261168, 4.47461213024, 0.969975702316),
               (-3.80611082432, -6.91334859293, -0.0162650756459),
               (4.09854466913, -1.64290475596, -13.4031862615),
               (0.484338480824, -1.30503436654, -6.04613303002),
               (-11.1000239122, 15.993470129, 23.2186869807),
               (-0.577883159569, 0.801977535733, 6.13874672206),
               (0.61008842868, -0.5009830671, -4.42736737765),
               (-1.94654022702, 1.31351068862, 8.94943709074)),
        "b3": 4.07777876994,
        "w3": (7.34881153553, 0.487879873912, -22.167664703, 7.01176085914, 3.57021820094,
               -7.05653415486, -8.82147148713, 5.35079872715, 93.627037987, 13.9420969201,
               -34.4032326496),
        "beta": -52.2644487109,
        "alpha": 111.528184073,
    },
    "HH": {
        "b1": (-0.342097701547, 0.118181818182, 0.15),
        "w1": (0.0281843837385, 0.0318181818182, 0.00388888888889),
        "b2": (1.30653883096, -2.77086154074, 10.6792861882, -4.0429666906,
               -0.172201666743, 20.4895916824, 28.2856865516, -3.60143441597,
               -3.53935574111, -2.11695768022, -2.57805898849),
        "w2": ((-2.61087309812, -0.973599180956, -9.07176856257),
               (-0.246776181361, 0.586523978839, -0.594867645776),
               (17.9261562541, 12.9439063319, 16.9815377306),
               (0.595882115891, 6.20098098757, -9.20238868219),
               (-0.993509213443, 0.301856868548, -4.12397246171),
               (15.0224985357, 17.643307099, 8.57886720397),
               (13.1833641617, 20.6983195925, -15.1439734434),
               (0.656338134446, 5.79854593024, -9.9811757434),
               (0.122736690257, -5.67640781126, 11.9861607453),
               (0.691577162612, 5.95289490539, -16.0530462),
               (1.2664066483, 0.151056851685, 7.93435940581)),
        "b3": 2.68352095337,
        "w3": (-8.21498722494, -94.9645431048, -17.7727420108, -63.3536337981,
               39.2450482271, -6.15275352542, 16.5337543167, 90.1967379935,
               -1.11346786284, -17.57689699, 8.20219395141),
        "beta": -66.9554922921,
        "alpha": 136.216953823,
    },
}

#: CDOP's domain (Mouche et al. 2012): incidence [deg] and U10 [m/s]
CDOP_INCIDENCE_DEG = (17.0, 42.0)
CDOP_U10_M_S = (1.0, 17.0)

#: X-band wave Doppler (horizontal surface velocity) per unit radial wind speed U10 cos(phi)
#: (Elyouncha et al. 2021, TanDEM-X: "about 15%")
XBAND_WAVE_DOPPLER_FRACTION = 0.15
#: agreement of that GMF with other models and data sets [m/s] (Elyouncha et al. 2021)
XBAND_GMF_SPREAD_M_S = 0.2
#: the Bragg waves' contribution to the X-band Doppler velocity [m/s] ("~0.2 m/s", ibid.)
XBAND_BRAGG_SPEED_M_S = 0.2


def _sigmoid(x):
    return 1.0 / (1.0 + np.exp(-x))


def cdop_hz(incidence_deg, u10_m_s, phi_deg, pol: str):
    """CDOP geophysical Doppler anomaly [Hz] at 5.5 GHz (Mouche et al. 2012).

    ``phi_deg``: direction the wind comes from relative to the look (0: the radar looks
    upwind; folded into 0-180 deg), ``u10_m_s`` the 10 m wind [m/s], ``pol`` "VV" or "HH".
    Positive: scatterers approaching the radar. Raises ``ValueError`` outside the domain
    the network was fitted on (incidence 17-42 deg, U10 1-17 m/s).
    """
    if pol not in CDOP_COEFFICIENTS:
        raise ValueError(f"pol must be 'VV' or 'HH', not {pol!r}")
    inc, u10, phi = np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                          for v in (incidence_deg, u10_m_s, phi_deg)))
    if np.any((inc < CDOP_INCIDENCE_DEG[0]) | (inc > CDOP_INCIDENCE_DEG[1])):
        raise ValueError(f"incidence {inc} deg outside CDOP's 17-42 deg")
    if np.any((u10 < CDOP_U10_M_S[0]) | (u10 > CDOP_U10_M_S[1])):
        raise ValueError(f"U10 {u10} m/s outside CDOP's 1-17 m/s")
    c = CDOP_COEFFICIENTS[pol]
    phi = np.abs(np.mod(phi + 180.0, 360.0) - 180.0)
    x = np.stack([inc, u10, phi], axis=-1) * np.asarray(c["w1"]) + np.asarray(c["b1"])
    h = _sigmoid(x @ np.asarray(c["w2"]).T + np.asarray(c["b2"]))
    return c["alpha"] * _sigmoid(h @ np.asarray(c["w3"]) + c["b3"]) + c["beta"]


def xband_wave_doppler_m_s(u10_m_s, phi_deg):
    """Horizontal X-band Doppler surface velocity [m/s] of the wind sea, ``0.15 U10
    cos(phi)`` (Elyouncha et al. 2021; ``phi_deg`` 0: the radar looks upwind)."""
    return XBAND_WAVE_DOPPLER_FRACTION * np.asarray(u10_m_s, dtype=float) * np.cos(
        np.radians(phi_deg))


def hicks_velocity_scale_m_s(significant_height_m, peak_period_s):
    """The sea's velocity scale H/T [m/s] to which Hicks et al. (1960) found the X-band
    clutter spectrum's width proportional (second-hand, module docstring); here H the
    significant wave height [m] and T the peak period [s] of the wave spectrum. The
    coefficient of the proportionality was not read, so only ratios of widths at
    different sea states can be compared with it."""
    return np.asarray(significant_height_m, dtype=float) / np.asarray(peak_period_s,
                                                                      dtype=float)


#: Published X-band (and nearby) sea-clutter Doppler measurements whose *widths* a
#: comparison should use, with their conditions as read (abstracts and first pages only;
#: none gave a width as a number). Keys: source, band, grazing angles [deg], winds
#: [m/s], polarisations, looks, what was read and where; ``short`` a name for tables.
WIDTH_MEASUREMENTS = (
    {"short": "Hicks et al. 1960",
     "source": "Hicks et al. (1960), J. Geophys. Res. 65(3), 825", "band": "X",
     "grazing_deg": None, "wind_m_s": None, "pols": None, "looks": None,
     "read": "abstract and a citing statement (scite.ai): width proportional to H/T"},
    {"short": "Hwang et al. 2008",
     "source": "Hwang, Sletten & Toporkov (2008), J. Geophys. Res. 113, C09017",
     "band": "X", "grazing_deg": (1.4, 5.5), "wind_m_s": (7.0, 15.0), "pols": "HH, VV",
     "looks": None, "read": "abstract: Doppler velocity ratios, no width"},
    {"short": "Lee et al. 1996",
     "source": "Lee et al. (1996), IEEE Trans. Antennas Propag. 44(3), 333-340",
     "band": "X", "grazing_deg": "small", "wind_m_s": (3.8, 10.3), "pols": "HH, VV",
     "looks": None, "read": "abstract: speed of fast scatterers rises with wind, no width"},
    {"short": "LOGAN 1993",
     "source": "Rino et al. (1997), IEEE J. Oceanic Eng. 22, 18-26 (LOGAN 1993)",
     "band": "X", "grazing_deg": "low", "wind_m_s": None, "pols": None, "looks": None,
     "read": "abstract: high-resolution Doppler spectra of sea spikes, no width"},
    {"short": "Rosenberg 2014",
     "source": "Rosenberg (2014), IEEE Trans. Aerosp. Electron. Syst. 50(1), 406-417",
     "band": "X", "grazing_deg": (15.0, 45.0), "wind_m_s": None, "pols": "quad",
     "looks": "all", "read": "abstract: two-component (Bragg, non-Bragg) model, no width"},
    {"short": "Johnsen 2015",
     "source": "Johnsen (2015), IEEE Radar Conf., doi:10.1109/RADARCONF.2015.7411864",
     "band": "X", "grazing_deg": (3.0, 56.0), "wind_m_s": None, "pols": None,
     "looks": "all", "read": "abstract: Doppler widths vs sea state studied, no number"},
    {"short": "DSTO-TR-2864",
     "source": "Whitrow (2013), DSTO-TR-2864", "band": "X", "grazing_deg": "low",
     "wind_m_s": None, "pols": None, "looks": None,
     "read": "first pages: Bragg, whitecap, spike bandwidths deduced; table not read"},
    {"short": "North Truro",
     "source": "Chan (1990), DREO Report 1051 (North Truro data)", "band": "X, S, L",
     "grazing_deg": None, "wind_m_s": "sea state 2", "pols": None,
     "looks": "up/cross-swell", "read": "first page: spectra differ with band, no width"},
)
