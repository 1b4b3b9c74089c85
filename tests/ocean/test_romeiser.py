"""The Romeiser, Alpers & Wismann (1997) spectrum ("RAW97", ``seaecho.ocean.romeiser``).

Romeiser et al.'s figures could not be read from here, so the spectrum is checked against (i) an
independent implementation of the same equations (OceanSAR, TU Delft, ``spec/romeiser97.py``
and ``spread/romeiser97.py``: values below computed from its expressions), (ii) what the
article says its spectrum is for: the Bragg level of the C-band scatterometers, where it
must agree with the Elfouhaily et al. (1997) spectrum that was fitted to the same
C-band backscatter (and the Cox & Munk slopes), and a short-wave saturation that falls
between the C- and X-band Bragg wavenumbers; (iii) closed forms (the spreading's unit
integral, the equilibrium range's wind-independent saturation ``a_0``).
"""

import numpy as np
import pytest
from scipy.integrate import quad

from seaecho.ocean.romeiser import RAW97_A0, romeiser, romeiser_spreading, wind_exponent
from seaecho.ocean.spectra import OMNI_SPECTRA, SPREADINGS, DirectionalSpectrum, elfouhaily
from seaecho.ocean.wind import u19_5_from_u10


def _saturation(name, k, u10):
    """Omnidirectional saturation B = k^3 S_1d [-] at U10 [m/s]."""
    k = np.asarray(k, dtype=float)
    return k**3 * OMNI_SPECTRA[name](k, float(u19_5_from_u10(u10)), None)


def test_registered_by_name():
    assert OMNI_SPECTRA["romeiser"] is romeiser
    assert SPREADINGS["romeiser"] is romeiser_spreading
    DirectionalSpectrum("romeiser", "romeiser", u19_5=8.0)  # accepted by name


# B = k^3 S_1d from OceanSAR's romeiser97(k, U_10) (eqs 38-42 as coded there), U10 in m/s.
OCEANSAR_SATURATION = [
    (4.5, 100.0, 3.9e-3), (4.5, 384.0, 9.6e-4),
    (7.0, 188.0, 4.9e-3), (7.0, 384.0, 1.6e-3),
    (10.0, 150.0, 1.0e-2), (10.0, 384.0, 2.4e-3),
    (12.5, 338.0, 4.1e-3), (12.5, 500.0, 2.3e-3),
]


@pytest.mark.parametrize(("u10", "k", "expected"), OCEANSAR_SATURATION)
def test_saturation_against_oceansar(u10, k, expected):
    """Two significant digits of OceanSAR's implementation of eqs 38-42."""
    assert _saturation("romeiser", k, u10) == pytest.approx(expected, rel=0.05)


@pytest.mark.parametrize("u10", [4.5, 7.0, 10.0, 12.5])
def test_c_band_bragg_level_as_elfouhaily(u10):
    """At the C-band Bragg wavenumbers of 30-50 deg incidence (110-170 rad/m at 5.3 GHz)
    both spectra reproduce the C-band scatterometers: within 2.5 dB of each other
    (measured -0.1 to +2.0 dB)."""
    k = np.array([110.0, 140.0, 170.0])
    ratio_db = 10 * np.log10(_saturation("romeiser", k, u10) / _saturation("elfouhaily", k,
                                                                              u10))
    assert np.all(np.abs(ratio_db) < 2.5)


@pytest.mark.parametrize("u10", [4.5, 7.0, 10.0, 12.5])
def test_x_band_bragg_level_below_elfouhaily(u10):
    """Between the C-band (188 rad/m at 58 deg) and the X-band (338-389 rad/m) Bragg waves
    RAW97's saturation falls by a factor 2-4 (measured 2.3-3.8), where E97's rises by
    10-20 %: the fall that Nathanson's X-band VV and CMOD5.N's C-band VV at 60 deg ask for
    together (docs/scattering.md). At 384 rad/m RAW97 is 4.5-8 dB below E97 (measured
    5.0-7.3 dB)."""
    fall = _saturation("romeiser", 188.0, u10) / _saturation("romeiser", 338.0, u10)
    assert 2.0 < fall < 4.0
    e97 = _saturation("elfouhaily", 338.0, u10) / _saturation("elfouhaily", 188.0, u10)
    assert 1.0 < e97 < 1.25
    below = 10 * np.log10(_saturation("elfouhaily", 384.0, u10)
                          / _saturation("romeiser", 384.0, u10))
    assert 4.5 < below < 8.0


def test_equilibrium_range_saturation_is_a0():
    """Well above the peak and below the short-wave shape (k ~ 1 rad/m at 12.5 m/s:
    P_L -> 1, beta -> 0, W_H -> 1 within 2 %), the saturation is the wind-independent
    a_0 = 1.95e-3 of eq 39 (a Phillips equilibrium range)."""
    assert wind_exponent(0.0) == 0.0
    for u10 in (10.0, 12.5):
        assert _saturation("romeiser", 1.0, u10) == pytest.approx(RAW97_A0, rel=0.08)


