"""Array namespaces (seaecho.backend): algebra, complex branch, variant choice, fusion.

The CUDA back end cannot run on a machine without a GPU: its selection logic is tested
here with the device query replaced (the namespace is built, no array is created).
"""

from __future__ import annotations

import sys
import types
from pathlib import Path

import numpy as np
import pytest

from seaecho import backend
from seaecho.backend import NUMPY, Boundary, Mat2, Vec3

needs_drjit = pytest.mark.skipif(not backend.drjit_available(),
                                 reason="Dr.Jit LLVM backend unavailable")


def _rng_mat(rng, shape=(7,)):
    return rng.normal(size=shape + (2, 2)) + 1j * rng.normal(size=shape + (2, 2))


def test_mat2_products_equal_numpy_matmul():
    rng = np.random.default_rng(0)
    a, s, b = _rng_mat(rng), _rng_mat(rng), _rng_mat(rng)

    def m(x):
        return Mat2(x[:, 0, 0], x[:, 0, 1], x[:, 1, 0], x[:, 1, 1])

    out = m(a).T @ m(s) @ m(b)
    ref = np.swapaxes(a, -1, -2) @ s @ b
    np.testing.assert_allclose(np.stack(out.flat(), -1).reshape(-1, 2, 2), ref, rtol=1e-13)
    # structural zeros of diag() give the same numbers as an explicit zero matrix
    d = Mat2.diag(s[:, 0, 0], s[:, 1, 1])
    full = np.zeros_like(s)
    full[:, 0, 0], full[:, 1, 1] = s[:, 0, 0], s[:, 1, 1]
    out = m(a).T @ d @ m(b)
    np.testing.assert_allclose(np.stack(out.flat(), -1).reshape(-1, 2, 2),
                               np.swapaxes(a, -1, -2) @ full @ b, rtol=1e-13)
    assert (Mat2.diag(1.0, 2.0) @ Mat2.diag(3.0, 4.0)).hv == 0  # stays structural


def test_vec3_defers_to_its_operators_under_numpy():
    s = np.array([1.0, 2.0])
    v = Vec3(np.array([1.0, 1.0]), np.array([0.0, 1.0]), 2.0)
    for w in (s * v, v * s):  # ndarray * Vec3 must not become an object array
        assert isinstance(w, Vec3)
        np.testing.assert_array_equal(w.z, [2.0, 4.0])
    np.testing.assert_array_equal(NUMPY.cross(Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)).z, 1.0)


def test_boundary_broadcasts_constants_and_stacks_vectors():
    io = Boundary(NUMPY, 4)
    v = io.vec3(np.arange(12.0).reshape(4, 3))
    w, m, c = io.numpy(v * 2.0, Mat2(1.0, 0, 0, 1.0), 3.0)
    np.testing.assert_array_equal(w, 2.0 * np.arange(12.0).reshape(4, 3))
    assert m.shape == (4, 2, 2) and np.all(m == np.eye(2))
    np.testing.assert_array_equal(c, np.full(4, 3.0))
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        io.vec3(np.zeros((4, 2)))


@needs_drjit
def test_complex_square_root_branch_is_numpys():
    # The principal branch with the sign of a signed zero (Fresnel's decaying root):
    # both namespaces must agree, including on the negative real axis. (Dr.Jit squares
    # |z|: it loses the result below |z| ~ 1e-150, far from eps_r - sin^2 ~ 1-100.)
    z = np.array([-4 + 0j, complex(-4.0, -0.0), 3 - 4j, -3 + 4j, 56 - 37j, 1e-20 + 0j])
    xp = backend.drjit_namespace()
    io = Boundary(xp, z.size)
    (got,) = io.numpy(xp.sqrt(io.complex(z)))
    np.testing.assert_allclose(got, np.sqrt(z), rtol=1e-15, atol=0)
    assert np.array_equal(np.signbit(got.imag), np.signbit(np.sqrt(z).imag))


def test_unknown_variant_is_refused():
    with pytest.raises(ValueError, match="allowed"):
        backend.check_variant("scalar_rgb")


def test_cuda_without_gpu_is_a_clear_error(monkeypatch):
    monkeypatch.setattr(backend, "cuda_available", lambda: False)
    with pytest.raises(ValueError, match="no CUDA GPU"):
        backend.drjit_namespace("cuda_ad_mono_polarized")


