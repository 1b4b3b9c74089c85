"""Pauli decomposition of canonical targets, multilook and speckle filters on simulated
speckle (exponential single-look intensity, Goodman 1976; Lee & Pottier 2009, ch. 4)."""

from __future__ import annotations

import numpy as np
import pytest

from seaecho.imaging.speckle import (
    boxcar,
    edge_masks,
    multilook,
    pauli_powers,
    refined_lee,
    speckle_filter,
)


def _fsa(s_bsa):
    """FSA channels of a BSA matrix, eq (S0): S_FSA = diag(-1, 1) S_BSA."""
    s = np.diag([-1.0, 1.0]) @ np.asarray(s_bsa, dtype=complex)
    return {"HH": s[0, 0], "HV": s[0, 1], "VH": s[1, 0], "VV": s[1, 1]}


@pytest.mark.parametrize("s_bsa, rgb", [
    # Cloude & Pottier (1996), Table 1; Lee & Pottier (2009), section 3.3: sphere or plate
    # (odd bounce) -> blue, dihedral (even bounce) -> red, 45 deg dihedral -> green
    ([[1, 0], [0, 1]], [0.0, 0.0, 2.0]),
    ([[1, 0], [0, -1]], [2.0, 0.0, 0.0]),
    ([[0, 1], [1, 0]], [0.0, 2.0, 0.0]),
])
def test_pauli_of_canonical_targets(s_bsa, rgb):
    np.testing.assert_allclose(pauli_powers(_fsa(s_bsa)), rgb, atol=1e-12)
    assert pauli_powers({"HH": 1.0, "VV": 1.0}) is None


def _speckle(shape, rng, mean=1.0):
    return mean * rng.exponential(1.0, shape)


def test_multilook_and_boxcar_reach_their_number_of_looks():
    rng = np.random.default_rng(0)
    i = _speckle((512, 512), rng, 3.0)
    ml = multilook(i, (4, 2))
    assert ml.shape == (128, 256)
    assert ml.mean() == pytest.approx(3.0, rel=0.01)
    # equivalent number of looks mean^2 / var = 8 for 8 independent exponential samples
    assert ml.mean() ** 2 / ml.var() == pytest.approx(8.0, rel=0.05)
    bc = boxcar(i, 7)
    assert bc.mean() ** 2 / bc.var() == pytest.approx(49.0, rel=0.08)
    with pytest.raises(ValueError, match="looks"):
        multilook(i, (0, 2))
    with pytest.raises(ValueError, match="speckle filter"):
        speckle_filter(i, "median")


def test_edge_masks_are_halves_of_28_pixels():
    m = edge_masks()
    assert m.shape == (8, 7, 7)
    np.testing.assert_array_equal(m.sum(axis=(1, 2)), 28)
    assert np.all(m[:, 3, 3] == 1)  # each holds the centre


def test_refined_lee_smooths_flat_areas_and_keeps_edges():
    rng = np.random.default_rng(1)
    ny, nx = 256, 256
    level = np.where(np.arange(nx)[None, :] < nx // 2, 1.0, 10.0) * np.ones((ny, 1))
    i = level * rng.exponential(1.0, (ny, nx))
    out = refined_lee(np.stack([i, 0.1 * i]))
    # the same weights on every channel keep the polarimetric ratio (Lee et al. 1999)
    np.testing.assert_allclose(out[1], 0.1 * out[0], rtol=1e-9)
    flat = out[0][:, 20:100]
    assert flat.mean() == pytest.approx(1.0, rel=0.04)  # unbiased on a flat area
    assert flat.mean() ** 2 / flat.var() > 10.0  # speckle reduced (1 look in)
    # One column from the edge on the dark side, the refined Lee filter picks the half
    # window away from the edge; the 7 x 7 boxcar mixes in 2 bright columns
    col = nx // 2 - 1
    box = boxcar(i, 7)
    bias_lee = abs(np.median(out[0][:, col]) / np.median(out[0][:, 40]) - 1.0)
    bias_box = abs(np.median(box[:, col]) / np.median(box[:, 40]) - 1.0)
    assert bias_lee < 0.5 * bias_box


def test_refined_lee_is_the_same_filter_at_any_scale():
    # Eq (S1): b = (v - m^2 sigma_v^2) / (v (1 + sigma_v^2)) is unchanged when the
    # intensities are scaled (v ~ c^2, m^2 ~ c^2), so filter(c I) = c filter(I) (Lee
    # 1981). Intensities of 1e160 (a squared amplitude of 1e80) used to overflow the local
    # variance E[I^2] - m^2 to Inf - Inf = NaN (found by the fuzzing suite via an
    # infinite Pauli power); far below 1e-160 their squares underflowed to 0
    rng = np.random.default_rng(2)
    i = np.where(np.arange(32)[None, :] < 16, 1.0, 10.0) * rng.exponential(1.0, (32, 32))
    ref = refined_lee(np.stack([i, 0.3 * i]))
    for c in (1e160, 1e-200):
        with np.errstate(all="raise"):
            out = refined_lee(np.stack([c * i, 0.3 * c * i]))
        np.testing.assert_allclose(out, c * ref, rtol=1e-12)
