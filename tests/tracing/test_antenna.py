"""The rectangular aperture of the radar stage registered as a Sionna RT pattern."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.radar.antennas import Antenna, aperture_radiated_power

LAM = C0 / 10e9


def test_sionna_registration_matches_numpy():
    # Sionna's evaluation of the registered pattern against the radar stage's numpy gain
    # of eq (A1) (Balanis 2016, sec. 12.5); float32 in Sionna, hence 1e-4.
    pytest.importorskip("sionna.rt")
    from seaecho.tracing.antenna import register_sionna_aperture
    from seaecho.tracing.variant import mitsuba_modules

    name = register_sionna_aperture(0.18, 0.14, LAM,
                                    aperture_radiated_power(0.18, 0.14, LAM))
    _, mi, _ = mitsuba_modules()
    from sionna.rt.antenna_pattern import antenna_pattern_registry

    pattern = antenna_pattern_registry.get(name)(polarization="V")
    theta = np.array([np.pi / 2, np.pi / 2 - 0.1, np.pi / 2, 1.3])
    phi = np.array([0.0, 0.0, 0.15, -0.2])
    c_theta, c_phi = pattern.patterns[0](mi.Float(theta), mi.Float(phi))
    g_sionna = np.abs(np.array(c_theta.real)) ** 2 + np.abs(np.array(c_phi.real)) ** 2
    d = np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], -1)
    g_numpy = Antenna("rectangular", LAM, 0.18, 0.14).gain_local(d)
    np.testing.assert_allclose(g_sionna, g_numpy, rtol=1e-4)
    assert np.all(g_numpy > 0)


def test_radar_stage_does_not_import_sionna():
    # docs/design.md: only seaecho.tracing imports mitsuba / sionna.
    import seaecho.radar.antennas as ant

    assert not hasattr(ant, "register_sionna_aperture")
    from pathlib import Path

    src = Path(ant.__file__).read_text(encoding="utf-8")
    assert "import sionna" not in src and "import mitsuba" not in src
