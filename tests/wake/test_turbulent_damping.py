"""Bragg damping in the turbulent wake: partial, decaying with age (eq W15), and the
Marangoni damping of the wake's surfactant film (eqs W16, W17).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import tomllib
import warnings

import numpy as np
import pytest

from seaecho.build import build_sea, build_sea_model
from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.ocean.dispersion import angular_frequency
from seaecho.wake import (
    NU_SEA_WATER,
    Ship,
    film_contrast_db,
    marangoni_damping_ratio,
    turbulent_damping_profile,
    turbulent_wake_film_contrast_db,
    turbulent_wake_mask,
    turbulent_wake_strip,
)

SIM2 = "scenes/paper_sim2_sar_128m_wind55.toml"


def _contrast_db(d):
    return 10.0 * np.log10(1.0 - d)


def _bragg(frequency_hz, incidence_deg):
    return 2.0 * (2.0 * np.pi * frequency_hz / C0) * np.sin(np.radians(incidence_deg))


def _sim2(**sea):
    with open(SIM2, "rb") as f:
        data = tomllib.load(f)
    data["sea"].update(sea)
    return parse_scene(data)


def test_profile_limits_and_decay_law():
    """Complete suppression at the stern (Milgram, Peltzer & Griffin 1993); the turbulent
    part decays as the eddy viscosity of the momentumless wake, (1 + xi/w0)^(-3/5)
    (Tennekes & Lumley 1972), down to the persistent film contrast C_f."""
    w0 = 4.0
    assert turbulent_damping_profile(0.0, w0, -3.0) == pytest.approx(1.0)
    xi = np.array([10.0, 100.0, 1000.0])
    no_film = turbulent_damping_profile(xi, w0, 0.0)
    np.testing.assert_allclose(no_film, (1 + xi / w0) ** -0.6, rtol=1e-12)
    # ratio of the turbulent damping over a decade of xi far downstream: 10^-0.6
    assert no_film[2] / no_film[1] == pytest.approx(((1 + 250) / (1 + 25)) ** -0.6)
    far = turbulent_damping_profile(1e9, w0, -3.0)
    assert _contrast_db(far) == pytest.approx(-3.0, abs=1e-3)
    with pytest.raises(ValueError, match="film_contrast_db"):
        turbulent_damping_profile(xi, w0, 2.0)


def test_marangoni_ratio_clean_and_inextensible_limits():
    """Eq W16 between its two closed-form limits: no film (E = 0) is clean water, y = 1;
    an inextensible film (E -> infinity) damps the wave's amplitude at Lamb's (1932, art.
    351) rate k sqrt(nu omega / 8), against 2 nu k^2 on clean water (art. 348). Fails if
    X lost its sqrt(2) or Y its factor 4 (the limit moves by sqrt(2) or 2), or if the
    dispersion relation lost its capillary term (omega at 300 rad/m off by 40 %)."""
    k = np.array([26.0, 87.0, 143.0, 296.0, 404.0])  # L, C, X (20, 45 deg), Ku band
    np.testing.assert_array_equal(marangoni_damping_ratio(k, 0.0), 1.0)
    omega = angular_frequency(k)
    lamb = (k * np.sqrt(NU_SEA_WATER * omega / 8.0)) / (2.0 * NU_SEA_WATER * k**2)
    np.testing.assert_allclose(marangoni_damping_ratio(k, 1.0e4), lamb, rtol=1e-3)
    assert np.all(lamb > 4.0)  # the inextensible film damps 4 (Ku) to 27 (L band) times more
    with pytest.raises(ValueError, match="elasticity"):
        marangoni_damping_ratio(k, -0.01)
    with pytest.raises(ValueError, match="wavenumbers"):
        marangoni_damping_ratio(np.array([0.0, 100.0]), 0.01)


def test_marangoni_damping_peaks_near_8_hz_for_a_modulus_of_0p01_n_per_m():
    """Alpers & Huehnerfuss (1988): airborne radar over an oil spill (Singh et al. 1986)
    showed maximum wave damping at frequencies around 8 Hz, which Marangoni theory
    predicts for a film of dilational modulus "of the order of 0.01 N/m". The frequency of
    the maximum of eq W16 for E = 0.01 N/m lies within 6-12 Hz (stated tolerance for "of
    the order of"); a film twice as stiff peaks at lower frequency (longer waves)."""
    k = np.geomspace(20.0, 3000.0, 4000)
    f = angular_frequency(k) / (2.0 * np.pi)
    peak = f[np.argmax(marangoni_damping_ratio(k, 0.010))]
    assert 6.0 < peak < 12.0
    assert f[np.argmax(marangoni_damping_ratio(k, 0.020))] < peak


def test_simulated_slick_contrast_against_huehnerfuss_1978():
    """The only measured film contrast found with its band, incidence, wind and
    polarisations: Huehnerfuss, Alpers & Jones (1978, Radio Sci. 13), an oleyl
    alcohol monolayer on the North Sea (JONSWAP 75), Ku band 13.9 GHz, 41 and 47 deg
    incidence, VV and HH, winds of 3.5-4.4 m/s: maximum NRCS reduction 7.3 +- 3.5 dB.

    The simulation's sea (the paper's Simulation 2 sea at U10 = 4 m/s, through the facet
    model and sea model the simulation uses) under the strongest film Marangoni theory
    allows (inextensible, W16 -> Lamb's limit; the abstract gives no elasticity) reduces
    sigma0 by 6.0-6.3 dB, inside the measured range, and the same for VV and HH (Bragg
    theory holds over slicks: Alpers, Holt & Zeng 2017). Fails if the film divided the
    Bragg amplitude instead of its spectrum (3 dB), or damped the specular term."""
    from seaecho.geometry import frames
    from seaecho.scattering.facet import facet_sigma

    sea = build_sea_model(_sim2(wind_speed_m_s=4.23), frequency=13.9e9)  # U10 = 4.0 m/s
    for theta in (41.0, 47.0):
        c_f = film_contrast_db(_bragg(13.9e9, theta), 1.0e4)
        ti = np.full(1, np.radians(theta))
        n_i, n_s = frames.directions_from_angles(ti, 0.0, ti, np.pi)
        args = (n_i, n_s, np.broadcast_to(frames.Z_HAT, n_i.shape), sea.facet_model)
        clean = facet_sigma(*args, backend="numpy")
        film = facet_sigma(*args, backend="numpy", wake_damping=np.array([1 - 10 ** (c_f / 10)]))
        reduction = -10.0 * np.log10(film / clean)[0, [0, 3]]  # HH, VV
        assert np.all(np.abs(reduction - 7.3) <= 3.5), (theta, reduction)
        np.testing.assert_allclose(reduction, -c_f, atol=0.05)


def test_wake_contrast_near_and_far_behind_the_stern():
    """The paper's boat seen at the Simulation 2 geometry (X band, 45 deg, k_B = 296
    rad/m): the turbulent part deepens the wake near the stern and decays with age
    (W15) down to the film's Marangoni contrast (W17, E = 0.01 N/m), -3.75 dB; the wake
    of a scene without a radar holds the turbulent part alone."""
    k_b = _bragg(10.0e9, 45.0)
    ship = Ship(10.0, 4.0, 1.5, 5.144, 0.0, (0.0, 0.0), bragg_wavenumber=k_b)
    c_f = turbulent_wake_film_contrast_db(ship)
    assert c_f == pytest.approx(film_contrast_db(k_b, 0.010))
    assert c_f == pytest.approx(-3.75, abs=0.01)
    xi = np.array([4.0, 20.0, 100.0, 5000.0])
    x = -(5.0 + xi)  # sailing +x: behind the stern at negative x
    c = _contrast_db(turbulent_wake_mask(ship, x, np.array([0.0]), 0.0, length=1.0e5)[0])
    expected = 10 * np.log10(1 - (1 + xi / 4.0) ** -0.6) + c_f
    np.testing.assert_allclose(c, expected, atol=1e-9)
    assert np.all(np.diff(c) > 0)  # recovers with age xi / V
    assert c[-1] == pytest.approx(c_f, abs=0.25)
    strip = turbulent_wake_strip(ship, x, np.array([0.0]), 0.0, length=1.0e5)[0]
    np.testing.assert_array_equal(strip, 1.0)
    no_radar = Ship(10.0, 4.0, 1.5, 5.144)
    assert turbulent_wake_film_contrast_db(no_radar) == 0.0


def test_film_contrast_override_elasticity_and_bad_values():
    ship = Ship(10.0, 4.0, 1.5, 5.144, turbulent_wake_film_contrast_db=-6.0,
                bragg_wavenumber=300.0)
    d = turbulent_wake_mask(ship, np.array([-5.0 - 1000.0]), np.array([0.0]), 0.0,
                            length=2000.0)[0, 0]
    assert _contrast_db(d) == pytest.approx(-6.0, abs=0.3)
    stiff = Ship(10.0, 4.0, 1.5, 5.144, turbulent_wake_film_elasticity=0.025,
                 bragg_wavenumber=300.0)
    assert turbulent_wake_film_contrast_db(stiff) == pytest.approx(film_contrast_db(300.0, 0.025))
    assert film_contrast_db(0.0) == 0.0  # specular geometry
    for kwargs, match in (({"turbulent_wake_film_contrast_db": 1.0}, "film_contrast_db"),
                          ({"turbulent_wake_film_elasticity": -1e-3}, "film_elasticity"),
                          ({"bragg_wavenumber": np.nan}, "bragg_wavenumber")):
        with pytest.raises(ValueError, match=match):
            Ship(10.0, 4.0, 1.5, 5.144, **kwargs)


def test_builder_sets_the_scene_bragg_wavenumber_and_film():
    """[ship] film fields and the scene's Bragg wavenumber (2 k sin 45 deg for the paper's
    Simulation 2 SAR, looking 45 deg down) reach the wake; without [radar] the ship has
    none."""
    ship = build_sea(_sim2()).ship
    assert ship.bragg_wavenumber == pytest.approx(_bragg(10.0e9, 45.0), rel=1e-3)
    assert ship.turbulent_wake_film_elasticity == pytest.approx(0.010)
    assert ship.turbulent_wake_film_contrast_db is None
    sea = {"wind_speed_m_s": 5.0, "size_x_m": 16.0, "nx": 16}
    cfg = {"length_m": 10.0, "beam_m": 4.0, "draft_m": 1.5, "speed_kn": 10.0,
           "turbulent_wake_film_elasticity_mn_m": 25.0,
           "turbulent_wake_film_contrast_db": -4.0}
    ship = build_sea(parse_scene({"sea": sea, "ship": cfg})).ship
    assert ship.bragg_wavenumber is None
    assert ship.turbulent_wake_film_elasticity == pytest.approx(0.025)
    assert ship.turbulent_wake_film_contrast_db == -4.0


def test_scene_bragg_wavenumber_with_a_platform_at_the_tile_centre():
    """A transmitter at the tile centre (which the preflight refuses) has no direction to
    it: the builder falls back to 2 k sin 45 deg instead of dividing 0 by 0 (a
    RuntimeWarning found by the fuzzing suite's geometry mutations)."""
    from seaecho.build import _scene_bragg_wavenumber

    with open(SIM2, "rb") as f:
        data = tomllib.load(f)
    data["transmitter"]["position_m"] = [0.0, 0.0, 0.0]
    data["transmitter"].pop("velocity_m_s", None)
    k = 2.0 * np.pi * 10.0e9 / C0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        k_b = _scene_bragg_wavenumber(parse_scene(data), k)
    assert k_b == pytest.approx(2.0 * k * np.sin(np.pi / 4))


def test_simulated_wake_to_sea_contrast_through_the_facet_model():
    """The wake-to-sea sigma0 contrast the simulation produces, HH and VV, for the paper's
    boat on the paper's Simulation 2 sea (X band, 10 GHz, U19.5 = 4.84 m/s), monostatic,
    flat facets, through the same facet model (two-scale blend, tilt average) and sea
    model the simulation uses (:func:`seaecho.build.build_sea_model`); the film's contrast
    at each incidence's Bragg wavenumber (W17).

    No published dB contrast of a turbulent wake against the sea could be found to
    compare with (docs/wake.md lists what was searched), so this is a closed-form check:
    at moderate incidence the Bragg term dominates and SPM's sigma is proportional to the
    height spectrum at the Bragg wavenumber (Valenzuela 1978), so the contrast is
    10 log10(1 - d) with d of eq W15, the same for HH and VV; near nadir the (undamped)
    Kirchhoff term dominates and the wake vanishes. Fails if the damping multiplied the
    Bragg amplitude instead of its power (contrast halved in dB), if it damped the
    specular term too (a wake visible at 5 deg), or if the decay with age had the wrong
    sign (contrast deepening downstream)."""
    from seaecho.geometry import frames
    from seaecho.scattering.facet import facet_sigma

    sea = build_sea_model(_sim2())
    xi = np.array([4.0, 20.0, 100.0, 1000.0])

    def contrast_db(theta_deg):
        ship = Ship(10.0, 4.0, 1.5, 5.144, 0.0, (0.0, 0.0),
                    bragg_wavenumber=_bragg(10.0e9, max(theta_deg, 20.0)))
        d = turbulent_wake_mask(ship, -(5.0 + xi), np.array([0.0]), 0.0, length=5000.0)[0]
        ti = np.full(xi.size, np.radians(theta_deg))
        n_i, n_s = frames.directions_from_angles(ti, 0.0, ti, np.pi)
        normal = np.broadcast_to(frames.Z_HAT, n_i.shape)
        args = (n_i, n_s, normal, sea.facet_model)
        sea_only = facet_sigma(*args, backend="numpy")
        wake = facet_sigma(*args, backend="numpy", wake_damping=d)
        return 10.0 * np.log10(wake / sea_only)[:, [0, 3]], _contrast_db(d)  # HH, VV

    for theta in (20.0, 30.0, 45.0):
        c, expected = contrast_db(theta)
        np.testing.assert_allclose(c, np.repeat(expected[:, None], 2, axis=1), atol=0.02)
    # the paper's boat at Simulation 2's 45 deg: 4, 20, 100, 1000 m behind the stern
    np.testing.assert_allclose(contrast_db(45.0)[0][:, 1], [-8.43, -5.57, -4.42, -3.91],
                               atol=0.02)
    assert np.all(np.diff(contrast_db(30.0)[0], axis=0) > 0)  # recovers with age xi / V
    assert np.all(np.abs(contrast_db(5.0)[0]) < 0.01)  # specular region: no dark wake
