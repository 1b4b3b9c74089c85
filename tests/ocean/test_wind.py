"""Wind speed at 10, 12.5 and 19.5 m: one neutral logarithmic profile (eq L1)."""

import numpy as np
import pytest

from seaecho.ocean.wind import (
    u10_from_u19_5,
    u12_5_from_u19_5,
    u19_5_from_u10,
    wind_speed_at,
)


def test_log_profile_with_stewarts_drag_coefficient():
    # Neutral log profile U(z) = (u*/kappa) ln(z/z0) with u* = sqrt(C_D) U10, kappa = 0.41
    # and C_D = 1.3e-3 (Stewart 2008, sec. 4.3 and the C_D stated with his eq 16.29),
    # written out here: U(z)/U10 = 1 + sqrt(1.3e-3)/0.41 ln(z / 10 m).
    a = np.sqrt(1.3e-3) / 0.41
    assert float(u19_5_from_u10(10.0)) / 10.0 == pytest.approx(1 + a * np.log(1.95), rel=1e-12)
    assert float(u19_5_from_u10(1.0)) == pytest.approx(1.0587, abs=5e-5)
    assert float(wind_speed_at(1.0, 10.0, 12.5)) == pytest.approx(1.0196, abs=5e-5)
    # the profile's roughness length z0 = 10 m exp(-kappa / sqrt(C_D)) = 0.115 mm, within
    # Charnock's z0 = 0.011 u*^2 / g for U10 of 8-10 m/s (Stewart 2008, sec. 4.3)
    z0 = 10.0 * np.exp(-1.0 / a)
    assert z0 == pytest.approx(1.15e-4, rel=0.01)
    for u10 in (8.0, 10.0):
        u_star = np.sqrt(1.3e-3) * u10
        assert 0.5 < z0 / (0.011 * u_star**2 / 9.81) < 1.5


def test_conversions_compose_and_invert():
    u = np.array([2.0, 4.53, 12.0])
    np.testing.assert_allclose(u10_from_u19_5(u19_5_from_u10(u)), u, rtol=1e-14)
    # 19.5 -> 12.5 directly equals 19.5 -> 10 -> 12.5: one profile for all heights
    np.testing.assert_allclose(u12_5_from_u19_5(u),
                               wind_speed_at(u10_from_u19_5(u), 10.0, 12.5), rtol=1e-14)
    with pytest.raises(ValueError, match="heights"):
        wind_speed_at(5.0, 0.0, 10.0)


def test_every_stage_uses_this_profile():
    # The spectra (U10 for JONSWAP / Elfouhaily) and the Cox-Munk slopes (U12.5) take
    # their conversions from seaecho.ocean.wind, not constants of their own.
    from seaecho.ocean import spectra
    from seaecho.ocean.spectra import elfouhaily_parameters
    from seaecho.scattering import slopes

    assert spectra.u10_from_u19_5 is u10_from_u19_5
    assert slopes.u12_5_from_u19_5 is u12_5_from_u19_5
    assert elfouhaily_parameters(float(u19_5_from_u10(7.0))).u10 == pytest.approx(7.0)


def test_friction_velocity_laws_against_their_sources():
    # Each law as its source prints it, at U10 = 10 m/s:
    # constant drag C_D = 1.3e-3 (Stewart 2008): u* = 0.3606 m/s;
    # Wu (1982) C_D = (0.8 + 0.065 U10) 1e-3 = 1.45e-3: u* = 0.3808 m/s;
    # Donelan et al. (1993) in Elfouhaily et al. (1997): z0 = 3.7e-5 U10^2 / g
    # Omega_c^0.9 = 0.3226 mm at Omega_c = 0.84, u* = 0.41 U10 / ln(10 / z0) = 0.3964 m/s.
    from seaecho.ocean.wind import (
        FRICTION_VELOCITY_LAWS,
        charnock_roughness_length,
        friction_velocity,
    )

    assert float(friction_velocity("constant-drag", 10.0)) == pytest.approx(0.36056, rel=1e-4)
    assert float(friction_velocity("wu-1982", 10.0)) == pytest.approx(
        10.0 * np.sqrt(1.45e-3), rel=1e-12)
    assert float(friction_velocity("wu-1982", 20.0)) == pytest.approx(
        20.0 * np.sqrt(2.1e-3), rel=1e-12)  # Wu's C_D grows with the wind
    z0 = 3.7e-5 * 100.0 / 9.80665 * 0.84**0.9
    assert z0 == pytest.approx(3.226e-4, rel=1e-3)
    assert float(friction_velocity("donelan-1993", 10.0)) == pytest.approx(
        0.41 * 10.0 / np.log(10.0 / z0), rel=1e-12)
    assert float(friction_velocity("donelan-1993", 10.0, 2.0)) > float(
        friction_velocity("donelan-1993", 10.0))  # a young sea is rougher
    assert sorted(FRICTION_VELOCITY_LAWS) == ["constant-drag", "donelan-1993", "wu-1982"]
    with pytest.raises(ValueError, match="friction-velocity law"):
        friction_velocity("charnock", 10.0)
    # KHCC03 eq 21: z0 = 0.018 u*^2 / g + 0.1 nu_a / u*, nu_a = 1.47e-5 m^2/s
    assert float(charnock_roughness_length(0.4)) == pytest.approx(
        0.018 * 0.16 / 9.80665 + 0.1 * 1.47e-5 / 0.4, rel=1e-12)


def test_each_model_names_its_friction_velocity_law():
    # The breaking-wave model takes Wu (1982), as KHCC03 do; the Elfouhaily spectrum
    # Donelan's wave-age dependent roughness, as Elfouhaily et al. do.
    from seaecho.ocean.spectra import elfouhaily_parameters
    from seaecho.ocean.wind import friction_velocity
    from seaecho.scattering import breaking

    assert breaking.FRICTION_LAW == "wu-1982"
    p = elfouhaily_parameters(float(u19_5_from_u10(10.0)))
    assert p.u_star == pytest.approx(float(friction_velocity("donelan-1993", 10.0, 0.84)),
                                     rel=1e-12)
