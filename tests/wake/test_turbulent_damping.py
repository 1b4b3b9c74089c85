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
