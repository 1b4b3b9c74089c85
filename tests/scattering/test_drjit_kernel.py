"""Parity: the scattering formulas run by numpy and by Dr.Jit (the same functions).

Each formula is one function over an array namespace (``seaecho.backend``); the fused
Dr.Jit kernel of :func:`facet_terms` / :func:`speckled_facet_amplitudes` and the numpy
path evaluate the same code, so these tests check the two array back ends (float64
rounding, Dr.Jit's own transcendental functions, its complex square root), degenerate
geometries included. Physics against the literature is in test_facet.py (both back
ends), test_fresnel.py, test_kirchhoff.py, test_spm.py and test_blend_twoscale.py.
"""

import numpy as np
import pytest

from seaecho import backend as _backend
from seaecho.backend import NUMPY, Boundary
from seaecho.geometry import frames
from seaecho.ocean.spectra import DirectionalSpectrum
from seaecho.scattering import blend, fresnel, kirchhoff, spm
from seaecho.scattering.facet import FacetModel, _drjit_available, facet_terms
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
    # facet normal along the ray, q = 0 (forward through a facet).
    n_i[:6] = [[0, 0, -1], [0.6, 0, -0.8], [1, 0, 0], [0.6, 0, -0.8], -normal[4], [0.6, 0, -0.8]]
    n_s[:6] = [[0, 0, 1], [0.6, 0, 0.8], [1, 0, 0], [-0.6, 0, 0.8], normal[4], [0.6, 0, -0.8]]
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
    sea = FacetModel(K, EPS, table, 0.01, 0.006, 0.5, model=model,
                     cox_munk=cox_munk_parameters(6.0) if cm else None)
    a = facet_terms(n_i, n_s, normal, sea, backend="numpy", wake_damping=damp)
    b = facet_terms(n_i, n_s, normal, sea, backend="drjit", wake_damping=damp)
    for x, y in ((a.specular, b.specular), (a.bragg, b.bragg), (a.weight, b.weight)):
        scale = np.abs(x).max(axis=1, keepdims=True) + 1e-300
        assert np.all(np.abs(x - y) / scale < 1e-8)
    assert np.all(np.isfinite(b.sigma()))


def test_table_is_periodic_across_the_azimuth_seam(table):
    # psi = +pi and -pi are one azimuth (node 0 of eq T2): on the negative kx axis the
    # sign of a zero ky must not move the look-up one azimuth step (2 deg at n_psi = 180).
    spec = DirectionalSpectrum(u19_5=7.0, wind_direction=0.5)
    kmag = np.exp(table.log_k0 + table.dlog_k * np.array([10, 300, 700]))
    plus = table(-kmag, np.zeros(3))
    minus = table(-kmag, np.full(3, -0.0))
    np.testing.assert_array_equal(plus, minus)
    np.testing.assert_allclose(plus, spec.height_spectrum(-kmag, np.zeros(3)), rtol=1e-9)


