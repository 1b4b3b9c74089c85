"""Blend weights (eqs 10-11) and the two-scale model.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest
from scattering_helpers import gaussian_spectrum

from seaecho.scattering.blend import blend, blend_weights, channel_weights
from seaecho.scattering.spm import spm_sigma
from seaecho.scattering.twoscale import two_scale_sigma
from seaecho.scattering.validity import SPMValidityWarning

EPS = 55.9 - 37.0j
K = 2 * np.pi * 10e9 / 299_792_458.0


def test_blend_weights_at_stated_angles():
    # Paper eqs 10-11 with beta in degrees: w = 0.1 where (beta / c)^p = 1, i.e. at
    # beta = 6 pi = 18.85 deg (co-pol) and 20 pi = 62.83 deg (cross-pol); 1 at specular.
    w1, w2 = blend_weights([0.0, 6 * np.pi, 20 * np.pi])
    np.testing.assert_allclose(w1[:2], [1.0, 0.1], rtol=1e-12)
    np.testing.assert_allclose(w2[[0, 2]], [1.0, 0.1], rtol=1e-12)
    # "Kirchhoff valid within +-20 deg": w1 falls from 0.37 to 0.004 between 17 and 21 deg
    # (10^-(17/18.85)^8 = 0.365, 10^-(21/18.85)^8 = 0.0042).
    w1, _ = blend_weights([17.0, 19.0, 21.0])
    assert 0.3 < w1[0] < 0.4 and 0.05 < w1[1] < 0.1 and w1[2] < 0.01
    b = np.linspace(0, 90, 91)
    w1, w2 = blend_weights(b)
    assert np.all(np.diff(w1) <= 0) and np.all(np.diff(w2) <= 0)


def test_blend_channels_use_their_weights():
    # Paper eqs 10-11 at beta = 6 pi deg = 18.85 deg, written out: co-pol (HH, VV) take
    # w1 = 10^-((beta / 6 pi)^8) = 0.1, cross-pol (HV, VH) w2 = 10^-((beta / 20 pi)^1.5)
    # = 10^-(0.3^1.5) = 0.6846; sigma = (1 - w) sigma_SPM + w sigma_K per channel.
    s_spm = np.array([1.0, 2.0, 3.0, 4.0])
    s_k = np.array([10.0, 20.0, 30.0, 40.0])
    w2 = 10.0 ** (-(0.3**1.5))
    expected = np.array([0.9 * 1.0 + 0.1 * 10.0, (1 - w2) * 2.0 + w2 * 20.0,
                         (1 - w2) * 3.0 + w2 * 30.0, 0.9 * 4.0 + 0.1 * 40.0])
    np.testing.assert_allclose(blend(s_spm, s_k, 6 * np.pi), expected, rtol=1e-12)
    np.testing.assert_allclose(channel_weights(6 * np.pi), [0.1, w2, w2, 0.1], rtol=1e-12)


def test_two_scale_tends_to_spm_as_slopes_vanish():
    ti, ts = np.radians(35.0), np.radians(40.0)
    ps = np.radians(np.array([60.0, 120.0, 180.0]))
    s_spm = spm_sigma(ti, 0.0, ts, ps, K, EPS, gaussian_spectrum)
    s_ts = two_scale_sigma(ti, 0.0, ts, ps, K, EPS, gaussian_spectrum, 1e-12, 1e-12, 0.0,
                           k_cut=1.0)
    # Relative to each geometry's strongest channel (cross-pol vanishes at backscatter).
    err = np.abs(s_ts - s_spm) / s_spm.max(axis=-1, keepdims=True)
    assert np.all(err < 1e-4), err


def test_two_scale_depolarises_at_backscatter():
    # Tilts out of the plane of incidence rotate the polarisation bases (Valenzuela
    # 1968): two-scale backscatter has HV = VH > 0 while flat SPM has none; the co-pol
    # ratio VV/HH is reduced towards 1.
    th = np.radians(np.array([30.0, 45.0]))
    s_ts = two_scale_sigma(th, 0.0, th, np.pi, K, EPS, gaussian_spectrum, 0.02, 0.02, 0.0,
                           k_cut=1.0)
    s_spm = spm_sigma(th, 0.0, th, np.pi, K, EPS, gaussian_spectrum)
    assert np.all(s_ts[:, 1] > 1e-4 * s_ts[:, 0])
    np.testing.assert_allclose(s_ts[:, 1], s_ts[:, 2], rtol=1e-10)
    assert np.all(s_ts[:, 3] / s_ts[:, 0] < s_spm[:, 3] / s_spm[:, 0])


def test_two_scale_warns_when_small_scale_too_rough():
    with pytest.warns(SPMValidityWarning):
        two_scale_sigma(0.5, 0.0, 0.5, np.pi, K, EPS, gaussian_spectrum, 0.01, 0.01, 0.0,
                        k_cut=1.0, small_scale_height_variance=(0.5 / K) ** 2)
