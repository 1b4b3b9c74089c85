"""Per-facet sigma and speckled amplitudes (seaecho.scattering.facet).

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scattering_helpers import gaussian_spectrum

from seaecho.geometry import frames
from seaecho.scattering.blend import blend
from seaecho.scattering.facet import (
    FacetModel,
    FacetTerms,
    _drjit_available,
    bragg_vectors,
    facet_amplitudes,
    facet_sigma,
    facet_terms,
    hhvv_coherence,
    speckle_amplitudes,
    speckle_draws,
    speckled_facet_amplitudes,
)
from seaecho.scattering.kirchhoff import kirchhoff_sigma
from seaecho.scattering.slopes import cox_munk_parameters
from seaecho.scattering.spectrum_table import BraggSpectrumTable
from seaecho.scattering.spm import spm_sigma
from seaecho.scattering.validity import SPMValidityWarning

EPS = 55.9 - 37.0j
K = 2 * np.pi * 10e9 / 299_792_458.0


def _geometry(n=7):
    ti = np.radians(np.linspace(5, 70, n))
    ts = np.radians(np.linspace(60, 10, n))
    ps = np.radians(np.linspace(0, 180, n))
    return ti, ts, ps


@pytest.mark.parametrize("model", ["spm", "kirchhoff", "blend"])
def test_flat_facets_equal_mean_plane_models(model):
    # Two code paths: facet.py (written-out rotations, its own specular matrix) and the
    # mean-plane functions of spm.py / kirchhoff.py / blend.py.
    ti, ts, ps = _geometry()
    n_i, n_s = frames.directions_from_angles(ti, 0.3, ts, ps + 0.3)
    normal = np.broadcast_to(frames.Z_HAT, n_i.shape)
    s = facet_sigma(n_i, n_s, normal,
                    FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01, 0.5, model=model))
    s_spm = spm_sigma(ti, 0.3, ts, ps + 0.3, K, EPS, gaussian_spectrum)
    s_k = kirchhoff_sigma(ti, 0.3, ts, ps + 0.3, EPS, 0.02, 0.01, 0.5, warn=False)
    beta = np.degrees(frames.beta_angle(n_i, n_s))
    ref = {"spm": s_spm, "kirchhoff": s_k, "blend": blend(s_spm, s_k, beta)}[model]
    np.testing.assert_allclose(s, ref, rtol=1e-9, atol=1e-12 * ref.max())


def test_precomputed_local_frames_give_same_result():
    rng = np.random.default_rng(3)
    n = 50
    normal = np.column_stack([rng.normal(0, 0.2, (n, 2)), np.ones(n)])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    n_i, n_s = frames.directions_from_angles(rng.uniform(0.1, 1.2, n), 0.0,
                                             rng.uniform(0.1, 1.2, n), rng.uniform(0, 6, n))
    th = frames.local_angles(n_i, n_s, normal)
    rot = frames.tilt_rotation(n_i, n_s, normal)
    local = dict(theta_i=th[0], theta_s=th[1], phi=th[2], rot_i=rot[0], rot_s=rot[1])
    sea = FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.01)
    a = facet_sigma(n_i, n_s, normal, sea)
    b = facet_sigma(n_i, n_s, normal, sea, local=local)
    np.testing.assert_allclose(a, b, rtol=1e-12)


def test_spectrum_values_at_bragg_vectors_equal_callable():
    ti, ts, ps = _geometry()
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ts, ps)
    normal = np.tile([0.1, 0.0, 1.0], (len(ti), 1)) / np.hypot(0.1, 1.0)
    kb = bragg_vectors(n_i, n_s, normal, K)
    values = gaussian_spectrum(kb[:, 0], kb[:, 1])
    a = facet_sigma(n_i, n_s, normal,
                    FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01, model="spm"))
    b = facet_sigma(n_i, n_s, normal, FacetModel(K, EPS, values, 0.02, 0.01, model="spm"))
    np.testing.assert_allclose(a, b, rtol=1e-12)


def test_wake_damping_removes_bragg_part():
    ti, ts, ps = _geometry()
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ts, ps)
    normal = np.broadcast_to(frames.Z_HAT, n_i.shape)
    t0 = facet_terms(n_i, n_s, normal, FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01))
    t1 = facet_terms(n_i, n_s, normal, FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01),
                     wake_damping=np.ones(len(ti)))
    t_half = facet_terms(n_i, n_s, normal, FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01),
                         wake_damping=np.full(len(ti), 0.5))
    np.testing.assert_allclose(t1.sigma(), t0.weight * np.abs(t0.specular) ** 2)
    np.testing.assert_allclose(np.abs(t_half.bragg) ** 2, 0.5 * np.abs(t0.bragg) ** 2)


def test_speckle_statistics_and_hhvv_coherence():
    # One bistatic geometry where both mechanisms matter (beta ~ 17 deg), 200 000 facets.
    n = 200_000
    n_i, n_s = frames.directions_from_angles(np.radians(20), 0.0, np.radians(30),
                                             np.radians(150))
    normal = np.array([0.05, 0.08, 1.0]) / np.linalg.norm([0.05, 0.08, 1.0])
    nn = np.broadcast_to(normal, (n, 3))
    terms = facet_terms(np.broadcast_to(n_i, (n, 3)), np.broadcast_to(n_s, (n, 3)), nn,
                        FacetModel(K, EPS, gaussian_spectrum, 0.004, 0.003))
    area = np.full(n, 2.0)
    a = speckle_amplitudes(terms, area, np.random.default_rng(20261122))
    sigma = terms.sigma()[0]
    inten = np.abs(a) ** 2
    mean = inten.mean(axis=0)
    # E|a|^2 = sigma A. Sample mean of an exponential over n draws: relative sd
    # 1/sqrt(n) = 0.22 %; 1 % is 4.5 sd.
    np.testing.assert_allclose(mean, sigma * 2.0, rtol=0.01)
    # Exponential intensity: variance = mean^2 (relative sd of the sample variance
    # sqrt(8/n) = 0.63 %; 3 % is 4.7 sd).
    np.testing.assert_allclose(inten.var(axis=0) / mean**2, 1.0, rtol=0.03)
    # HH-VV coherence from eq P5 vs its sample estimate (sd ~ (1 - |g|^2)/sqrt(n) < 0.003).
    gamma = hhvv_coherence(terms)[0]
    est = np.mean(a[:, 0] * a[:, 3].conj()) / np.sqrt(mean[0] * mean[3])
    assert abs(est - gamma) < 0.01
    # A single mechanism is fully coherent.
    spm = FacetModel(K, EPS, gaussian_spectrum, 0.004, 0.003, model="spm")
    assert np.allclose(np.abs(hhvv_coherence(facet_terms(n_i[None], n_s[None], normal[None],
                                                         spm))), 1.0)


def test_speckle_covariance_matches_eq_p5_for_mixed_mechanisms():
    # Two mechanisms with different polarimetric signatures and equal weight: the sample
    # 4x4 covariance of the amplitudes must match eq P5, including the partial HH-VV
    # coherence (0.5 (K_hh K_vv^* + B_hh B_vv^*) / ...) and the cross-pol terms.
    n = 200_000
    spec = np.array([1.0, 0.1, 0.1, 0.8j])
    bragg = np.array([0.6, 0.2j, 0.2j, -1.0])
    terms = FacetTerms(specular=np.tile(spec, (n, 1)), bragg=np.tile(bragg, (n, 1)),
                       weight=np.full((n, 4), 0.5))
    a = speckle_amplitudes(terms, np.ones(n), np.random.default_rng(7))
    cov = a.T @ a.conj() / n
    ref = terms.covariance()[0]
    # Entries are means of products of Gaussians: sd <= |C_mm C_nn|^0.5 / sqrt(n) ~ 0.3 %
    # of the diagonal; 2 % of the largest entry is > 6 sd.
    np.testing.assert_allclose(cov, ref, atol=0.02 * np.abs(ref).max())
    gamma = hhvv_coherence(terms)[0]
    assert 0.2 < abs(gamma) < 0.8


def test_amplitudes_reproducible_and_calibrated_by_area():
    ti, ts, ps = _geometry()
    n_i, n_s = frames.directions_from_angles(ti, 0.0, ts, ps)
    normal = np.broadcast_to(frames.Z_HAT, n_i.shape)
    args = (n_i, n_s, normal, np.full(len(ti), 3.0),
            FacetModel(K, EPS, gaussian_spectrum, 0.02, 0.01))
    a1 = facet_amplitudes(*args, np.random.default_rng(5))
    a2 = facet_amplitudes(*args, np.random.default_rng(5))
    np.testing.assert_array_equal(a1, a2)
    assert a1.shape == (len(ti), 4) and a1.dtype == complex


def test_spm_validity_warning():
    n_i, n_s = frames.directions_from_angles(0.5, 0.0, 0.5, np.pi)
    with pytest.warns(SPMValidityWarning):
        facet_sigma(n_i[None], n_s[None], frames.Z_HAT[None],
                    FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.01),
                    small_scale_height_variance=1e-2)


unit = arrays(np.float64, (3,), elements=st.floats(-1, 1)).filter(
    lambda v: np.linalg.norm(v) > 1e-3)


@settings(max_examples=200, deadline=None)
@given(unit, unit, unit, st.sampled_from(["blend", "spm", "kirchhoff"]))
def test_no_nan_or_inf_for_any_geometry(a, b, c, model):
    # Random directions, plus the singular ones: backscatter (Tx = Rx), forward through
    # (n_s = n_i), nadir/zenith, facet normal along a ray, grazing.
    n_i = a / np.linalg.norm(a)
    n_s = b / np.linalg.norm(b)
    nn = c / np.linalg.norm(c)
    nn = nn if nn[2] > 0 else -nn
    zen = np.array([0.0, 0.0, 1.0])
    graz = np.array([1.0, 0.0, 0.0])
    cases_i = np.array([n_i, n_i, n_i, -zen, -zen, graz, -nn, n_i])
    cases_s = np.array([n_s, -n_i, n_i, zen, -zen, graz, nn, np.array([-1.0, 0, 0])])
    normals = np.array([nn, nn, nn, zen, zen, zen, nn, zen])
    with np.errstate(invalid="raise", divide="raise", over="raise"):
        s = facet_sigma(cases_i, cases_s, normals,
                        FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.005, 0.3, model=model))
    assert np.all(np.isfinite(s)) and np.all(s >= 0)


def test_accepts_the_geometry_stage_facets():
    # Integration with seaecho.geometry (analytic facets): its analytic facets carry the local
    # angles and basis rotations, which facet_sigma accepts as `local`.
    from seaecho.geometry.facets import analytic_facets

    x = np.linspace(-20, 20, 9)
    y = np.linspace(-20, 20, 9)
    xx, yy = np.meshgrid(x, y)
    z = 0.3 * np.sin(0.3 * xx + 0.1 * yy)
    zx = 0.09 * np.cos(0.3 * xx + 0.1 * yy)
    zy = 0.03 * np.cos(0.3 * xx + 0.1 * yy)
    fac = analytic_facets(x, y, z, zx, zy, None, np.array([-500.0, 100.0, 200.0]),
                          np.array([300.0, -400.0, 100.0]), shadowing="none")
    a = facet_sigma(fac.n_i, fac.n_s, fac.normal,
                    FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.005))
    b = facet_sigma(fac.n_i, fac.n_s, fac.normal,
                    FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.005), local=fac)
    np.testing.assert_allclose(a, b, rtol=1e-10, atol=1e-14 * a.max())
    amp = facet_amplitudes(fac.n_i, fac.n_s, fac.normal, fac.area,
                           FacetModel(K, EPS, gaussian_spectrum, 0.01, 0.005),
                           np.random.default_rng(1), local=fac)
    assert amp.shape == (fac.n_facets, 4)


def test_speckle_draws_reused_give_the_plain_eq_p4_bytes():
    # Precomputed draws (held sea: drawn once per sea state) give the same bytes as drawing
    # from the same generator, and both equal eq P4 written out plainly.
    rng = np.random.default_rng(3)
    n = 1000
    terms = FacetTerms(specular=rng.normal(size=(n, 4)) + 1j * rng.normal(size=(n, 4)),
                       bragg=rng.normal(size=(n, 4)) + 1j * rng.normal(size=(n, 4)),
                       weight=rng.uniform(size=(n, 4)))
    area = rng.uniform(0.1, 2.0, n)
    a = speckle_amplitudes(terms, area, np.random.default_rng(11))
    g_k, g_b = speckle_draws(n, np.random.default_rng(11))
    b = speckle_amplitudes(terms, area, draws=(g_k, g_b))
    assert a.tobytes() == b.tobytes()
    plain = np.sqrt(area)[:, None] * (np.sqrt(terms.weight) * terms.specular * g_k[:, None]
                                      + np.sqrt(1.0 - terms.weight) * terms.bragg
                                      * g_b[:, None])
    assert a.tobytes() == plain.tobytes()
    with pytest.raises(ValueError, match="draws of shape"):
        speckle_amplitudes(terms, area, draws=(g_k[:-1], g_b[:-1]))
    with pytest.raises(ValueError, match="rng or draws"):
        speckle_amplitudes(terms, area)


# ---------------------------------------------- closed forms through both array back ends
BACKENDS = ["numpy", pytest.param("drjit", marks=pytest.mark.skipif(
    not _drjit_available(), reason="Dr.Jit LLVM backend unavailable"))]


@pytest.fixture(scope="module")
def gaussian_table():
    return BraggSpectrumTable(gaussian_spectrum, K / 3, 20 * K, n_k=512, n_psi=180)


def _backscatter(theta, n=3):
    n_i = np.tile([np.sin(theta), 0.0, -np.cos(theta)], (n, 1))
    return n_i, -n_i, np.tile(frames.Z_HAT, (n, 1))


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("cm", [False, True])
def test_nadir_specular_is_barrick_closed_form(backend, cm, gaussian_table):
    # Nadir backscatter on a flat facet, Kirchhoff/GO (Barrick 1968; kirchhoff.py):
    # sigma = pi P(0, 0) |R(0)|^2 with P(0, 0) = 1 / (2 pi sigma_u sigma_c) (Cox & Munk
    # 1954 eq 1) times, for the Gram-Charlier density, its value at zero slope
    # 1 + c40 / 8 + c22 / 4 + c04 / 8 (eq 2 at xi = eta = 0), and the normal-incidence
    # Fresnel coefficient R(0) = (1 - sqrt eps) / (1 + sqrt eps) (Born & Wolf 1999) on
    # HH and VV, nothing on HV, VH.
    n_i, n_s, nn = _backscatter(0.0)
    p = cox_munk_parameters(7.0) if cm else None
    mu, mc = (p.mss_upwind, p.mss_crosswind) if cm else (0.02, 0.012)
    t = facet_terms(n_i, n_s, nn,
                    FacetModel(K, EPS, gaussian_table, mu, mc, 0.4, model="kirchhoff", cox_munk=p),
                    backend=backend)
    r0 = abs((1 - np.sqrt(EPS)) / (1 + np.sqrt(EPS))) ** 2
    peak = 1.0 + p.c40 / 8 + p.c22 / 4 + p.c04 / 8 if cm else 1.0
    expected = r0 / (2.0 * np.sqrt(mu * mc)) * peak
    sigma = t.sigma()
    np.testing.assert_allclose(sigma[:, [0, 3]], expected, rtol=1e-12)
    np.testing.assert_allclose(sigma[:, [1, 2]], 0.0, atol=1e-15 * expected)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("theta_deg", [8.0, 15.0, 25.0])
def test_upwind_backscatter_is_the_geometric_optics_closed_form(backend, theta_deg,
                                                                 gaussian_table):
    # Monostatic GO looking upwind (Barrick 1968; Valenzuela 1978):
    # sigma0 = |R(0)|^2 sec^4(theta) / (2 s_u s_c) exp(-tan^2(theta) / (2 s_u^2)),
    # the specular facets being tilted by theta towards the radar (local incidence 0).
    th = np.radians(theta_deg)
    n_i, n_s, nn = _backscatter(th)
    mu, mc = 0.02, 0.012
    t = facet_terms(n_i, n_s, nn,
                    FacetModel(K, EPS, gaussian_table, mu, mc, 0.0, model="kirchhoff"),
                    backend=backend)
    r0 = abs((1 - np.sqrt(EPS)) / (1 + np.sqrt(EPS))) ** 2
    expected = r0 / (2 * np.sqrt(mu * mc) * np.cos(th) ** 4) * np.exp(-np.tan(th) ** 2
                                                                    / (2 * mu))
    np.testing.assert_allclose(t.sigma()[:, [0, 3]], expected, rtol=1e-12)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("theta_deg", [25.0, 40.0, 60.0])
def test_bragg_backscatter_is_the_classic_small_perturbation_formula(backend, theta_deg,
                                                                      gaussian_table):
    # Flat-facet SPM backscatter: sigma0_pp = 16 pi k^4 cos^4(theta) |g_pp|^2 W(2k sin, 0)
    # for W normalised to the height variance (Valenzuela 1978; Plant 1990;
    # docs/scattering.md), g_hh = (eps - 1) / (cos + r)^2,
    # g_vv = (eps - 1) (eps (1 + sin^2) - sin^2) / (eps cos + r)^2, r = sqrt(eps - sin^2);
    # no cross-polarisation. W is the table's value at the Bragg vector (the table's own
    # accuracy is tested in test_drjit_kernel.py).
    th = np.radians(theta_deg)
    n_i, n_s, nn = _backscatter(th)
    t = facet_terms(n_i, n_s, nn, FacetModel(K, EPS, gaussian_table, 0.01, 0.01, model="spm"),
                    backend=backend)
    c, s2 = np.cos(th), np.sin(th) ** 2
    r = np.sqrt(EPS - s2)
    w = gaussian_table(np.array([-2 * K * np.sin(th)]), np.array([0.0]))[0]
    g_hh = (EPS - 1) / (c + r) ** 2
    g_vv = (EPS - 1) * (EPS * (1 + s2) - s2) / (EPS * c + r) ** 2
    pref = 16 * np.pi * K**4 * c**4 * w
    sigma = t.sigma()
    np.testing.assert_allclose(sigma[:, 0], pref * abs(g_hh) ** 2, rtol=1e-12)
    np.testing.assert_allclose(sigma[:, 3], pref * abs(g_vv) ** 2, rtol=1e-12)
    np.testing.assert_allclose(sigma[:, [1, 2]], 0.0, atol=1e-15 * sigma[0, 3])


@pytest.mark.parametrize("backend", BACKENDS)
def test_blend_weights_at_the_papers_angles(backend, gaussian_table):
    # Paper eqs 10-11 (beta in degrees): at backscatter on a flat facet beta is the
    # incidence angle; w1 = 0.1 at beta = 6 pi deg on HH, VV and w2 = 0.1 at 20 pi deg
    # on HV, VH; and the speckled amplitudes are eq P4 with those weights.
    for beta, channels in ((6 * np.pi, [0, 3]), (20 * np.pi, [1, 2])):
        n_i, n_s, nn = _backscatter(np.radians(beta))
        t = facet_terms(n_i, n_s, nn, FacetModel(K, EPS, gaussian_table, 0.01, 0.01),
                        backend=backend)
        np.testing.assert_allclose(t.weight[:, channels], 0.1, rtol=1e-12)
        draws = speckle_draws(3, np.random.default_rng(4))
        a = speckled_facet_amplitudes(n_i, n_s, nn, np.full(3, 2.0),
                                      FacetModel(K, EPS, gaussian_table, 0.01, 0.01), draws=draws,
                                      backend=backend)
        np.testing.assert_allclose(a, speckle_amplitudes(t, np.full(3, 2.0), draws=draws),
                                   rtol=1e-12, atol=1e-14 * np.abs(a).max())