def test_drjit_needs_a_table():
    n_i, n_s, normal = _facets(10)
    with pytest.raises(ValueError, match="BraggSpectrumTable"):
        facet_terms(n_i, n_s, normal, FacetModel(K, EPS, lambda kx, ky: 0 * kx, 0.01, 0.01),
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
    args = (n_i, n_s, normal, area, FacetModel(K, EPS, table, 0.01, 0.006, 0.5, model=model))
    a = speckled_facet_amplitudes(*args, draws=draws, wake_damping=damp, backend="numpy")
    b = speckled_facet_amplitudes(*args, draws=draws, wake_damping=damp, backend="drjit")
    scale = np.abs(a).max(axis=1, keepdims=True) + 1e-300
    assert np.all(np.abs(a - b) / scale < 1e-8)
    assert np.abs(a).max() > 0
    with pytest.raises(ValueError, match="draws of shape"):
        speckled_facet_amplitudes(*args, draws=(draws[0][1:], draws[1][1:]), backend="drjit")


# ----------------------------------------------------- formula by formula, two namespaces
def _both(fn, *arrays, n=None):
    """fn(xp, *inputs) with numpy and with Dr.Jit; inputs: (N, 3) vectors or (N,) reals."""
    out = []
    for xp in (NUMPY, _backend.drjit_namespace()):
        io = Boundary(xp, n or arrays[0].shape[0])
        args = [io.vec3(a) if np.ndim(a) == 2 else (io.complex(a) if np.iscomplexobj(a)
                                                      else io.array(a)) for a in arrays]
        res = fn(xp, *args)
        res = res if isinstance(res, tuple) else (res,)
        out.append(io.numpy(*res))
    return out


def _close(ref, got, rtol, what):
    for r, g in zip(ref, got, strict=True):
        assert np.all(np.isfinite(g)), what
        scale = np.max(np.abs(r)) + 1e-300
        np.testing.assert_allclose(g, r, rtol=rtol, atol=rtol * scale, err_msg=what)


needs_drjit = pytest.mark.skipif(not _drjit_available(), reason="Dr.Jit LLVM backend unavailable")


@needs_drjit
@pytest.mark.parametrize("eps", [EPS, 2.25 + 0j, 1e6 - 1e6j])
def test_fresnel_formula_agrees(eps):
    # cos in [0, 1] with normal incidence (1) and grazing (0) and out-of-range values
    c = np.concatenate([[0.0, 1.0, -0.2, 1.3], np.linspace(0, 1, 200)])
    ref, got = _both(lambda xp, c: fresnel.reflection(xp, c, xp.cconst(eps)), c)
    _close(ref, got, 1e-13, "R_h, R_v")


@needs_drjit
def test_spm_alpha_formula_agrees():
    rng = np.random.default_rng(1)
    ti, ts, ph = rng.uniform(0, 1.55, 300), rng.uniform(0, 1.55, 300), rng.uniform(-3.2, 3.2, 300)
    ti[:3], ts[:3], ph[:3] = [0.0, 0.0, 1.5707963], [0.0, 1.0, 1.5707963], [0.0, np.pi, 0.0]
    args = [np.cos(ti), np.sin(ti), np.cos(ts), np.sin(ts), np.cos(ph), np.sin(ph)]
    ref, got = _both(lambda xp, *a: spm.alpha(xp, *a, xp.cconst(EPS)), *args)
    _close(ref, got, 1e-13, "alpha")


@needs_drjit
@pytest.mark.parametrize("cm", [None, cox_munk_parameters(9.0)])
def test_specular_weight_formula_agrees(cm):
    # eq K1 with the Gaussian (K3) or Cox-Munk Gram-Charlier (K4) density, including the
    # specular normal along the plane (q_N = 0) and beyond it (gc = 0)
    n_i, n_s, normal = _facets(600)
    n_sp_fn = kirchhoff.specular_direction

    def fn(xp, a, b, nn):
        n_sp = n_sp_fn(xp, a, b, nn)
        e_u, e_c = kirchhoff.wind_axes(xp, nn, xp.const(np.cos(0.4)), xp.const(np.sin(0.4)))
        return kirchhoff.specular_weight(xp, n_sp, nn, e_u, e_c, xp.const(0.01),
                                         xp.const(0.006), cm)

    ref, got = _both(fn, n_i, n_s, normal)
    # log_w: absolute 1e-9 (values up to 700); gc relative
    np.testing.assert_allclose(got[0], ref[0], rtol=0, atol=1e-9)
    _close(ref[1:], got[1:], 1e-12, "gc")


@needs_drjit
def test_specular_matrix_formula_agrees():
    n_i, n_s, normal = _facets(600)

    def fn(xp, a, b, nn):
        z = xp.vec(0.0, 0.0, 1.0)
        n_sp = kirchhoff.specular_direction(xp, a, b, nn)
        return kirchhoff.specular_matrix(xp, a, b, n_sp, xp.cconst(EPS),
                                         frames.fsa_basis(xp, a, z), frames.fsa_basis(xp, b, z))

    ref, got = _both(fn, n_i, n_s, normal)
    _close(ref, got, 1e-12, "F")


@needs_drjit
def test_blend_weights_formula_agrees():
    beta = np.concatenate([[0.0, 6 * np.pi, 20 * np.pi, 90.0, 180.0], np.linspace(0, 180, 500)])
    ref, got = _both(lambda xp, b: blend.blend_weights(b, xp=xp), beta)
    _close(ref, got, 1e-13, "w1, w2")


@needs_drjit
def test_table_lookup_agrees_including_edges(table):
    # inside, on both range ends, outside (0), on the azimuth seam (psi = +-pi) and at K = 0
    rng = np.random.default_rng(3)
    kmag = np.concatenate([[0.0, table.k_min, table.k_max, 0.5 * table.k_min, 2 * table.k_max,
                            K, K], np.exp(rng.uniform(np.log(K / 3), np.log(20 * K), 400))])
    psi = np.concatenate([[0.0, 0.3, -1.0, 2.0, 1.0, np.pi, -np.pi], rng.uniform(-np.pi, np.pi,
                                                                                400)])
    kx, ky = kmag * np.cos(psi), kmag * np.sin(psi)
    ref, got = _both(lambda xp, a, b: table.lookup(xp, a, b), kx, ky)
    _close(ref, got, 1e-12, "W")
    assert ref[0][3] == 0.0 and ref[0][4] == 0.0


@pytest.mark.skipif(not _drjit_available(), reason="Dr.Jit LLVM backend unavailable")
@pytest.mark.parametrize("model", ["blend", "spm", "kirchhoff"])
@pytest.mark.parametrize("cm", [False, True])
def test_single_precision_kernel_against_the_float64_numpy_path(table, model, cm):
    # The simulation's kernels evaluate eqs P1-P7 in float32 (facet.PRECISION); numpy in
    # float64. With every mechanism (unresolved tilts, breaking, damping) on the
    # geometries of _facets (grazing up to 86 deg, nadir, Tx = Rx, forward specular) and
    # exact monostatic specular facets (their specular normal is -n_i: an exactly
    # degenerate basis that float32 rounding must not turn into a random one), each
    # facet's amplitudes agree within 5e-5 of its largest (1.5e-5 measured; a float64
    # constant promoting a stage, an overflow of exp in float32 or a lost degenerate
    # case would exceed it), and the channels' power within 1e-4 dB.
    from seaecho.scattering.facet import MECHANISMS, TiltQuadrature, speckled_facet_amplitudes

    n_i, n_s, normal = _facets()
    n_i[6:10] = [[0.6, 0.0, -0.8], [0.0, 0.7, -0.71414284], [0.3, 0.3, -0.9055385],
                 [-0.5, 0.1, -0.8602325]]
    n_s[6:10] = -n_i[6:10]
    normal[6:10] = n_s[6:10]
    n = len(n_i)
    rng = np.random.default_rng(11)
    draws = {m: (rng.normal(size=n) + 1j * rng.normal(size=n)) * np.sqrt(0.5)
             for m in MECHANISMS}
    kw = dict(wake_damping=np.linspace(0, 1, n), breaking_fraction=np.linspace(0.0, 0.1, n),
              draws=draws)
    sea = FacetModel(K, EPS, table, 0.01, 0.006, 0.5, model=model,
                     cox_munk=cox_munk_parameters(6.0) if cm else None,
                     tilt=TiltQuadrature.unscented(0.01, 0.006), breaking_tilt=0.05)
    args = (n_i, n_s, normal, rng.uniform(0.0, 2.0, n), sea)
    a = speckled_facet_amplitudes(*args, backend="numpy", **kw)
    b = speckled_facet_amplitudes(*args, backend="drjit", precision="single", **kw)
    assert b.dtype == np.complex128 and np.all(np.isfinite(b))
    assert np.all(b == b.astype(np.complex64))  # float32 values
    scale = np.abs(a).max(axis=1, keepdims=True) + 1e-300
    assert np.all(np.abs(a - b) / scale < 5e-5)
    assert np.abs(a[6:10]).max() > 0.1 * np.abs(a).max()  # the specular facets echo
    p_a, p_b = (np.sum(np.abs(x) ** 2, axis=0) for x in (a, b))
    live = p_a > 0
    assert np.all(np.abs(10 * np.log10(p_b[live] / p_a[live])) < 1e-4)


@pytest.mark.skipif(not _drjit_available(), reason="Dr.Jit LLVM backend unavailable")
def test_single_precision_stays_finite_at_the_extremes(table):
    # float32 ends at 3.4e38 and 1.2e-38: the Kirchhoff weight of a specular facet with
    # the 1e-12 floor of the slope variances (pi / (2 pi 1e-12) ~ 5e11), the Cox-Munk
    # factor's fourth powers of slopes near grazing (q_N -> 0: slopes up to 1e12) and
    # exp(log W) of an empty table entry stay finite, and near the float64 values (to
    # 1e-2: at slope variances of 1e-12 the Gaussian exp(-Z^2 / 2e-12) turns the float32
    # rounding of the slopes, ~1e-7, into 0.1 %; at the sea's, 1e-3 and up, into 1e-11).
    from seaecho.scattering.facet import speckled_facet_amplitudes

    n_i = np.array([[0.6, 0.0, -0.8], [0.6, 0.0, -0.8], [1.0, 0.0, -1e-7]])
    n_s = np.array([[-0.6, 0.0, 0.8], [0.6, 0.0, 0.8], [1.0, 0.0, 1e-7]])
    normal = np.array([[-0.6, 0.0, 0.8], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0]])
    draws = (np.ones(3, complex), np.ones(3, complex))
    for cm in (None, cox_munk_parameters(6.0)):
        args = (n_i, n_s, normal, np.ones(3),
                FacetModel(K, EPS, table, 0.0, 0.0, 0.5, cox_munk=cm))
        a = speckled_facet_amplitudes(*args, draws=draws, backend="numpy")
        b = speckled_facet_amplitudes(*args, draws=draws, backend="drjit", precision="single")
        assert np.all(np.isfinite(b))
        np.testing.assert_allclose(b, a, rtol=1e-2, atol=1e-2 * np.abs(a).max())
        assert np.abs(a).max() > (1e5 if cm is None else 1.0)


