"""Calibration of the speckled facet amplitudes: E|a_mn|^2 = sigma_mn A (eq P4-P5).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest
from scattering_helpers import gaussian_spectrum

from seaecho.geometry import frames
from seaecho.scattering.facet import FacetModel, facet_amplitudes
from seaecho.scattering.spm import spm_sigma

EPS = 55.9 - 37.0j
K = 2 * np.pi * 10e9 / 299_792_458.0


@pytest.mark.parametrize("area", [3.0, 0.75])
def test_amplitudes_calibrated_by_area_against_flat_spm(area):
    # |a_mn|^2 is the facet's radar cross section: its mean over independent speckle
    # draws is sigma_mn x A (eqs P4-P5), with sigma_mn for a flat facet (normal +z) the
    # mean-plane first-order SPM of scattering.spm (paper eqs 8-9; a separate code path).
    # 100 000 copies of one facet: |a|^2 is exponential, the relative standard error of
    # its mean is 1/sqrt(100 000) = 0.32 %; tolerance 2 %. A wrong area scaling (A^2,
    # sqrt A) or a lost factor 4 pi would be off by far more.
    n = 100_000
    ti, ts, ps = np.radians(35.0), np.radians(45.0), np.radians(150.0)
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ts, ps)
    normal = np.broadcast_to(frames.Z_HAT, (n, 3))
    args = (np.broadcast_to(n_i, (n, 3)), np.broadcast_to(n_s, (n, 3)), normal,
            np.full(n, area), FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01, model="spm"))
    a = facet_amplitudes(*args, np.random.default_rng(5))
    np.testing.assert_array_equal(a, facet_amplitudes(*args, np.random.default_rng(5))
                                  )  # reproducible
    expected = area * spm_sigma(ti, 0.0, ts, ps, K, EPS, gaussian_spectrum)
    np.testing.assert_allclose(np.mean(np.abs(a) ** 2, axis=0), expected, rtol=0.02)