def test_wind_exponent_peaks_between_the_c_and_x_band_bragg_waves():
    """beta(k) (eq 41) is largest near 216 rad/m (1.59) and 1.17-1.32 at the X-band
    Bragg waves (338-384 rad/m): RAW97's short waves there grow about as U10^1.2."""
    k = np.linspace(10.0, 3000.0, 3000)
    b = wind_exponent(k)
    assert 200.0 < k[np.argmax(b)] < 250.0
    assert 1.5 < b.max() < 1.65
    assert np.all((wind_exponent([338.0, 384.0]) > 1.1) & (wind_exponent([338.0, 384.0]) < 1.4))


@pytest.mark.parametrize("k", [0.05, 0.5, 10.0, 384.0, 3000.0])
@pytest.mark.parametrize("u19_5", [3.0, 10.0, 20.0])
def test_spreading_unit_integral(k, u19_5):
    """Eq 43 normalised over (-pi, pi] (the erf factor): unit integral, peak downwind."""
    total, _ = quad(lambda p: romeiser_spreading(k, p, u19_5), -np.pi, np.pi, limit=200)
    assert total == pytest.approx(1.0, rel=1e-9)
    assert romeiser_spreading(k, 0.0, u19_5) > romeiser_spreading(k, np.pi, u19_5)


def test_spreading_width_against_oceansar():
    """1 / (2 delta^2) of eq 44 at k = 100 rad/m, U10 = 10 m/s: 0.14 + 0.5 (1 - e^-2.5)
    + 5 e^2.5 10^-2.6 100^-1.3 = 0.5993 (OceanSAR's expression)."""
    from seaecho.ocean.romeiser import spreading_width

    expected = 0.14 + 0.5 * (1 - np.exp(-2.5)) + 5 * np.exp(2.5) * 10**-2.6 * 100**-1.3
    assert float(spreading_width(100.0, 10.0)) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(0.5993, abs=5e-4)


def test_zero_and_negative_wavenumbers_give_zero():
    assert np.all(romeiser(np.array([-1.0, 0.0]), 10.0) == 0.0)


def test_elfouhaily_unchanged():
    """The new module only registers a spectrum: E97's values are as before (its
    saturation at 384 rad/m, 7 m/s: 6.8e-3, docs/scattering.md)."""
    assert 384.0**3 * elfouhaily(384.0, float(u19_5_from_u10(7.0))) == pytest.approx(6.8e-3,
                                                                                      rel=0.02)


def test_scene_selects_raw97_and_ignores_the_fetch():
    """``[sea] spectrum = "romeiser"``: the builder's spectrum is RAW97 (no fetch law: a
    fetch_m is not checked against Elfouhaily's or JONSWAP's, as with Pierson-Moskowitz)."""
    from seaecho.build import sea_spectrum
    from seaecho.config import parse_scene

    scene = parse_scene({"sea": {"spectrum": "romeiser", "spreading": "romeiser",
                                 "wind_speed_m_s": 8.0, "fetch_m": 10.0, "size_x_m": 8.0,
                                 "nx": 64},
                         "tracing": {"mode": "analytic"}})
    spec = sea_spectrum(scene)
    assert (spec.spectrum, spec.spreading) == ("romeiser", "romeiser")
    np.testing.assert_allclose(spec.omni([384.0]), romeiser(np.array([384.0]), 8.0))


def test_sigma_command_line_takes_raw97(tmp_path):
    """``seaecho sigma --spectrum romeiser``: the CSV holds sea_sigma's numbers with RAW97
    (X band, 10 deg grazing upwind, U19.5 7.4 m/s), VV several dB below E97's."""
    from seaecho.cli import main
    from seaecho.ocean.seawater import meissner_wentz
    from seaecho.scattering.models import sea_sigma

    rows = {}
    for name in ("romeiser", "elfouhaily"):
        out = tmp_path / f"{name}.csv"
        assert main(["sigma", "--model", "two-scale+breaking", "--spectrum", name,
                     "--frequency-ghz", "9.3", "--wind-speed", "7.4", "--theta-i-deg", "80",
                     "--theta-s-deg", "80", "--phi-s-deg", "180", "--no-figure",
                     "-o", str(out)]) == 0
        rows[name] = np.loadtxt(out, delimiter=",", skiprows=1)
    spec = DirectionalSpectrum("romeiser", "elfouhaily", u19_5=7.4)
    ref = sea_sigma("two-scale+breaking", np.radians(80.0), 0.0, np.radians(80.0), np.pi,
                    9.3e9, spec, meissner_wentz(9.3e9, 20.0, 35.0))
    np.testing.assert_allclose(rows["romeiser"][4:], 10 * np.log10(ref), atol=1e-3)
    assert rows["elfouhaily"][7] - rows["romeiser"][7] > 3.0
