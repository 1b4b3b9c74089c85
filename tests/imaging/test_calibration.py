"""Calibration pieces: the compressed pulse's energy and the radar-equation factor."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.imaging.calibration import Track, amplitude_factor, compressed_pulse_energy
from seaecho.radar.antennas import Antenna
from seaecho.radar.waveform import lfm_chirp


@pytest.mark.parametrize("weighting, enbw", [("none", 1.00), ("hamming", 1.36)])
def test_compressed_pulse_energy_is_the_equivalent_noise_bandwidth(weighting, enbw):
    # For an LFM pulse of large time-bandwidth product the compressed spectrum is the
    # weighting W(f) over the band, chi(0) = 1, so E_chi = ENBW / B (Parseval), with the
    # equivalent noise bandwidths of Harris (1978), Table 1: 1.00 and 1.36 bins
    b, fs = 100e6, 120e6
    s = lfm_chirp(b, 20e-6, fs)  # B T = 2000
    assert compressed_pulse_energy(s, fs, weighting) * b == pytest.approx(enbw, rel=0.02)


def test_amplitude_factor_is_the_bistatic_radar_equation():
    # Eq K1 squared is Skolnik (2008) eq 23.1 for sigma = 1 m^2: isotropic transmitter,
    # 0.18 x 0.14 m aperture receiver looking straight at the point (25.6 dBi)
    lam = 0.03
    x = np.array([[10.0, 20.0, 0.0]])
    tx, rx = np.array([[-500.0, 0.0, 300.0]]), np.array([[100.0, -400.0, 200.0]])
    b = (x[0] - rx[0]) / np.linalg.norm(x[0] - rx[0])
    w = np.cross([0.0, 0.0, 1.0], b)
    w /= np.linalg.norm(w)
    axes = np.stack([b, w, np.cross(b, w)], axis=-1)[None]
    track = Track(tx, rx, np.zeros_like(tx), np.zeros_like(rx), np.tile(np.eye(3), (1, 1, 1)),
                  axes)
    iso = Antenna("isotropic", lam)
    rect = Antenna("rectangular", lam, 0.18, 0.14)
    a = amplitude_factor(x, track, iso, rect, 50.0, lam)[0, 0]
    r_t, r_r = np.linalg.norm(x - tx), np.linalg.norm(x - rx)
    p_r = 50.0 * 1.0 * rect.peak_gain * lam**2 / ((4 * np.pi) ** 3 * r_t**2 * r_r**2)
    # (a ratio: p_r is about 1e-13 W, below pytest.approx's default absolute tolerance)
    assert a**2 / p_r == pytest.approx(1.0, rel=1e-9)
    assert 10 * np.log10(rect.peak_gain) == pytest.approx(25.6, abs=0.05)
