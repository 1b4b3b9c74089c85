"""Weighting windows, one module for every use (processing/windows.py, eq W1).

Against the textbook windows (Harris 1978, eqs 27b and 30: Hann 0.5 - 0.5 cos, Hamming
0.54 - 0.46 cos over N - 1 intervals, as numpy samples them) and Taylor's (1955) window
as scipy samples it (``scipy.signal.windows.taylor``, cosine series of the same
coefficients).
"""

import numpy as np
import pytest
from scipy.signal import windows as sw

from seaecho.processing.windows import cosine_coefficients, sampled_window, window_values


@pytest.mark.parametrize("n", [1, 2, 7, 64, 65])
def test_symmetric_hamming_is_harris_window(n):
    np.testing.assert_allclose(sampled_window("hamming", n), np.hamming(n), atol=1e-14)


@pytest.mark.parametrize("n", [2, 7, 64])
def test_open_hann_has_no_zero_end_samples(n):
    w = sampled_window("hann", n, open_ends=True)
    np.testing.assert_allclose(w, np.hanning(n + 2)[1:-1], atol=1e-14)
    assert w.min() > 0
    np.testing.assert_allclose(sampled_window("hann", n), np.hanning(n), atol=1e-14)


def test_taylor_series_is_scipys_window():
    # scipy samples the same series at xi = (n - (N - 1)/2) / N, unnormalised
    n, nbar, sll = 64, 5, 35.0
    c = cosine_coefficients("taylor", nbar, sll)
    xi = (np.arange(n) - 0.5 * (n - 1)) / n
    ref = sw.taylor(n, nbar=nbar, sll=sll, norm=False, sym=True)
    np.testing.assert_allclose(window_values(c, xi) * sum(c), ref, rtol=1e-12)
    w = sampled_window("taylor", n, nbar, sll)
    assert w.max() <= 1.0 and w[0] == pytest.approx(w[-1])


def test_window_is_one_at_the_centre_and_zero_outside():
    for kind in ("none", "hann", "hamming", "taylor"):
        c = cosine_coefficients(kind)
        assert window_values(c, 0.0) == pytest.approx(1.0)
        assert window_values(c, 0.51) == 0.0
    with pytest.raises(ValueError, match="unknown"):
        cosine_coefficients("kaiser")
