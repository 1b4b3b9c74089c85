"""Range compression of linear FM pulses: main-lobe width and sidelobes."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.constants import C0
from seaecho.processing.range_compression import range_compress, weighting_window
from seaecho.radar.waveform import lfm_chirp, plain_pulse

FS, B, T = 400e6, 100e6, 10e-6  # time-bandwidth product 1000: the sinc limit holds


def _compressed(weighting, up=32):
    s = lfm_chirp(B, T, FS)
    raw = np.zeros(12000, complex)
    raw[3000:3000 + s.size] = s
    y = range_compress(raw, s, weighting)
    n = y.size
    spec = np.fft.fft(y)
    yu = np.fft.ifft(np.concatenate([spec[: n // 2], np.zeros(n * (up - 1)),
                                     spec[n // 2:]])) * up
    return y, np.abs(yu) ** 2, up


def _width_and_psl(p, up):
    i = int(np.argmax(p))
    db = 10 * np.log10(p / p[i])

    def crossing(step):
        j = i
        while db[j + step] > -3.0:
            j += step
        # linear interpolation between samples j and j + step
        return j + step * (db[j] + 3.0) / (db[j] - db[j + step])

    width = (crossing(1) - crossing(-1)) / up / FS  # [s]
    m = i
    while p[m + 1] < p[m]:  # walk down the main lobe to its first null
        m += 1
    psl = db[m: m + int(60 * up * FS / B)].max()
    return width, psl


def test_unweighted_width_and_peak_sidelobe():
    # LFM with large BT compresses to ~sinc(B t): 3 dB width 0.886 / B, i.e.
    # 0.886 c / (2B) in range, and peak sidelobe -13.26 dB (Cook & Bernfeld 1967, ch. 6;
    # Richards, Fundamentals of Radar Signal Processing 2014, section 4.6). Fresnel
    # ripples of a BT = 1000 chirp move both by < 1 %.
    y, p, up = _compressed("none")
    width, psl = _width_and_psl(p, up)
    assert C0 * width / 2 == pytest.approx(0.886 * C0 / (2 * B), rel=0.01)
    assert psl == pytest.approx(-13.26, abs=0.15)
    # calibrated: the peak of a unit echo at an integer delay is 1, at its delay
    assert np.argmax(np.abs(y)) == 3000 and abs(y[3000]) == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("weighting,psl_ref,widen", [("hamming", -42.7, 1.30 / 0.89),
                                                      ("taylor", -35.0, 1.18 / 0.89)])
def test_weighted_sidelobes(weighting, psl_ref, widen):
    # Hamming: highest sidelobe -43 dB (-42.7), 3 dB width 1.30 bins against 0.89 for the
    # rectangle (Harris 1978, Table 1). Taylor nbar = 5, -35 dB: sidelobes at the design
    # level, 3 dB width ~1.18 bins (Carrara et al., Spotlight SAR 1995, Table 4.4).
    _, p, up = _compressed(weighting)
    width, psl = _width_and_psl(p, up)
    assert psl == pytest.approx(psl_ref, abs=0.7)
    assert width * B / 0.886 == pytest.approx(widen, rel=0.03)


def test_plain_pulse_compresses_to_triangle():
    # Matched filter of a rectangular pulse: triangular output of base 2T (Richards 2014,
    # section 4.2)
    s = plain_pulse(1e-6, 100e6)
    raw = np.zeros(1000, complex)
    raw[200:300] = s
    y = range_compress(raw, s)
    np.testing.assert_allclose(np.abs(y[200:300]), 1 - np.arange(100) / 100, atol=1e-12)


def test_weighting_rejects_unknown():
    with pytest.raises(ValueError, match="weighting"):
        weighting_window("kaiser", 10)
