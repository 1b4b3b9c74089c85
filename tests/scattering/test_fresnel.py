"""Fresnel coefficients against closed forms (Born & Wolf 1999, sec. 1.5)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.scattering.fresnel import fresnel_coefficients


def test_brewster_angle_real_permittivity():
    # Brewster's law (Born & Wolf 1999, sec. 1.5.3): R_v = 0 at tan(theta_B) = sqrt(eps).
    eps = 2.25
    theta_b = np.arctan(np.sqrt(eps))
    r_h, r_v = fresnel_coefficients(np.cos(theta_b), eps)
    assert abs(r_v) < 1e-14
    # R_h = -sin(ti - tt) / sin(ti + tt) (Fresnel, Born & Wolf sec. 1.5.2) with tt = 90 deg - ti
    # there gives cos(2 theta_B).
    np.testing.assert_allclose(r_h, np.cos(2 * theta_b), atol=1e-14)


def test_pseudo_brewster_minimum_lossy_sea_water():
    # For a lossy medium |R_v| has a non-zero minimum near atan(sqrt|eps|) (the
    # pseudo-Brewster angle; Ulaby & Long 2014, sec. 2-8.3).
    eps = 56.0 - 37.0j
    th = np.radians(np.linspace(60, 89.9, 30000))
    r_v = np.abs(fresnel_coefficients(np.cos(th), eps)[1])
    th_min = np.degrees(th[np.argmin(r_v)])
    assert abs(th_min - np.degrees(np.arctan(np.sqrt(abs(eps))))) < 1.0
    assert 0.0 < r_v.min() < 0.3


def test_normal_incidence_and_grazing():
    eps = 56.0 - 37.0j
    r_h, r_v = fresnel_coefficients(1.0, eps)
    r0 = (1 - np.sqrt(eps)) / (1 + np.sqrt(eps))
    # At normal incidence R_h = r0 and R_v = -r0 in the FSA bases (same field, h/v flip).
    np.testing.assert_allclose([r_h, r_v], [r0, -r0], rtol=1e-14)
    np.testing.assert_allclose(fresnel_coefficients(0.0, eps), [-1.0, -1.0], atol=1e-14)


@settings(max_examples=300, deadline=None)
@given(st.floats(0.0, 1.0), st.floats(1.0, 90.0), st.floats(0.0, 60.0))
def test_passive_medium_reflects_at_most_everything(c, er, ei):
    # Energy conservation: a passive medium (eps'' >= 0 with exp(+j w t)) gives |R| <= 1.
    r_h, r_v = fresnel_coefficients(c, complex(er, -ei))
    assert abs(r_h) <= 1.0 + 1e-12 and abs(r_v) <= 1.0 + 1e-12
