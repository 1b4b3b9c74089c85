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
