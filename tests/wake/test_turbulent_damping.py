"""Bragg damping in the turbulent wake: partial, decaying with age (eq W15).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest

from seaecho.wake import Ship, turbulent_damping_profile, turbulent_wake_mask, turbulent_wake_strip


def _contrast_db(d):
    return 10.0 * np.log10(1.0 - d)


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


def test_wake_contrast_is_a_few_db_not_full_suppression():
    """The paper's boat: the wake core is at most about -8 dB just behind the stern and
    -3 to -4 dB ten ship lengths behind it (it was -inf, complete damping, before);
    within the bound of the strongest published film damping at moderate wind (a spectral
    contrast of about 10, -10 dB, for an artificial oil slick at 6-8 m/s; Dulov &
    Yurovskaya) everywhere beyond one beam behind the stern."""
    ship = Ship(10.0, 4.0, 1.5, 5.144, 0.0, (0.0, 0.0))
    xi = np.array([4.0, 20.0, 100.0])
    x = -(5.0 + xi)  # sailing +x: behind the stern at negative x
    d = turbulent_wake_mask(ship, x, np.array([0.0]), 0.0)[0]
    c = _contrast_db(d)
    assert -10.0 < c[0] < -6.0
    assert -6.0 < c[1] < -4.0
    assert -4.5 < c[2] < -3.0
    assert np.all(np.diff(c) > 0)  # recovers with age xi / V
    strip = turbulent_wake_strip(ship, x, np.array([0.0]), 0.0)[0]
    np.testing.assert_array_equal(strip, 1.0)


def test_film_contrast_option_and_bad_value():
    ship = Ship(10.0, 4.0, 1.5, 5.144, turbulent_wake_film_contrast_db=-6.0)
    d = turbulent_wake_mask(ship, np.array([-5.0 - 1000.0]), np.array([0.0]), 0.0,
                            length=2000.0)[0, 0]
    assert _contrast_db(d) == pytest.approx(-6.0, abs=0.3)
    with pytest.raises(ValueError, match="turbulent_wake_film_contrast_db"):
        Ship(10.0, 4.0, 1.5, 5.144, turbulent_wake_film_contrast_db=1.0)


def test_simulated_wake_to_sea_contrast_through_the_facet_model():
    """The wake-to-sea sigma0 contrast the simulation produces, HH and VV, for the paper's
    boat on the paper's Simulation 2 sea (X band, 10 GHz, U = 5.5 m/s), monostatic, flat
    facets, through the same facet model (two-scale blend, tilt average) and sea model the
    simulation uses (:func:`seaecho.build.build_sea_model`).

    No published dB contrast of a turbulent wake against the sea could be found to
    compare with (docs/wake.md lists what was searched), so this is a closed-form check:
    at moderate incidence the Bragg term dominates and SPM's sigma is proportional to the
    height spectrum at the Bragg wavenumber (Valenzuela 1978), so the contrast is
    10 log10(1 - d) with d of eq W15, the same for HH and VV; near nadir the (undamped)
    Kirchhoff term dominates and the wake vanishes. Fails if the damping multiplied the
    Bragg amplitude instead of its power (contrast halved in dB), if it damped the
    specular term too (a wake visible at 5 deg), or if the decay with age had the wrong
    sign (contrast deepening downstream)."""
    from seaecho.build import build_sea_model
    from seaecho.config.loading import load_scene
    from seaecho.geometry import frames
    from seaecho.scattering.facet import facet_sigma

    sea = build_sea_model(load_scene("scenes/paper_sim2_sar_128m_wind55.toml"))
    ship = Ship(10.0, 4.0, 1.5, 5.144, 0.0, (0.0, 0.0))
    xi = np.array([4.0, 20.0, 100.0, 1000.0])
    d = turbulent_wake_mask(ship, -(5.0 + xi), np.array([0.0]), 0.0, length=5000.0)[0]

    def contrast_db(theta_deg):
        ti = np.full(xi.size, np.radians(theta_deg))
        n_i, n_s = frames.directions_from_angles(ti, 0.0, ti, np.pi)
        normal = np.broadcast_to(frames.Z_HAT, n_i.shape)
        args = (n_i, n_s, normal, *sea.facet_model)
        sea_only = facet_sigma(*args, backend="numpy", **sea.facet_options)
        wake = facet_sigma(*args, backend="numpy", wake_damping=d, **sea.facet_options)
        return 10.0 * np.log10(wake / sea_only)[:, [0, 3]]  # HH, VV

    for theta in (20.0, 30.0, 45.0):
        c = contrast_db(theta)
        np.testing.assert_allclose(c, np.repeat(_contrast_db(d)[:, None], 2, axis=1),
                                   atol=0.02)
    # the paper's boat: -7.7, -4.8, -3.7, -3.2 dB at 4, 20, 100, 1000 m behind the stern
    np.testing.assert_allclose(contrast_db(30.0)[:, 1], [-7.68, -4.81, -3.66, -3.16],
                               atol=0.02)
    assert np.all(np.diff(contrast_db(30.0), axis=0) > 0)  # recovers with age xi / V
    assert np.all(np.abs(contrast_db(5.0)) < 0.01)  # specular region: no dark wake
