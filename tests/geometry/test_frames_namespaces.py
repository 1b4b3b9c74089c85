"""Parity: each frame formula (eqs F1-F4, G1) run by numpy and by Dr.Jit (same function).

Both namespaces evaluate one function per formula (``seaecho.geometry.frames``,
``seaecho.geometry.bistatic``); these tests check that the two array back ends give the
same numbers, degenerate directions included (nadir, zenith, within 1e-10 of the
normal, grazing, a normal along x, where the reference azimuth falls back on y).
Tolerance: 1e-12 absolute on unit vectors, cosines and angles [rad] (float64 rounding of
a few dozen operations; Dr.Jit's acos/atan2 are not libm's).
"""

from __future__ import annotations

import numpy as np
import pytest

from seaecho import backend
from seaecho.backend import NUMPY, Boundary, Mat2
from seaecho.geometry import bistatic, frames

pytestmark = pytest.mark.skipif(not backend.drjit_available(),
                                reason="Dr.Jit LLVM backend unavailable")

TOL = 1e-12


def _unit(a):
    a = np.asarray(a, dtype=float)
    return a / np.linalg.norm(a, axis=-1, keepdims=True)


def _cases(n=400, seed=5):
    """(n_i, n_s, N): random facets plus the degenerate ones, rows aligned."""
    rng = np.random.default_rng(seed)
    normal = _unit(np.column_stack([rng.normal(0, 0.3, (n, 2)), np.ones(n)]))
    n_i = _unit(rng.normal(size=(n, 3)) - [0, 0, 1.5])
    n_s = _unit(rng.normal(size=(n, 3)) + [0, 0, 1.5])
    z, x = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    tilt = _unit([1e-10, -2e-10, 1.0])
    special = [  # (n_i, n_s, N)
        (-z, z, z),  # nadir backscatter: both directions along N
        (-z, -z, z),  # q = 0 (forward through)
        (_unit([0.6, 0, -0.8]), _unit([0.6, 0, 0.8]), z),  # forward specular
        (x, x, z),  # grazing, q = 0
        (x, -x, z),  # grazing backscatter
        (-tilt, tilt, z),  # within 1e-10 of the normal
        (_unit([-1, 0.2, 0.1]), _unit([1, 0.3, 0.2]), x),  # N along x: reference y
        (-x, x, x),  # along an x normal
        (-normal[0], normal[0], normal[0]),  # along a tilted normal
    ]
    for j, (a, b, c) in enumerate(special):
        n_i[j], n_s[j], normal[j] = a, b, c
    return n_i, n_s, normal


def _run(xp, fn, *vectors):
    """fn(xp, *namespace vectors) evaluated and returned as numpy arrays."""
    io = Boundary(xp, vectors[0].shape[0])
    out = fn(xp, *(io.vec3(v) for v in vectors))
    out = out if isinstance(out, tuple) else (out,)
    flat = []
    for o in out:
        flat.extend(o if isinstance(o, tuple) else (o,))
    return io.numpy(*flat)


def _both(fn, *vectors):
    return _run(NUMPY, fn, *vectors), _run(backend.drjit_namespace(), fn, *vectors)


@pytest.mark.parametrize("name,fn", [
    ("reference_tangent", lambda xp, a, b, N: frames.reference_tangent(xp, N)),
    ("fsa_basis incident", lambda xp, a, b, N: frames.fsa_basis(xp, a, N)),
    ("fsa_basis scattered", lambda xp, a, b, N: frames.fsa_basis(xp, b, N)),
    ("fsa_basis global", lambda xp, a, b, N: frames.fsa_basis(xp, a, xp.vec(0.0, 0.0, 1.0))),
    ("local_geometry", frames.local_geometry),
    ("tilt", lambda xp, a, b, N: frames.tilt(xp, a, b, N, xp.vec(0.0, 0.0, 1.0))),
    ("cos_beta", frames.cos_beta),
    ("azimuths", lambda xp, a, b, N: bistatic.azimuths(xp, a, b)[:2]),
])
def test_frame_formulas_agree_between_namespaces(name, fn):
    n_i, n_s, normal = _cases()
    ref, got = _both(fn, n_i, n_s, normal)
    for r, g in zip(ref, got, strict=True):
        assert np.all(np.isfinite(g)), name
        np.testing.assert_allclose(g, r, rtol=0, atol=TOL, err_msg=name)


def test_azimuths_agree_modulo_a_turn():
    # phi = +-pi are the same azimuth (sign of a zero in atan2): compare on the circle
    n_i, n_s, normal = _cases()
    for fn in (lambda xp, a, b, N: frames.bistatic_angles(xp, a, b, N)[2],
               lambda xp, a, b, N: bistatic.azimuths(xp, a, b)[2]):
        (ref,), (got,) = _both(fn, n_i, n_s, normal)
        np.testing.assert_allclose(np.angle(np.exp(1j * (got - ref))), 0.0, atol=TOL)


def test_bases_are_orthonormal_and_rotations_are_rotations_at_degenerate_directions():
    # Eqs F1-F3 at every case: h, v unit, normal to n and to each other; A of eq F3 a
    # rotation (A^T A = 1, det A = 1), in both namespaces.
    n_i, n_s, normal = _cases()
    for xp in (NUMPY, backend.drjit_namespace()):
        h, v = _run(xp, lambda xp, a, b, N: frames.fsa_basis(xp, a, N), n_i, n_s, normal)
        for a, b in ((h, h), (v, v)):
            np.testing.assert_allclose(np.sum(a * b, -1), 1.0, atol=1e-14)
        for a, b in ((h, v), (h, n_i), (v, n_i)):
            np.testing.assert_allclose(np.sum(a * b, -1), 0.0, atol=1e-14)
        a_i, _ = _run(xp, lambda xp, a, b, N: frames.tilt(xp, a, b, N, xp.vec(0.0, 0.0, 1.0)),
                      n_i, n_s, normal)
        np.testing.assert_allclose(np.swapaxes(a_i, -1, -2) @ a_i,
                                   np.broadcast_to(np.eye(2), a_i.shape), atol=1e-13)
        np.testing.assert_allclose(np.linalg.det(a_i), 1.0, atol=1e-13)


def test_ranges_agree_between_namespaces_monostatic_and_bistatic():
    rng = np.random.default_rng(1)
    c = rng.uniform(-100, 100, (300, 3))
    xp = backend.drjit_namespace()
    for tx, rx in (([0.0, 0.0, 500.0], [0.0, 0.0, 500.0]), ([-900.0, 5, 40], [300, -200, 60])):
        mono = tx == rx
        out = []
        for ns in (NUMPY, xp):
            io = Boundary(ns, c.shape[0])
            out.append(io.numpy(*bistatic.ranges(ns, io.vec3(c), ns.vconst(tx), ns.vconst(rx),
                                                 mono)))
        for r, g in zip(*out, strict=True):
            np.testing.assert_allclose(g, r, rtol=1e-15, atol=1e-13)


def test_global_matrix_is_eq_f4():
    # S_glob = A_s^T S_loc A_i on Mat2 (any entry type) = the numpy matrix product
    rng = np.random.default_rng(2)
    s, a_i, a_s = (rng.normal(size=(5, 2, 2)) for _ in range(3))

    def m(x):
        return Mat2(x[:, 0, 0], x[:, 0, 1], x[:, 1, 0], x[:, 1, 1])

    out = frames.global_matrix(m(s), m(a_i), m(a_s))
    np.testing.assert_allclose(np.stack(out.flat(), -1).reshape(-1, 2, 2),
                               np.swapaxes(a_s, -1, -2) @ s @ a_i, rtol=1e-14)