@pytest.mark.parametrize("precision", ["single", pytest.param("double",
                                                               marks=pytest.mark.slow)])
def test_monostatic_receive_side_from_the_transmit_side_to_the_bit(table, precision):
    """``mechanisms(..., monostatic=True)`` takes the receive side's FSA bases, rotations
    and local cosines from the transmit side's (``frames.reversed_fsa_basis``,
    ``frames.reversed_basis_change``): negation is exact and round-to-nearest symmetric,
    so every mechanism matrix and weight must equal the general path's bit for bit, on
    the geometries of _facets made monostatic (nadir: the global basis degenerate; a
    facet normal along the ray: the local one degenerate; both), with the unresolved
    tilts and breaking zones, in numpy and in Dr.Jit (float32 and float64)."""
    from seaecho.scattering.facet import TiltQuadrature, kernel_sea, mechanisms

    n_i, _, normal = _facets()
    n_i[4:8] = [[0.0, 0.0, -1.0], [0.0, 0.0, -1.0], [0.6, 0.0, -0.8], [0.3, -0.4, -0.8660254]]
    normal[5:8] = -n_i[5:8]  # facets facing the ray: local bases degenerate
    normal[4] = [0.1, 0.0, 0.99498744]
    n_s = -n_i
    sea = FacetModel(K, EPS, table, 0.01, 0.006, 0.5, model="blend",
                     tilt=TiltQuadrature.unscented(0.01, 0.006), breaking_tilt=0.05)
    spaces = [NUMPY] + ([_backend.drjit_namespace()] if _drjit_available() else [])
    for xp in spaces:
        xs = xp.with_precision(precision)
        io = Boundary(xp, len(n_i))
        vi, vs, vn = (xs.cast(io.vec3(a)) for a in (n_i, n_s, normal))
        ks = kernel_sea(io, sea, xs)
        brk = xs.cast(io.array(np.linspace(0.0, 0.1, len(n_i))))
        out = []
        for m in (False, True):
            mech = mechanisms(xs, vi, vs, vn, ks, breaking=brk, monostatic=m)
            names = [f"{k} {j}" for k in mech for j in range(8)]
            entries = [e for pair in mech.values() for mat in pair for e in mat.flat()]
            out.append(dict(zip(names, io.numpy(*(xs.cast(e) if not isinstance(
                e, int | float) else xs.cast(io.array(np.full(len(n_i), float(e))))
                for e in entries)), strict=True)))
        assert out[0].keys() == out[1].keys()
        for name, x in out[0].items():
            np.testing.assert_array_equal(out[1][name], x, err_msg=f"{xp.name}: {name}")