@needs_drjit
def test_cuda_variant_selects_drjit_cuda(monkeypatch):
    # With a (pretended) device the CUDA variant builds a namespace on drjit.cuda: no
    # array is created, so this runs without a GPU.
    monkeypatch.setattr(backend, "cuda_available", lambda: True)
    monkeypatch.setitem(sys.modules, "mitsuba", types.SimpleNamespace(variant=lambda: None))
    try:
        xp = backend.drjit_namespace("cuda_ad_mono_polarized")
        assert xp.name == "cuda" and xp.Float.__module__ == "drjit.cuda"
        assert backend.drjit_namespace(None).name == "llvm"  # default: the CPU
        assert backend.namespace("drjit", "llvm_ad_mono_polarized").Float.__module__ == (
            "drjit.llvm")
    finally:
        backend._drjit_namespace.cache_clear()


@needs_drjit
def test_variant_mismatch_with_running_mitsuba_is_refused(monkeypatch):
    monkeypatch.setattr(backend, "cuda_available", lambda: True)
    fake = types.SimpleNamespace(variant=lambda: "cuda_ad_mono_polarized")
    monkeypatch.setitem(sys.modules, "mitsuba", fake)
    try:
        with pytest.raises(ValueError, match="Mitsuba already runs"):
            backend.drjit_namespace("llvm_ad_mono_polarized")
        # no variant given: the kernels follow the variant Mitsuba runs
        assert backend.check_variant(None) == "cuda_ad_mono_polarized"
        fake.variant = lambda: "llvm_ad_mono_polarized"
        with pytest.raises(ValueError, match="Mitsuba already runs"):
            backend.drjit_namespace("cuda_ad_mono_polarized")
    finally:
        backend._drjit_namespace.cache_clear()


def _jit_kernels(fn):
    """Dr.Jit kernels launched by fn(): [(hash, operation count), ...] (memsets left out)."""
    import drjit as dr

    dr.set_flag(dr.JitFlag.KernelHistory, True)
    try:
        fn()
        history = dr.kernel_history()
    finally:
        dr.set_flag(dr.JitFlag.KernelHistory, False)
    return [(h["hash"], h["operation_count"]) for h in history
            if h["type"] == dr.KernelType.JIT]


def _facet_inputs(n, seed):
    rng = np.random.default_rng(seed)
    normal = np.column_stack([rng.normal(0, 0.1, (n, 2)), np.ones(n)])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    centre = np.column_stack([rng.uniform(-50, 50, (n, 2)), np.zeros(n)])
    return centre, normal


@needs_drjit
def test_each_kernel_is_one_fused_launch_compiled_once():
    # Every per-pulse kernel is one Dr.Jit launch (no host round trip inside the
    # formulas: a read-back would split it), and a new pulse (new platform positions, new
    # numpy buffers of any alignment) reuses the compiled kernel: same hash.
    from seaecho.ocean.spectra import DirectionalSpectrum
    from seaecho.scattering.facet import (
        FacetModel,
        speckle_draws,
        speckled_facet_amplitudes,
    )
    from seaecho.scattering.spectrum_table import BraggSpectrumTable
    from seaecho.tracing.kernels import facet_frames_drjit

    k = 200.0
    table = BraggSpectrumTable(DirectionalSpectrum(u19_5=6.0).height_spectrum, k / 3, 20 * k,
                               n_k=64, n_psi=36)
    runs = []
    for pulse, n in enumerate((1001, 1003)):
        c, nn = _facet_inputs(n, pulse)
        tx = np.array([-900.0 + 7 * pulse, 10.0, 300.0])
        rx = np.array([400.0, -300.0 + pulse, 120.0])
        frames = {}
        kernels = _jit_kernels(lambda c=c, nn=nn, tx=tx, rx=rx, frames=frames: frames.update(
            facet_frames_drjit(c, nn, tx, rx)))
        draws = speckle_draws(n, np.random.default_rng(pulse))
        kernels += _jit_kernels(lambda f=frames, nn=nn, n=n, draws=draws: (
            speckled_facet_amplitudes(f["n_i"], f["n_s"], nn, np.ones(n),
                                      FacetModel(k, 50 - 30j, table, 0.01, 0.006, 0.3),
                                      draws=draws, backend="drjit")))
        runs.append(kernels)
    assert [len(r) for r in runs] == [2, 2]  # frames, then scattering P1-P4
    assert runs[0] == runs[1]  # same compiled kernels at the second pulse


