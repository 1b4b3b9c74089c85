"""The Dr.Jit facet kernel agrees with the numpy path; the spectrum table is accurate."""

import numpy as np
import pytest

from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.scattering import frames
from seaecho.scattering.facet import _drjit_available, facet_terms
from seaecho.scattering.slopes import cox_munk_parameters
from seaecho.scattering.spectrum_table import BraggSpectrumTable

K = 2 * np.pi * 10e9 / 299_792_458.0
EPS = 55.9 - 37.0j


def _facets(n=3000, seed=2):
    rng = np.random.default_rng(seed)
    normal = np.column_stack([rng.normal(0, 0.15, (n, 2)), np.ones(n)])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    n_i, n_s = frames.directions_from_angles(rng.uniform(0, 1.5, n), rng.uniform(-3, 3, n),
                                             rng.uniform(0, 1.5, n), rng.uniform(-3, 3, n))
    # Singular cases: nadir backscatter, forward specular, grazing, Tx = Rx off nadir,
    # facet normal along the ray.
    n_i[:5] = [[0, 0, -1], [0.6, 0, -0.8], [1, 0, 0], [0.6, 0, -0.8], -normal[4]]
    n_s[:5] = [[0, 0, 1], [0.6, 0, 0.8], [1, 0, 0], [-0.6, 0, 0.8], normal[4]]
    normal[:4] = [0, 0, 1]
    return n_i, n_s, normal


@pytest.fixture(scope="module")
def table():
    spec = DirectionalSpectrum(u19_5=7.0, wind_direction=0.5)
    return BraggSpectrumTable(spec.height_spectrum, K / 3, 20 * K)


def test_table_matches_spectrum(table):
    # Bilinear interpolation of log W on 1024 x 360 nodes: relative error < 1e-3 off the
    # nodes for the Elfouhaily spectrum (smooth in log K and azimuth).
    spec = DirectionalSpectrum(u19_5=7.0, wind_direction=0.5)
    rng = np.random.default_rng(0)
    kmag = np.exp(rng.uniform(np.log(K / 3), np.log(20 * K), 5000))
    psi = rng.uniform(-np.pi, np.pi, 5000)
    kx, ky = kmag * np.cos(psi), kmag * np.sin(psi)
    np.testing.assert_allclose(table(kx, ky), spec.height_spectrum(kx, ky), rtol=1e-3)
    assert table(np.array([K / 4]), np.array([0.0]))[0] == 0.0


@pytest.mark.skipif(not _drjit_available(), reason="Dr.Jit LLVM backend unavailable")
@pytest.mark.parametrize("model", ["blend", "spm", "kirchhoff"])
@pytest.mark.parametrize("cm", [False, True])
def test_drjit_equals_numpy(table, model, cm):
    n_i, n_s, normal = _facets()
    damp = np.linspace(0, 1, len(n_i))
    kw = dict(model=model, cox_munk=cox_munk_parameters(6.0) if cm else None,
              wake_damping=damp)
    a = facet_terms(n_i, n_s, normal, K, EPS, table, 0.01, 0.006, 0.5, backend="numpy", **kw)
    b = facet_terms(n_i, n_s, normal, K, EPS, table, 0.01, 0.006, 0.5, backend="drjit", **kw)
    for x, y in ((a.specular, b.specular), (a.bragg, b.bragg), (a.weight, b.weight)):
        scale = np.abs(x).max(axis=1, keepdims=True) + 1e-300
        assert np.all(np.abs(x - y) / scale < 1e-8)
    assert np.all(np.isfinite(b.sigma()))


def test_drjit_needs_a_table():
    n_i, n_s, normal = _facets(10)
    with pytest.raises(ValueError, match="BraggSpectrumTable"):
        facet_terms(n_i, n_s, normal, K, EPS, lambda kx, ky: 0 * kx, 0.01, 0.01,
                    backend="drjit")


@pytest.mark.skipif(not _drjit_available(), reason="Dr.Jit LLVM backend unavailable")
@pytest.mark.parametrize("model", ["blend", "spm", "kirchhoff"])
def test_fused_speckled_amplitudes_equal_terms_then_speckle(table, model):
    # Eq P4 evaluated inside the Dr.Jit kernel (simulation's per-pulse path) against the
    # numpy path facet_terms + speckle_amplitudes with the same draws: the same numbers
    # up to rounding (1e-8 of each facet's largest amplitude, as the test above).
    from seaecho.scattering.facet import speckle_draws, speckled_facet_amplitudes

    n_i, n_s, normal = _facets()
    n = len(n_i)
    damp = np.linspace(0, 1, n)
    area = np.random.default_rng(5).uniform(0.0, 2.0, n)
    draws = speckle_draws(n, np.random.default_rng(9))
    args = (n_i, n_s, normal, area, K, EPS, table, 0.01, 0.006, 0.5)
    a = speckled_facet_amplitudes(*args, draws=draws, model=model, wake_damping=damp,
                                  backend="numpy")
    b = speckled_facet_amplitudes(*args, draws=draws, model=model, wake_damping=damp,
                                  backend="drjit")
    scale = np.abs(a).max(axis=1, keepdims=True) + 1e-300
    assert np.all(np.abs(a - b) / scale < 1e-8)
    assert np.abs(a).max() > 0
    with pytest.raises(ValueError, match="draws of shape"):
        speckled_facet_amplitudes(*args, draws=(draws[0][1:], draws[1][1:]), backend="drjit")
