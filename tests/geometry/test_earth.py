"""The 4/3 Earth: grazing angle, horizon, drop and the scene frame on a sphere.

References: Federal Standard 1037C (1996), "radio horizon range (RHR)": on the 4/3
Earth, R = 1.23 (sqrt(h_t) + sqrt(h_r)) NM with the heights in feet and
2.23 (sqrt(h_t) + sqrt(h_r)) NM with them in metres (4.12 km sqrt(h [m]) for one end);
Skolnik, *Introduction to Radar Systems*, 3rd ed. (2001), chapter 8, and Blake, *Radar
Range-Performance Analysis* (1986), chapter 5 (the 4/3 Earth; their equation numbers
not checked here). The grazing angle (eq E1) is the law of cosines, checked against the
sphere's own geometry.
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.geometry.earth import (
    EARTH_RADIUS_M,
    SphericalEarth,
    effective_radius,
    grazing_angle,
    horizon_range,
    surface_drop,
)

R43 = effective_radius(4.0 / 3.0)


def test_horizon_rule_4_12_km_per_sqrt_m():
    # FS-1037C, "radio horizon range": 2.23 NM sqrt(h [m]) = 4.13 km for k = 4/3;
    # sqrt(2 k a) = 4.122 km per sqrt(m) with a = 6371 km
    assert horizon_range(1.0, 0.0, R43) / 1e3 == pytest.approx(4.12, rel=1e-3)
    assert horizon_range(1.0, 0.0, R43) / 1852.0 == pytest.approx(2.23, rel=2e-3)
    # a 25 m coastal antenna: 20.6 km to a sea-level target; two 25 m masts: 41.2 km
    assert horizon_range(25.0, 0.0, R43) / 1e3 == pytest.approx(20.6, rel=1e-3)
    assert horizon_range(25.0, 25.0, R43) == pytest.approx(2 * horizon_range(25.0, 0, R43))


def test_horizon_rule_1_23_nmi_per_sqrt_ft():
    # FS-1037C, "radio horizon range": R [NM] = 1.23 sqrt(h [ft]); h = 100 ft -> 12.3 NM
    d_nmi = horizon_range(100 * 0.3048, 0.0, R43) / 1852.0
    assert d_nmi == pytest.approx(12.3, rel=2e-3)


def test_grazing_angle_flat_limit_and_horizon_zero():
    h, r = 30.0, np.array([500.0, 3000.0, 10000.0])
    # infinite radius: sin psi = h / r (flat Earth)
    np.testing.assert_allclose(grazing_angle(h, r, np.inf), np.arcsin(h / r), rtol=1e-15)
    # eq E1 vanishes at the tangent point, r^2 = 2 R h + h^2 (the horizon's slant range)
    r_h = np.sqrt(2 * R43 * h + h * h)
    assert abs(grazing_angle(h, r_h, R43)) < 1e-12
    assert grazing_angle(h, 1.01 * r_h, R43) < 0


def test_grazing_angle_eq_e1_against_the_sphere():
    # Eq E1 is the law of cosines: compare with the geometry of the sphere itself
    earth = SphericalEarth(R43)
    h = 30.0
    for rho in (1000.0, 5000.0, 15000.0):
        radar = earth.position(np.array([rho, 0.0, h]))  # the radar at rho, the point at 0
        r = np.linalg.norm(radar)
        psi = np.arcsin(radar[2] / r)  # elevation of the radar seen from the origin
        assert grazing_angle(h, r, R43) == pytest.approx(psi, rel=1e-9, abs=1e-13)
    # 30 m at 5 km: 0.343 deg flat, 0.327 deg on the 4/3 Earth (eq E1)
    assert np.degrees(grazing_angle(30.0, 5000.0, R43)) == pytest.approx(0.3270, abs=2e-4)


def test_drop_and_mapping():
    d = np.array([0.0, 1000.0, 10000.0])
    np.testing.assert_allclose(surface_drop(d, R43), d * d / (2 * R43), rtol=1e-6)
    earth = SphericalEarth(R43)
    p = earth.position(np.array([[0.0, 10000.0, 0.0]]))
    # the surface point 10 km north is d^2 / (2 R) = 5.9 m below the tangent plane
    assert p[0, 2] == pytest.approx(-surface_drop(10000.0, R43), rel=1e-6)
    # its local vertical, turned by rho / R towards north
    up = earth.tilt(np.array([0.0, 10000.0, 0.0])) @ np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(up, [0.0, np.sin(1e4 / R43), np.cos(1e4 / R43)], atol=1e-15)
    assert EARTH_RADIUS_M == pytest.approx(6.371e6, rel=1e-5)


@pytest.mark.parametrize("h1, h2", [(25.0, 0.0), (30.0, 10.0), (15.0, 20.0)])
def test_target_just_inside_and_beyond_the_horizon(h1, h2):
    earth = SphericalEarth(R43)
    d_h = horizon_range(h1, h2, R43)
    radar = earth.position(np.array([0.0, 0.0, h1]))
    inside = earth.position(np.array([0.0, 0.995 * d_h, h2]))
    beyond = earth.position(np.array([0.0, 1.005 * d_h, h2]))
    assert earth.visible(radar, inside)
    assert not earth.visible(radar, beyond)
