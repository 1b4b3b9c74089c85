"""The sea a range cell covers (eq F1 of seaecho.detection.footprint): the beam's
half-power width against the line-source constants (Skolnik 2001, table 9.1; Balanis
2016, section 12.5) and the pulse-limited cell R theta_B Delta R sec psi on flat and 4/3
Earths (Skolnik 2001, section 7.1; sin psi of eq E1 of seaecho.geometry.earth)."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.detection import clutter_cell_area, half_power_width
from seaecho.radar.antennas import Antenna

LAMBDA_M = 0.0319
KA_M = 4.0 / 3.0 * 6371.0088e3


@pytest.mark.parametrize(("illumination", "k_hp", "rel"), [
    # uniform: sinc^2 falls to 1/2 at L u / lambda = 0.44295 (Balanis 2016, 12.5)
    ("uniform", 0.88590, 2e-4),
    # cosine: 1.19 lambda / L (Skolnik 2001, table 9.1, quoted to three figures)
    ("cosine", 1.19, 5e-3),
])
def test_half_power_width_of_line_sources(illumination, k_hp, rel):
    width = 2.0
    ant = Antenna("rectangular", LAMBDA_M, width, 0.12, illumination=illumination)
    want = 2.0 * np.arcsin(0.5 * k_hp * LAMBDA_M / width)
    assert half_power_width(ant.gain_local) == pytest.approx(want, rel=rel)


def test_half_power_width_of_an_omnidirectional_pattern_is_the_circle():
    assert half_power_width(Antenna("isotropic", LAMBDA_M).gain_local) == 2.0 * np.pi


def test_clutter_cell_area_closed_forms():
    r, dr, th, h = 2000.0, 15.0, np.deg2rad(1.0), 35.0
    # flat Earth: sin psi = h / R
    flat = r * th * dr / np.sqrt(1.0 - (h / r) ** 2)
    assert clutter_cell_area(r, dr, th, np.arcsin(h / r)) == pytest.approx(flat, rel=1e-12)
    assert flat == pytest.approx(523.68, abs=0.01)
    # 4/3 Earth: sin psi = h / R + h^2 / (2 k a R) - R / (2 k a) (eq E1, law of cosines)
    from seaecho.geometry.earth import grazing_angle

    s = h / r + h * h / (2 * KA_M * r) - r / (2 * KA_M)
    sphere = r * th * dr / np.sqrt(1.0 - s * s)
    assert clutter_cell_area(r, dr, th, grazing_angle(h, r, KA_M)) == pytest.approx(
        sphere, rel=1e-12)
    # no sea nearer than the height or beyond the horizon (psi < 0)
    psi = grazing_angle(h, np.array([20.0, 30e3]), KA_M)
    assert np.isnan(clutter_cell_area([20.0, 30e3], dr, th, psi)).all()
