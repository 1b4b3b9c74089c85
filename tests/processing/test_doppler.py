"""Doppler processing (processing/doppler.py, eqs DP1-DP2) and the Doppler of moving facets."""

import numpy as np
import pytest

from seaecho.build import build_radar
from seaecho.config import parse_scene
from seaecho.constants import C0
from seaecho.processing.doppler import (
    autocorrelation,
    doppler_moments,
    doppler_spectrum,
    range_doppler,
)
from seaecho.radar.system import RadarSystem
from seaecho.scattering.dynamics import extrapolate

ISO = {"pattern": "isotropic", "look_at_m": (0.0, 0.0, 0.0)}


def test_periodogram_is_a_power_density_and_finds_a_tone():
    # Eq DP1 is a PSD: for white noise of power P its mean over the band is P / PRF and
    # its sum times PRF / N is P (Parseval, with the window's energy normalised away).
    # A tone at f0 peaks at f0.
    rng = np.random.default_rng(0)
    prf, n = 1000.0, 256
    x = (rng.normal(size=(n, 2, 300)) + 1j * rng.normal(size=(n, 2, 300))) * np.sqrt(0.5 * 3.0)
    f, psd = range_doppler(x, prf, cpi=64)
    assert psd.shape == (2, 64, 300)
    assert np.mean(psd.sum(axis=1) * prf / 64) == pytest.approx(3.0, rel=0.02)
    t = np.arange(n) / prf
    tone = np.exp(2j * np.pi * 137.0 * t)[:, None, None] * np.ones((1, 1, 4))
    f, psd = range_doppler(tone, prf)
    spec = doppler_spectrum(f, psd)
    assert abs(f[np.argmax(spec[0])] - 137.0) <= prf / n
    c, w = doppler_moments(f, spec)
    assert c[0] == pytest.approx(137.0, abs=1.0) and w[0] < 5.0
    rho = autocorrelation(tone, 3)
    np.testing.assert_allclose(rho[0], np.exp(2j * np.pi * 137.0 * np.arange(4) / prf))
    with pytest.raises(ValueError, match="cpi"):
        range_doppler(x, prf, cpi=1)


def test_moving_facet_doppler_is_minus_path_rate_over_lambda():
    # A flat facet moving at v (its phase centre carried by eq D1) returns, after range
    # compression and Doppler processing, the Doppler f_D = -(1 / lambda) d(r_T + r_R)/dt
    # (the bistatic Doppler of a moving point; e.g. Willis 2005, Bistatic Radar, ch. 2)
    # with r_T, r_R the ranges to the transmitter and the receiver: within one Doppler
    # bin (PRF / 128) after the whole chain, within 0.5 Hz from the echo's carrier phase.
    # Approaching the radars gives f_D > 0.
    sc = parse_scene({
        "sea": {"wind_speed_m_s": 3.0, "size_x_m": 8.0, "nx": 8},
        "radar": {"carrier_frequency_hz": 10e9, "sampling_rate_hz": 60e6, "prf_hz": 1000.0,
                  "n_pulses": 128, "sea_clutter": False, "channels": ["VV"],
                  "waveform": {"kind": "lfm", "bandwidth_hz": 50e6, "duration_s": 1e-6}},
        "transmitter": {"position_m": (-600.0, 0.0, 300.0), "antenna": ISO},
        "receiver": {"position_m": (-300.0, -400.0, 150.0), "antenna": ISO},
        "targets": [{"position_m": (0.0, 0.0, 0.0), "rcs_m2": 1e-9}],
    })
    radar = RadarSystem(build_radar(sc))
    lam = C0 / 10e9
    p0 = np.array([[0.5, -0.3, 0.0]])
    tx, rx = np.array(sc.transmitter.position_m), np.array(sc.receiver.position_m)

    def path(t, v):
        q = p0[0] + v[0] * t
        return np.linalg.norm(q - tx) + np.linalg.norm(q - rx)

    for v, chain in ((np.array([[-1.3, 0.4, 0.2]]), True),
                     (np.array([[2.0, 0.5, -0.3]]), False)):
        f_d = -(path(1e-3, v) - path(-1e-3, v)) / 2e-3 / lam
        rc, phase = [], []
        for p in range(radar.n_pulses):
            geo = radar.geometry(p)
            pos = extrapolate(p0, v, None, geo.time)
            echo = radar.scatterer_echo(geo, pos, v, np.eye(2, dtype=complex)[None])
            phase.append(echo.amplitudes[0, 0])
            if chain:  # received, range compressed, Doppler processed
                rc.append(radar.receive(p, [echo], noise=False))
        if chain:
            f, psd = range_doppler(np.array(rc), radar.prf)
            spec = doppler_spectrum(f, psd)
            assert abs(f[np.argmax(spec[0])] - f_d) <= radar.prf / radar.n_pulses
        # the carrier phase turns at f_D from pulse to pulse (sub-Hz)
        dphi = np.angle(np.array(phase[1:]) / np.array(phase[:-1]))
        assert np.mean(dphi) * radar.prf / (2 * np.pi) == pytest.approx(f_d, abs=0.5)
        assert np.sign(f_d) == -np.sign(path(1e-3, v) - path(0.0, v))
