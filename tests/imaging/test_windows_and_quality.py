"""Azimuth windows against scipy and Harris (1978); IRF measures on analytic responses."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.signal import windows

from seaecho.imaging.quality import irf_cut
from seaecho.imaging.windows import AzimuthWindow, cosine_coefficients


@pytest.mark.parametrize("nbar, sll", [(4, 30.0), (5, 35.0), (8, 45.0)])
def test_taylor_series_is_scipys_window(nbar, sll):
    # Parity with scipy.signal.windows.taylor, which samples the same cosine series
    # (Taylor 1955; Carrara et al. 1995, appendix D) at xi = (n - M/2 + 1/2) / M
    m = 101
    w = AzimuthWindow.named("taylor", 1.0, nbar, sll)
    xi = (np.arange(m) - m / 2 + 0.5) / m
    np.testing.assert_allclose(w(xi), windows.taylor(m, nbar, sll, norm=True), atol=1e-12)


def test_hamming_is_harris_and_zero_outside_the_band():
    w = AzimuthWindow.named("hamming", 100.0)
    # Harris (1978), eq 30: 0.54 + 0.46 cos(2 pi xi), 0.08 at the band edges
    np.testing.assert_allclose(w(np.array([0.0, 0.25, 0.5])), [1.0, 0.54, 0.08])
    assert w(np.array([0.5001, -0.7])).tolist() == [0.0, 0.0]
    assert cosine_coefficients("none") == (1.0,)
    with pytest.raises(ValueError, match="window = 'kaiser'"):
        cosine_coefficients("kaiser")
    with pytest.raises(ValueError, match="Doppler bandwidth"):
        AzimuthWindow(0.0)


def test_irf_measures_of_a_sinc():
    # sinc(t): 3 dB width 0.886, first sidelobe -13.26 dB, ISLR over +-20 from quad
    t = np.linspace(-20, 20, 40001)
    m = irf_cut(np.sinc(t - 0.1234), t)
    assert m.resolution == pytest.approx(0.8859, abs=1e-3)
    assert m.pslr_db == pytest.approx(-13.26, abs=0.01)
    assert m.peak_position == pytest.approx(0.1234, abs=2e-3)
    main = quad(lambda x: np.sinc(x) ** 2, -1, 1)[0]
    total = quad(lambda x: np.sinc(x) ** 2, -20.1234, 19.8766, limit=400)[0]
    assert m.islr_db == pytest.approx(10 * np.log10((total - main) / main), abs=0.02)
    with pytest.raises(ValueError, match="end of the cut"):
        irf_cut(np.sinc(t[:100]), t[:100])
