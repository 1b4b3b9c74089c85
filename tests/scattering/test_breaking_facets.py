"""Breaking zones as the third per-facet mechanism (eq P7) and their placement.

KHCC03 is Kudryavtsev, Hauser, Caudal & Chapron (2003), J. Geophys. Res. 108(C3), 8054.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest
from scipy import special

from seaecho.constants import C0, G
from seaecho.geometry import frames
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.ocean.surface import SeaSurface
from seaecho.scattering.breaking import (
    THETA_WB,
    add_breaking,
    breaking_placement,
    breaking_sigma,
    breaking_statistics,
)
from seaecho.scattering.facet import (
    FacetModel,
    TiltQuadrature,
    facet_sigma,
    facet_terms,
    speckle_amplitudes,
    speckled_facet_amplitudes,
)
from seaecho.scattering.spectrum_table import BraggSpectrumTable
from seaecho.sea import surface_kinematics, vertical_acceleration

K = 2 * np.pi * 10e9 / C0
EPS = 55.9 - 37.0j


def _table():
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=8.0)
    return BraggSpectrumTable(spec.height_spectrum, k_min=10.0, k_max=20 * K, n_k=256,
                              n_psi=90)


def _geometry(n, seed=0):
    rng = np.random.default_rng(seed)
    th = rng.uniform(0.3, 1.45, n)
    ph = rng.uniform(-np.pi, np.pi, n)
    n_i, n_s = frames.directions_from_angles(th, ph, th, ph + np.pi)
    z = rng.normal(scale=0.15, size=(n, 2))
    normal = np.concatenate([-z, np.ones((n, 1))], axis=1)
    return n_i, n_s, normal / np.linalg.norm(normal, axis=1, keepdims=True)


def test_placement_covers_the_fraction_q_on_the_largest_downward_acceleration():
    rng = np.random.default_rng(1)
    b = rng.normal(size=50_000)
    area = rng.uniform(0.5, 1.5, b.size)
    for q in (0.0, 3e-3, 0.013, 0.2, 1.0):
        f = breaking_placement(b, area, q)
        assert np.all((f >= 0) & (f <= 1))
        assert (area * f).sum() == pytest.approx(q * area.sum(), rel=1e-12, abs=1e-9)
        if 0 < q < 1:
            assert b[f == 1].min() >= b[f == 0].max()  # a threshold on the index
    with pytest.raises(ValueError, match="q = "):
        breaking_placement(b, area, 1.5)


def test_placement_threshold_is_srokosz_gaussian_quantile():
    # On a linear (Gaussian) sea the downward acceleration is Gaussian with variance
    # m4 = sum omega^4 Psi dK (deep water); the probability that it exceeds gamma g is
    # 1/2 erfc(gamma g / sqrt(2 m4)) (Srokosz 1986, J. Phys. Oceanogr. 16, 382-385).
    # Placing the fraction q therefore puts the threshold at gamma g =
    # sqrt(2 m4) erfcinv(2 q): within 2 % with the realisation's own variance of a_z,
    # within 8 % with the spectrum's m4 (the realisation's variance is 10 % below it).
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=10.0)
    surf = SeaSurface(spec, (64.0, 64.0), (256, 256), np.random.default_rng(4))
    acc = surface_kinematics(surf, 0.0).acceleration[..., 2].ravel()
    q = breaking_statistics(10.0, K).q
    f = breaking_placement(-acc, np.ones(acc.size), q)
    threshold = (-acc)[f == 1].min()
    kx = 2 * np.pi * np.fft.fftfreq(256, 0.25)
    kk = np.hypot(kx[None, :], kx[:, None])
    psi = spec(kx[None, :] + 0 * kk, kx[:, None] + 0 * kk)
    psi[0, 0] = psi[128, :] = psi[:, 128] = 0.0
    m4 = np.sum((G * kk) ** 2 * psi) * (2 * np.pi / 64.0) ** 2  # omega^4 = (g K)^2
    assert 0.002 < q < 0.05
    sample = np.sqrt(2 * acc.var()) * special.erfcinv(2 * q)
    assert threshold == pytest.approx(sample, rel=0.02)
    assert threshold == pytest.approx(np.sqrt(2 * m4) * special.erfcinv(2 * q), rel=0.08)
    assert 0.1 < threshold / G < 0.6  # the order of the Phillips / Longuet-Higgins gamma


def test_vertical_acceleration_is_the_kinematics_one_bit_for_bit():
    # Parity: the one-FFT a_z that places the breaking zones equals the full kinematics'
    # (whose threshold the Srokosz test above validates), at two times.
    spec = DirectionalSpectrum(spectrum="elfouhaily", u19_5=10.0)
    surf = SeaSurface(spec, (32.0, 32.0), (64, 64), np.random.default_rng(6))
    for t in (0.0, 3.7):
        a = surface_kinematics(surf, t).acceleration[..., 2]
        assert vertical_acceleration(surf, t).tobytes() == a.tobytes()


@pytest.mark.parametrize("backend", ["numpy", "drjit"])
def test_facet_breaking_is_eq_br1_with_its_own_weight(backend):
    # Eq P7: a facet covered by the fraction q of breaking zones scatters
    # (1 - q) sigma_regular + q sigma_wb (KHCC03 eq 1, BR1), with sigma_wb the zones'
    # BR5-BR6 on the facet's plane.
    n_i, n_s, normal = _geometry(400)
    q = np.random.default_rng(2).uniform(0, 1, 400)
    sea = FacetModel(K, EPS, _table(), 0.01, 0.007, 0.4)
    reg = facet_sigma(n_i, n_s, normal, sea, backend=backend)
    wb = breaking_sigma(n_i, n_s, normal, 0.4, 0.6, THETA_WB)
    got = facet_sigma(n_i, n_s, normal, sea.with_(breaking_tilt=THETA_WB * 0.6),
                      breaking_fraction=q, backend=backend)
    np.testing.assert_allclose(got, add_breaking(reg, wb, q), rtol=1e-9, atol=1e-300)


def test_breaking_and_tilt_nodes_same_on_both_backends_and_fused():
    n_i, n_s, normal = _geometry(300, seed=5)
    q = np.random.default_rng(3).uniform(0, 0.3, 300)
    tq = TiltQuadrature.unscented(0.01, 0.007)
    sea = FacetModel(K, EPS, _table(), 0.01, 0.007, 0.4, tilt=tq, breaking_tilt=0.03)
    kw = dict(breaking_fraction=q)
    a, b = (facet_terms(n_i, n_s, normal, sea, **kw, backend=be) for be in ("numpy", "drjit"))
    for x, y in zip(a.mechanisms().values(), b.mechanisms().values(), strict=True):
        np.testing.assert_allclose(x[0], y[0], rtol=1e-8, atol=1e-12)
        np.testing.assert_allclose(x[1], y[1], rtol=1e-12, atol=1e-250)
    assert len(a.mechanisms()) == 7  # specular, bragg, bragg1..4, breaking
    area = np.random.default_rng(4).uniform(0.5, 2.0, 300)
    rng = np.random.default_rng(7)
    draws = {m: (rng.normal(size=300) + 1j * rng.normal(size=300)) / np.sqrt(2)
             for m in a.mechanisms()}
    ref = speckle_amplitudes(a, area, draws=draws)
    for be in ("numpy", "drjit"):
        got = speckled_facet_amplitudes(n_i, n_s, normal, area, sea, draws=draws,
                                        backend=be, **kw)
        np.testing.assert_allclose(got, ref, rtol=1e-8, atol=1e-12)
    with pytest.raises(ValueError, match="none given"):
        speckled_facet_amplitudes(n_i, n_s, normal, area, sea,
                                  draws=(draws["specular"], draws["bragg"]), **kw)


def test_speckle_covariance_includes_the_breaking_mechanism():
    # Eq P5 with three mechanisms: the sample covariance of 200 000 speckled facets of
    # identical terms equals sum_j w_j M_j M_j^H (its own independent draw per
    # mechanism), within 3 % of the largest entry.
    n_i, n_s, normal = _geometry(1)
    t = facet_terms(n_i, n_s, normal, FacetModel(K, EPS, _table(), 0.01, 0.007, 0.4),
                    breaking_fraction=0.3, backend="numpy")
    n = 200_000
    rep = type(t)(specular=np.repeat(t.specular, n, 0), bragg=np.repeat(t.bragg, n, 0),
                  weight=np.repeat(t.weight, n, 0), breaking=np.repeat(t.breaking, n, 0),
                  breaking_fraction=np.full(n, 0.3))
    a = speckle_amplitudes(rep, np.ones(n), np.random.default_rng(0))
    cov = a.T @ a.conj() / n
    ref = t.covariance()[0]
    assert np.abs(cov - ref).max() < 0.03 * np.abs(ref).max()
    np.testing.assert_allclose(np.diag(ref).real, t.sigma()[0], rtol=1e-12)


def test_facet_breaking_is_khcc03_eq1_combination_of_the_facet_terms():
    # KHCC03 eq 1 on each facet: sigma = (1 - q) sigma_regular + q sigma_wb, sigma_wb
    # the facet covered by breaking zones (q = 1) and sigma_regular the paper's blend
    # (q = 0). Keeping the regular mechanisms at full weight on the breaking zones'
    # area (a dropped 1 - q), or a wrong weight of the breaking term, fails.
    n_i, n_s, normal = _geometry(200, seed=8)
    sea = FacetModel(K, EPS, _table(), 0.01, 0.007, 0.4,
                     tilt=TiltQuadrature.unscented(0.01, 0.007), breaking_tilt=0.03)
    q = np.random.default_rng(9).uniform(0.0, 0.4, 200)
    regular, wb, mixed = (facet_terms(n_i, n_s, normal, sea, breaking_fraction=f,
                                      backend="numpy").sigma() for f in (0.0, 1.0, q))
    np.testing.assert_allclose(mixed, (1 - q)[:, None] * regular + q[:, None] * wb,
                               rtol=1e-12, atol=1e-300)
    assert np.any(wb[:, 0] > 0) and np.any(regular[:, 3] > 0)  # not a vacuous 0 = 0


def test_tilt_average_without_unresolved_slopes_is_the_papers_facet_term():
    # Eq P6's limiting case: with no unresolved slopes (s_u = s_c = 0) every node is the
    # facet itself and the average is the paper's Bragg term of the facet's plane (eq P2,
    # the paper's eqs 8-9): the weights of the five-point rule sum to 1 (Julier &
    # Uhlmann 2004). A centre weight of 1 (or any weights not summing to 1) fails.
    n_i, n_s, normal = _geometry(200, seed=10)
    sea = FacetModel(K, EPS, _table(), 0.01, 0.007, 0.4)
    plain = facet_terms(n_i, n_s, normal, sea, backend="numpy").sigma()
    flat = facet_terms(n_i, n_s, normal, sea.with_(tilt=TiltQuadrature.unscented(0.0, 0.0)),
                       backend="numpy").sigma()
    np.testing.assert_allclose(flat, plain, rtol=1e-12, atol=1e-300)
    assert sum(TiltQuadrature.unscented(0.0, 0.0).weights) == pytest.approx(1.0, abs=1e-15)
