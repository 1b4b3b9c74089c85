"""Resolution cells (``seaecho.radar.resolution``) against their closed forms: the ground
range of a monostatic radar at grazing psi, c / (2 B cos psi), and of a bistatic pair in
its plane, c / (2 B cos(beta / 2)) (Willis, *Bistatic Radar*, 2005, ch. 8); the stripmap
azimuth resolution D / 2 (Cumming and Wong 2005, ch. 4)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.radar.resolution import (
    azimuth_resolution,
    footprint_length,
    ground_range_resolution,
    slant_range_resolution,
    synthetic_aperture,
)

B = 100e6


def _towards_origin(elevation: float, azimuth: float) -> np.ndarray:
    """Unit vector from a platform at (elevation, azimuth) seen from the origin, towards
    the origin."""
    return -np.array([math.cos(elevation) * math.cos(azimuth),
                      math.cos(elevation) * math.sin(azimuth), math.sin(elevation)])


def test_slant_range_resolution_is_c_over_2b():
    assert slant_range_resolution(B) == pytest.approx(1.49896229, rel=1e-8)


@pytest.mark.parametrize("grazing_deg", [5.0, 30.0, 60.0])
def test_monostatic_ground_resolution_is_c_over_2b_cos_grazing(grazing_deg):
    u = _towards_origin(math.radians(grazing_deg), 0.7)
    cell, direction = ground_range_resolution(B, u, u)
    assert cell == pytest.approx(C0 / (2 * B * math.cos(math.radians(grazing_deg))))
    np.testing.assert_allclose(direction, [math.cos(0.7), math.sin(0.7)], atol=1e-12)


@pytest.mark.parametrize("beta_deg", [10.0, 60.0, 120.0])
def test_bistatic_ground_resolution_in_the_plane_is_c_over_2b_cos_half_beta(beta_deg):
    # both platforms on the ground plane (grazing 0), beta apart in azimuth
    beta = math.radians(beta_deg)
    cell, _ = ground_range_resolution(B, _towards_origin(0.0, 0.0),
                                      _towards_origin(0.0, beta))
    assert cell == pytest.approx(C0 / (2 * B * math.cos(beta / 2)))


def test_no_ground_resolution_straight_below():
    u = np.array([0.0, 0.0, -1.0])
    assert ground_range_resolution(B, u, u) is None


def test_stripmap_azimuth_resolution_is_half_the_antenna():
    lam, r, d = 0.03, 5000.0, 1.2
    assert azimuth_resolution(lam, r, footprint_length(lam, r, d)) == pytest.approx(d / 2)


def test_synthetic_aperture_counts_the_speed_across_the_line_of_sight():
    los = np.array([1.0, 0.0, 0.0])
    assert synthetic_aperture(np.array([30.0, 40.0, 0.0]), los, 2.0) == pytest.approx(80.0)