def _cuda_parity() -> None:
    """The per-pulse kernels on drjit.cuda against numpy (run in its own process)."""
    from seaecho.geometry.facets import facet_frames
    from seaecho.ocean.spectra import DirectionalSpectrum
    from seaecho.scattering.facet import (
        FacetModel,
        speckle_draws,
        speckled_facet_amplitudes,
    )
    from seaecho.scattering.spectrum_table import BraggSpectrumTable
    from seaecho.tracing.kernels import facet_frames_drjit

    variant = "cuda_ad_mono_polarized"
    c, nn = _facet_inputs(2000, 3)
    tx, rx = np.array([-900.0, 10.0, 300.0]), np.array([400.0, -300.0, 120.0])
    a = facet_frames_drjit(c, nn, tx, rx, variant=variant)
    b = facet_frames(c, nn, tx, rx)
    for key in ("r_tx", "n_i", "theta_i", "rot_i"):
        np.testing.assert_allclose(a[key], b[key], rtol=1e-12, atol=1e-12, err_msg=key)
    k = 200.0
    table = BraggSpectrumTable(DirectionalSpectrum(u19_5=6.0).height_spectrum, k / 3, 20 * k)
    draws = speckle_draws(c.shape[0], np.random.default_rng(0))
    args = (b["n_i"], b["n_s"], nn, np.ones(c.shape[0]),
            FacetModel(k, 50 - 30j, table, 0.01, 0.006))
    x = speckled_facet_amplitudes(*args, draws=draws, backend="drjit", variant=variant)
    y = speckled_facet_amplitudes(*args, draws=draws, backend="numpy")
    scale = np.abs(y).max(axis=1, keepdims=True) + 1e-300
    assert np.all(np.abs(x - y) / scale < 1e-8)


@pytest.mark.gpu
@pytest.mark.skipif(not backend.cuda_available(), reason="needs a CUDA GPU")
def test_cuda_kernels_equal_numpy():
    # On a GPU machine: the frames and scattering kernels on drjit.cuda against numpy
    # (same formulas), at the parity tests' tolerances. In a process of its own: one
    # Mitsuba variant per process, and the other tests run the LLVM one.
    import subprocess

    res = subprocess.run([sys.executable, "-c", "import test_backend; "
                          "test_backend._cuda_parity()"], cwd=str(Path(__file__).parent),
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr[-3000:]


@needs_drjit
def test_read_only_arrays_stay_on_the_device_while_they_live():
    # A held sea's arrays are copied once: the same read-only array gives the same
    # device value; a writeable one is copied at every call (it could change under its
    # copy); the copy goes when the numpy array does.
    import gc

    xp = backend.drjit_namespace()
    a = np.arange(5.0)
    a.setflags(write=False)
    first = Boundary(xp, 5).array(a)
    assert Boundary(xp, 5).array(a) is first
    np.testing.assert_array_equal(first.numpy(), a)
    b = np.arange(5.0)
    assert Boundary(xp, 5).array(b) is not Boundary(xp, 5).array(b)
    v = np.arange(15.0).reshape(5, 3)
    v.setflags(write=False)
    assert Boundary(xp, 5).vec3(v) is Boundary(xp, 5).vec3(v)
    assert Boundary(xp, 5).vec3(first * 0 + xp.Array3(1.0, 2.0, 3.0)) is not None
    keys = [(xp.name, id(a), "array"), (xp.name, id(v), "vec3")]
    assert all(k in backend._RESIDENT for k in keys)
    del a, v
    gc.collect()
    assert not any(k in backend._RESIDENT for k in keys)


@needs_drjit
def test_data_pointer_is_the_arrays_memory():
    xp = backend.drjit_namespace()
    a = xp.Float(np.linspace(0.0, 1.0, 6))
    xp.eval(a)
    assert backend.data_pointer(a) == xp.host(a).ctypes.data
    view = backend.cuda_array(a, np.complex128, (3,))
    assert view.__cuda_array_interface__["shape"] == (3,)
    with pytest.raises(ValueError, match="needs 64 bytes"):
        backend.cuda_array(a, np.complex128, (4,))


def test_numpy_while_loop_steps_each_entry_until_its_condition_fails():
    # As Dr.Jit's symbolic loop: an entry whose condition is false keeps its value
    i, s = NUMPY.while_loop((np.array([0, 2, 5]), np.zeros(3)),
                            lambda i, s: i < 4, lambda i, s: (i + 1, s + i))
    np.testing.assert_array_equal(i, [4, 4, 5])
    np.testing.assert_array_equal(s, [6.0, 5.0, 0.0])
