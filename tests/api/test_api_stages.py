"""The stages from Python: sigma, permittivity, surface, trace and compare as xarray.

Parity with the functions they wrap (the command line writes what these return), the
labelled layout, reciprocity at backscatter (S_hv = S_vh, so sigma_hv = sigma_vh: a
property of any reciprocal medium, e.g. Ulaby & Long, *Microwave Radar and Radiometric
Remote Sensing*, 2014, sec. 5-6), the wave spectrum against the Pierson-Moskowitz closed
forms and the paper's eq 14 scaling, and bad input named.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import numpy as np
import pytest

import seaecho
from seaecho.config import SceneError
from seaecho.ocean.seawater import meissner_wentz
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.scattering.models import sea_sigma

SEA = """
name = "api-stages"
[sea]
spectrum = "pierson-moskowitz"
wind_speed_m_s = 8.0
size_x_m = 64.0
nx = 32
[ship]
length_m = 10.0
beam_m = 4.0
draft_m = 1.5
speed_kn = 10.0
heading_deg = 35.0
[run]
seed = 3
surface_times_s = [0.0, 0.5]
"""


def test_sigma_is_the_model_on_labelled_axes():
    s = seaecho.sigma("two-scale", theta_s_deg=[20.0, 40.0], phi_s_deg=np.arange(0, 181, 45))
    assert s.dims == ("theta_s_deg", "phi_s_deg", "polarisation")
    assert s["theta_i_deg"].ndim == 0 and float(s["theta_i_deg"]) == 20.0
    assert s["polarisation"].values.tolist() == ["HH", "HV", "VH", "VV"]
    spec = DirectionalSpectrum(u19_5=4.53)
    eps = complex(meissner_wentz(10e9, 20.0, 35.0))
    ts, ps = np.meshgrid(np.radians([20.0, 40.0]), np.radians(np.arange(0, 181, 45)),
                         indexing="ij")
    ref = sea_sigma("two-scale", np.radians(20.0), 0.0, ts, ps, 10e9, spec, eps)
    np.testing.assert_array_equal(s.values, ref)
    assert s.attrs["eps_r_real"] == eps.real and s.attrs["units"] == "m2 m-2"


def test_sigma_backscatter_is_reciprocal_and_from_a_scene():
    scene = seaecho.parse_scene(SEA)
    s = seaecho.sigma("blend", theta_i_deg=40.0, theta_s_deg=40.0, phi_s_deg=180.0,
                      scene=scene, frequency_hz=9.4e9)
    assert s.dims == ("polarisation",)
    assert float(s.sel(polarisation="HV")) == pytest.approx(float(s.sel(polarisation="VH")),
                                                            rel=1e-9)
    assert s.attrs["wind_speed_m_s"] == 8.0 and s.attrs["spectrum"] == "pierson-moskowitz"
    with pytest.raises(SceneError, match="do not give wind_speed_m_s"):
        seaecho.sigma(scene=scene, frequency_hz=9.4e9, wind_speed_m_s=3.0)
    with pytest.raises(SceneError, match=r"no \[radar\]"):
        seaecho.sigma(scene=scene)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"theta_i_deg": 95.0}, r"theta_i_deg = 95.0: values must lie in \[0, 90\]"),
    ({"phi_s_deg": [[0.0]]}, "phi_s_deg: expected"),
    ({"frequency_hz": 0.0}, "frequency_hz = 0"),
    ({"wind_speed_m_s": 0.0}, "wind_speed_m_s = 0"),
    ({"cut_ratio": 2.0}, "cut_ratio = 2.0"),
    ({"spectrum": "jonswap"}, "needs fetch_m"),
    ({"model": "lambert"}, "model = 'lambert'"),
])
def test_sigma_bad_input_is_named(kwargs, message):
    with pytest.raises(SceneError, match=message):
        seaecho.sigma(**kwargs)


def test_permittivity():
    eps = seaecho.permittivity([5e9, 10e9])
    assert eps.dims == ("frequency_hz",) and eps.dtype == np.complex128
    ref = complex(meissner_wentz(10e9, 20.0, 35.0))
    assert complex(eps.sel(frequency_hz=10e9)) == pytest.approx(ref, rel=1e-12)
    assert eps.values[0].imag < 0  # exp(+j omega t): eps' - j eps''
    assert seaecho.permittivity(10e9).ndim == 0
    with pytest.raises(SceneError, match="frequency_hz"):
        seaecho.permittivity(-1.0)
    with pytest.raises(SceneError, match="salinity"):
        seaecho.permittivity(10e9, salinity_psu=90.0)


def test_surface_dataset():
    ds = seaecho.surface(seaecho.parse_scene(SEA))
    assert ds["elevation"].dims == ("time", "y", "x") and ds.sizes["time"] == 2
    assert float(np.abs(ds["wake_elevation"]).max()) > 0
    one = seaecho.surface(seaecho.parse_scene(SEA), 0.5)
    assert one["elevation"].values.tobytes() == ds["elevation"].values[1].tobytes()
    with pytest.raises(SceneError, match="times"):
        seaecho.surface(seaecho.parse_scene(SEA), [0.0, float("nan")])


def test_trace_and_compare():
    scene = seaecho.parse_scene(SEA)
    tx = [-200.0, -150.0, 25.0]
    ds = seaecho.trace(scene, 0.5, mode="analytic", tx_position=tx, frequency_hz=10e9)
    assert ds["visibility"].dims == ("y_cell", "x_cell", "triangle")
    w = ds["area"] / ds["area"].sum()
    assert ds.attrs["lit_fraction_tx"] == pytest.approx(float((w * ds["lit"]).sum()))
    assert ds.attrs["facet_mode"] == "analytic" and ds.attrs["time_s"] == 0.5
    cmp = seaecho.compare(scene, tx_position=tx, frequency_hz=10e9)
    assert cmp["visibility"].dims == ("mode", "y_cell", "x_cell")
    assert cmp["sigma_sum"].dims == ("mode", "polarisation")
    d = cmp["theta_i_difference"].values
    assert np.isfinite(d).any() and cmp["theta_i_difference"].attrs["units"] == "deg"
    with pytest.raises(SceneError, match="rx_position needs tx_position"):
        seaecho.trace(scene, rx_position=tx)
    with pytest.raises(SceneError, match=r"no \[transmitter\]"):
        seaecho.trace(scene, frequency_hz=10e9)
    with pytest.raises(SceneError, match=r"no \[radar\]"):
        seaecho.trace(scene, tx_position=tx)


def test_wave_spectrum_against_pierson_moskowitz_closed_forms():
    # Pierson & Moskowitz (1964) in the paper's eq 5 form S(K) = a0 / (2 K^3)
    # exp(-b0 g^2 / (K^2 U^4)), a0 = 8.1e-3, b0 = 0.74 (the 1/2: docs/ocean.md): its
    # maximum at K_p = sqrt(2 b0 / 3) g / U^2 (dS/dK = 0), its significant wave height
    # H_s = 4 sqrt(a0 U^4 / (4 b0 g^2)) = 0.2092 U^2 / g, and the paper's eq 14 scaling
    # S(K / a^2; a U) = a^6 S(K; U).
    from seaecho.constants import G

    k = np.geomspace(1e-3, 10.0, 50)
    s = seaecho.wave_spectrum(k, wind_speed_m_s=10.0, spectrum="pierson-moskowitz")
    assert s.dims == ("wavenumber",) and s.attrs["units"] == "m3"
    np.testing.assert_allclose(s.values, 8.1e-3 / (2 * k**3)
                               * np.exp(-0.74 * G**2 / (k**2 * 10.0**4)), rtol=1e-12)
    assert s.attrs["peak_wavenumber_rad_m"] == pytest.approx(
        np.sqrt(2 * 0.74 / 3) * G / 100.0, rel=1e-6)
    assert s.attrs["significant_wave_height_m"] == pytest.approx(0.2092 * 100.0 / G,
                                                                 rel=2e-3)
    a = 2.0
    s2 = seaecho.wave_spectrum(k / a**2, wind_speed_m_s=10.0 * a, spectrum="pierson-moskowitz")
    np.testing.assert_allclose(s2.values, a**6 * s.values, rtol=1e-12)
    # a scene's [sea] gives the same spectrum as its values
    scene = seaecho.parse_scene(SEA)
    np.testing.assert_array_equal(
        seaecho.wave_spectrum(k, scene=scene).values,
        seaecho.wave_spectrum(k, wind_speed_m_s=8.0, spectrum="pierson-moskowitz").values)
    with pytest.raises(SceneError, match="wavenumber_rad_m"):
        seaecho.wave_spectrum([0.0, 1.0])
    with pytest.raises(SceneError, match="wind_speed_m_s = -1"):
        seaecho.wave_spectrum(1.0, wind_speed_m_s=-1.0)
