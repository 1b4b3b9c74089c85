"""Array namespaces: each physics formula is written once and run by numpy or by Dr.Jit.

The per-facet and per-scatterer formulas of seaecho (frames, Fresnel, Kirchhoff/GO, SPM,
blend, the facet mechanism matrices, the radar equation) are plain Python functions whose
first argument ``xp`` is an *array namespace*. The numpy reference path passes
:data:`NUMPY`; the fast path passes :func:`drjit_namespace` of the scene's variant, which
records the same operations into one fused Dr.Jit kernel (float64) evaluated once, on the
CPU (``drjit.llvm``, the default) or on a CUDA GPU (``drjit.cuda``, when the scene's
``[tracing] variant`` is a ``cuda_*`` one). A formula therefore reads like its equation::

    root = xp.sqrt(eps_r - (1.0 - c * c))
    r_h = (c - root) / (c + root)

whatever the namespace, with complex arithmetic through real complex types (numpy
``complex128``, Dr.Jit ``Complex2f64``).

What a namespace provides
-------------------------
- real functions ``sqrt exp log sin cos acos atan2 floor abs clip maximum minimum``,
  ``select(condition, a, b)`` (also for vectors and :class:`Mat2`) and
  ``select_lazy(condition, fn, b)`` for rare cases (numpy calls ``fn`` only when needed);
- 3-vectors: ``vec(x, y, z)``, components ``.x .y .z``, ``+ - *`` by a scalar array,
  ``dot cross norm normalize`` (numpy: :class:`Vec3` of component arrays, so that
  ``s * v`` broadcasts as in Dr.Jit);
- complex numbers: ``complex(re, im)``, ``real imag abs2 conj``; ``sqrt`` is the principal
  branch in both (``Re >= 0``, imaginary part with the sign of the argument's);
- 2x2 matrices: :class:`Mat2` (``@``, ``.T``, element-wise ``*`` and ``+``), the same
  class for both namespaces;
- per-run and per-pulse constants: ``const``, ``cconst``, ``vconst`` (``const32`` and
  ``single`` for the float32 parts of a kernel). In Dr.Jit they are
  *opaque* (kernel parameters): a literal would be baked into the kernel's code and a
  new value (the platform's position at each pulse) would recompile it (0.04-0.14 s);
- table look-ups: ``index`` (float -> integer) and ``gather``;
- ``eval(*arrays)``: evaluates every output of a kernel together (one fused kernel in
  Dr.Jit; nothing in numpy);
- loops and indexing for kernels that walk a table (backprojection): ``arange``,
  ``zeros``, ``while_loop(state, cond, body)`` (a symbolic loop in Dr.Jit, a Python loop
  over whole arrays in numpy), ``gather(values, index, active)``, ``compress(mask)``
  (indices of the true entries, in order) and ``host(a)`` (a numpy view or copy).

Stage boundaries
----------------
:class:`Boundary` converts numpy inputs into namespace arrays and the outputs back to
numpy, once per stage: nothing inside a formula reads values back to the host, so the
CUDA path stays device-resident between the two transfers. Dr.Jit's LLVM backend aliases
numpy memory without copying and compiles a kernel variant that depends on whether each
input is 64-byte aligned (aligned vector loads); numpy's allocator gives 16-byte
alignment, so buffers go through :func:`aligned` (about one pulse in two recompiled a
kernel before, 30-90 ms each).

Residency
---------
A read-only numpy array (``a.flags.writeable`` False: the facet geometry of a held sea,
its speckle draws) is copied to the device once and kept there while the numpy array
lives (:func:`resident`; :class:`Boundary` uses it): the per-pulse kernels of a held sea
then read device memory only, and on a GPU nothing per facet crosses the bus after the
first pulse of a block. Outputs come back by :meth:`DrJitNamespace.host`, a zero-copy
view on the CPU (Dr.Jit's LLVM arrays live in host memory). :func:`cuda_array` hands a
CUDA array to a library that reads ``__cuda_array_interface__`` (cufinufft).

Set-up
------
Dr.Jit is imported lazily, after :func:`seaecho._llvm.configure_llvm` has pointed it at a
libLLVM that works. This module never imports Mitsuba (only ``seaecho.tracing`` does);
it only reads the variant Mitsuba already runs, to refuse a mismatch.
"""

from __future__ import annotations

import ctypes
import functools
import importlib
import sys
import weakref
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "ALIGNMENT",
    "DEFAULT_VARIANT",
    "NUMPY",
    "VARIANTS",
    "PRECISIONS",
    "Boundary",
    "DrJitNamespace",
    "Mat2",
    "NumpyNamespace",
    "Rows",
    "Vec3",
    "aligned",
    "check_variant",
    "cuda_array",
    "cuda_available",
    "drjit_available",
    "drjit_namespace",
    "namespace",
    "resident",
]

#: Mitsuba variants seaecho runs with; their prefix selects the Dr.Jit back end.
VARIANTS = ("llvm_ad_mono_polarized", "cuda_ad_mono_polarized")
#: CPU through libLLVM (``seaecho._llvm``).
DEFAULT_VARIANT = "llvm_ad_mono_polarized"

#: Working precisions of a namespace: ``"double"`` (float64, complex128) and ``"single"``
#: (float32, complex64; Dr.Jit only, for the scattering stage of the facet kernels).
PRECISIONS = ("double", "single")
#: Per precision: ``tiny``, a positive threshold below which a square of a value counts as
#: 0 (far above the smallest normal number); ``exp_cap``, the largest exponent the
#: formulas let ``exp`` take (a power of ``e`` that still leaves room for the products
#: that follow: exp(700) ~ 1e304 in float64, exp(80) ~ 6e34 in float32, whose largest is
#: 3.4e38); ``degenerate``, the length of the tangential part of a unit direction below
#: which it counts as along a plane's normal (``geometry.frames.DEGENERATE``: 1e-9 in
#: float64; 1e-5 in float32, whose rounding leaves up to about 5e-7 of an exactly
#: degenerate one, e.g. the specular normal of a monostatic geometry, -n_i).
_LIMITS = {"double": (1e-200, 700.0, 1e-9), "single": (1e-30, 80.0, 1e-5)}

#: Byte alignment of the buffers handed to Dr.Jit (a cache line; the widest AVX-512 load).
ALIGNMENT = 64


def aligned(a: ArrayLike, dtype=np.float64) -> NDArray:
    """A C-contiguous copy of ``a`` in ``dtype`` whose data start on a 64-byte boundary.

    Parameters
    ----------
    a : array_like
        Values (any shape, any strides).
    dtype : numpy dtype
        Element type of the copy.

    Returns
    -------
    ndarray
        Same shape and values; ``result.ctypes.data % ALIGNMENT == 0``.
    """
    a = np.asarray(a)
    dt = np.dtype(dtype)
    n = a.size
    raw = np.empty(n * dt.itemsize + ALIGNMENT, dtype=np.uint8)
    start = -raw.ctypes.data % ALIGNMENT
    out = raw[start:start + n * dt.itemsize].view(dt).reshape(a.shape)
    np.copyto(out, a, casting="unsafe" if dt != a.dtype else "same_kind")
    return out


# ----------------------------------------------------------------------------- values
def _is_zero(a: Any) -> bool:
    """A structural zero: the Python number 0 (entries of :meth:`Mat2.diag`)."""
    return isinstance(a, int | float) and not isinstance(a, bool) and a == 0


def _mul(a: Any, b: Any) -> Any:
    if _is_zero(a) or _is_zero(b):
        return 0
    return a * b


def _add(a: Any, b: Any) -> Any:
    if _is_zero(a):
        return b
    if _is_zero(b):
        return a
    return a + b


class Vec3:
    """A 3-vector of numpy component arrays (the numpy namespace's ``Array3f64``).

    Components broadcast against each other and against scalar arrays, so that
    ``s * v`` scales every component as in Dr.Jit; numpy defers to this class's
    operators (``__array_ufunc__ = None``).
    """

    __slots__ = ("x", "y", "z")
    __array_ufunc__ = None

    def __init__(self, x: Any, y: Any, z: Any) -> None:
        self.x, self.y, self.z = x, y, z

    def __add__(self, o: Vec3) -> Vec3:
        return Vec3(self.x + o.x, self.y + o.y, self.z + o.z)

    def __sub__(self, o: Vec3) -> Vec3:
        return Vec3(self.x - o.x, self.y - o.y, self.z - o.z)

    def __neg__(self) -> Vec3:
        return Vec3(-self.x, -self.y, -self.z)

    def __mul__(self, s: Any) -> Vec3:
        return Vec3(self.x * s, self.y * s, self.z * s)

    __rmul__ = __mul__

    def __truediv__(self, s: Any) -> Vec3:
        return Vec3(self.x / s, self.y / s, self.z / s)

    def __getitem__(self, i: int) -> Any:
        return (self.x, self.y, self.z)[i]

    def __iter__(self):
        return iter((self.x, self.y, self.z))


class Mat2:
    """A 2x2 matrix of namespace arrays (real or complex), rows and columns in (h, v) order.

    ``A @ B`` is the matrix product, ``A * B`` and ``A + B`` are element-wise (``A * s``
    scales by a scalar array), ``A.T`` the transpose; :meth:`flat` lists the entries in
    the channel order HH, HV, VH, VV. Entries that are the Python number 0
    (:meth:`diag`) are structural zeros: products with them are skipped, so
    ``A_s.T @ Mat2.diag(r_h, r_v) @ A_i`` costs what the written-out sum costs.
    """

    __slots__ = ("hh", "hv", "vh", "vv")
    __array_ufunc__ = None

    def __init__(self, hh: Any, hv: Any, vh: Any, vv: Any) -> None:
        self.hh, self.hv, self.vh, self.vv = hh, hv, vh, vv

    @classmethod
    def diag(cls, a: Any, b: Any) -> Mat2:
        """``diag(a, b)`` with structural zeros off the diagonal."""
        return cls(a, 0, 0, b)

    @property
    def T(self) -> Mat2:  # noqa: N802 - the usual name of a transpose
        return Mat2(self.hh, self.vh, self.hv, self.vv)

    def __matmul__(self, o: Mat2) -> Mat2:
        return Mat2(_add(_mul(self.hh, o.hh), _mul(self.hv, o.vh)),
                    _add(_mul(self.hh, o.hv), _mul(self.hv, o.vv)),
                    _add(_mul(self.vh, o.hh), _mul(self.vv, o.vh)),
                    _add(_mul(self.vh, o.hv), _mul(self.vv, o.vv)))

    def __mul__(self, o: Any) -> Mat2:
        if isinstance(o, Mat2):
            return Mat2(*(_mul(a, b) for a, b in zip(self.flat(), o.flat(), strict=True)))
        return Mat2(*(_mul(a, o) for a in self.flat()))

    __rmul__ = __mul__

    def __add__(self, o: Mat2) -> Mat2:
        return Mat2(*(_add(a, b) for a, b in zip(self.flat(), o.flat(), strict=True)))

    def __getitem__(self, ij: tuple[int, int]) -> Any:
        return self.flat()[2 * ij[0] + ij[1]]

    def flat(self) -> tuple[Any, Any, Any, Any]:
        """Entries HH, HV, VH, VV (row-major)."""
        return (self.hh, self.hv, self.vh, self.vv)

    def map(self, fn: Callable[[Any], Any]) -> Mat2:
        """``fn`` applied to every entry."""
        return Mat2(*(fn(a) for a in self.flat()))


# ------------------------------------------------------------------------- namespaces
class NumpyNamespace:
    """The numpy namespace: float64 / complex128 arrays of any (broadcast) shape."""

    name = "numpy"
    is_numpy = True
    #: numpy evaluates every formula in float64 (the reference of the single-precision
    #: Dr.Jit kernels): :meth:`with_precision` returns this namespace whatever is asked.
    precision = "double"
    tiny, exp_cap, degenerate = _LIMITS["double"]

    sqrt = staticmethod(np.sqrt)
    exp = staticmethod(np.exp)
    log = staticmethod(np.log)
    sin = staticmethod(np.sin)
    cos = staticmethod(np.cos)
    acos = staticmethod(np.arccos)
    atan2 = staticmethod(np.arctan2)
    floor = staticmethod(np.floor)
    abs = staticmethod(np.abs)
    maximum = staticmethod(np.maximum)
    minimum = staticmethod(np.minimum)
    real = staticmethod(np.real)
    imag = staticmethod(np.imag)
    conj = staticmethod(np.conj)

    @staticmethod
    def clip(x: Any, lo: float, hi: float) -> Any:
        return np.clip(x, lo, hi)

    @staticmethod
    def select(c: Any, a: Any, b: Any) -> Any:
        if isinstance(a, Vec3) or isinstance(b, Vec3):
            return Vec3(*(np.where(c, ai, bi) for ai, bi in zip(a, b, strict=True)))
        if isinstance(a, Mat2) or isinstance(b, Mat2):
            return Mat2(*(np.where(c, ai, bi) for ai, bi in zip(a.flat(), b.flat(),
                                                                 strict=True)))
        return np.where(c, a, b)

    def select_lazy(self, c: Any, fn: Callable[[], Any], b: Any) -> Any:
        """``select(c, fn(), b)``, calling ``fn`` only if some ``c`` holds (rare cases)."""
        return self.select(c, fn(), b) if np.any(c) else b

    def with_precision(self, precision: str) -> NumpyNamespace:
        """This namespace: numpy is the float64 reference whatever ``precision`` asks
        (``"double"`` or ``"single"``)."""
        _check_precision(precision)
        return self

    @staticmethod
    def cast(a: Any) -> Any:
        """``a`` unchanged (numpy values are float64 already)."""
        return a

    # vectors
    @staticmethod
    def vec(x: Any, y: Any, z: Any) -> Vec3:
        return Vec3(x, y, z)

    @staticmethod
    def is_vector(a: Any) -> bool:
        return isinstance(a, Vec3)

    @staticmethod
    def dot(a: Vec3, b: Vec3) -> Any:
        return a.x * b.x + a.y * b.y + a.z * b.z

    @staticmethod
    def cross(a: Vec3, b: Vec3) -> Vec3:
        return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x)

    def norm(self, a: Vec3) -> Any:
        return np.sqrt(self.dot(a, a))

    def normalize(self, a: Vec3) -> Vec3:
        return a * (1.0 / self.norm(a))

    # complex numbers
    @staticmethod
    def complex(re: Any, im: Any) -> Any:
        re, im = np.broadcast_arrays(np.asarray(re, dtype=np.float64),
                                     np.asarray(im, dtype=np.float64))
        out = np.empty(re.shape, dtype=np.complex128)
        out.real, out.imag = re, im  # (keeps the sign of a zero imaginary part)
        return out

    @staticmethod
    def abs2(z: Any) -> Any:
        return z.real * z.real + z.imag * z.imag

    # constants, tables
    @staticmethod
    def const(value: float) -> float:
        return float(value)

    @staticmethod
    def cconst(value: complex) -> complex:
        return complex(value)

    @staticmethod
    def const32(value: float) -> np.float32:
        return np.float32(value)

    @staticmethod
    def single(a: Any) -> Any:
        """``a`` rounded to float32."""
        return np.asarray(a, dtype=np.float32)

    @staticmethod
    def vconst(a: ArrayLike) -> Vec3:
        x, y, z = (float(c) for c in np.asarray(a, dtype=np.float64).reshape(3))
        return Vec3(x, y, z)

    @staticmethod
    def table(values: NDArray) -> NDArray:
        return np.asarray(values, dtype=np.float64)

    @staticmethod
    def index(x: Any) -> Any:
        return np.asarray(x).astype(np.int64)

    @staticmethod
    def gather(values: NDArray, index: Any, active: Any = True) -> Any:
        if active is True:
            return values[index]
        return np.where(active, values[np.where(active, index, 0)], 0)

    @staticmethod
    def eval(*arrays: Any) -> None:
        return None

    # loops and indexing
    @staticmethod
    def arange(n: int) -> NDArray:
        return np.arange(n, dtype=np.int64)

    @staticmethod
    def zeros(n: int) -> NDArray:
        return np.zeros(n)

    @staticmethod
    def compress(mask: Any) -> NDArray:
        """Indices of the true entries of ``mask``, in increasing order."""
        return np.flatnonzero(mask)

    @staticmethod
    def while_loop(state: tuple, cond: Callable, body: Callable) -> tuple:
        """``while cond(*state): state = body(*state)``, entry by entry (as Dr.Jit's).

        Whole arrays step together; an entry whose condition is false keeps its values.
        """
        state = tuple(state)
        while True:
            c = np.asarray(cond(*state))
            if not c.any():
                return state
            new = body(*state)
            state = tuple(np.where(c, b, a) for a, b in zip(state, new, strict=True))

    @staticmethod
    def host(a: Any) -> NDArray:
        return np.asarray(a)


#: The numpy namespace (the reference path).
NUMPY = NumpyNamespace()


class DrJitNamespace:
    """A Dr.Jit namespace on ``drjit.llvm`` (CPU) or ``drjit.cuda`` (GPU).

    Build it with :func:`drjit_namespace`. Arrays are 1-D (one entry per facet or
    scatterer); width-1 arrays (constants) broadcast.

    ``precision`` ``"double"`` (the default) works in ``Float64``/``Complex2f64``;
    ``"single"`` in ``Float32``/``Complex2f`` (its ``Float``, ``Complex``, ``Array3``,
    ``const`` and ``table`` are float32): :meth:`with_precision` gives the other one of
    the same back end and :meth:`cast` converts values into it. Dr.Jit promotes a float32
    operand mixed with a float64 one to float64, so a formula evaluated on single values
    with this namespace's constants stays float32 throughout.
    """

    is_numpy = False

    def __init__(self, backend: str, precision: str = "double") -> None:
        if backend not in ("llvm", "cuda"):
            raise ValueError(f"backend = {backend!r}: allowed 'llvm', 'cuda'")
        _check_precision(precision)
        from ._llvm import configure_llvm

        configure_llvm()
        import drjit as dr

        m = importlib.import_module(f"drjit.{backend}")
        if backend == "cuda":
            exact_cuda_math()
        self.name = backend
        self.dr = dr
        self.module = m
        self.precision = precision
        self.tiny, self.exp_cap, self.degenerate = _LIMITS[precision]
        single = precision == "single"
        self.Float = m.Float32 if single else m.Float64
        self.Complex = m.Complex2f if single else m.Complex2f64
        self.Array3 = m.Array3f if single else m.Array3f64
        self.UInt = m.UInt32
        self.Int = m.Int32
        self.Float32 = m.Float32
        self.Bool = m.Bool
        self.sqrt = dr.sqrt
        self.exp = dr.exp
        self.log = dr.log
        self.sin = dr.sin
        self.cos = dr.cos
        self.acos = dr.acos
        self.atan2 = dr.atan2
        self.floor = dr.floor
        self.abs = dr.abs
        self.maximum = dr.maximum
        self.minimum = dr.minimum
        self.real = dr.real
        self.imag = dr.imag
        self.conj = dr.conj
        self.abs2 = dr.squared_norm
        self.eval = dr.eval

    def clip(self, x: Any, lo: float, hi: float) -> Any:
        return self.dr.clip(x, lo, hi)

    def select(self, c: Any, a: Any, b: Any) -> Any:
        if isinstance(a, Mat2) or isinstance(b, Mat2):
            return Mat2(*(self.dr.select(c, ai, bi) for ai, bi in zip(a.flat(), b.flat(),
                                                                       strict=True)))
        return self.dr.select(c, a, b)

    def select_lazy(self, c: Any, fn: Callable[[], Any], b: Any) -> Any:
        """``select(c, fn(), b)`` (a kernel evaluates both sides anyway)."""
        return self.select(c, fn(), b)

    def with_precision(self, precision: str) -> DrJitNamespace:
        """The namespace of the same back end in ``precision`` (``"double"``,
        ``"single"``)."""
        return _drjit_namespace(self.name, precision)

    def cast(self, a: Any) -> Any:
        """``a`` (a real, complex or 3-vector value, or a :class:`Mat2` of them) in this
        namespace's precision; Python numbers and masks as they are."""
        if isinstance(a, Mat2):
            return a.map(self.cast)
        if isinstance(a, int | float | complex | self.Bool):
            return a
        m = self.module
        if isinstance(a, m.Complex2f64 | m.Complex2f):
            return a if isinstance(a, self.Complex) else self.Complex(a)
        if isinstance(a, m.Array3f64 | m.Array3f):
            return a if isinstance(a, self.Array3) else self.Array3(a)
        return a if isinstance(a, self.Float) else self.Float(a)

    def vec(self, x: Any, y: Any, z: Any) -> Any:
        return self.Array3(x, y, z)

    def is_vector(self, a: Any) -> bool:
        return isinstance(a, self.Array3)

    # dot and cross as numpy rounds them (products, then sums; no fused multiply-add):
    # the two paths then agree to the last bit on these, and exact zeros stay exact
    # (an ideal H port has no component on v: HH of a VV-only target is exactly 0).
    @staticmethod
    def dot(a: Any, b: Any) -> Any:
        return a.x * b.x + a.y * b.y + a.z * b.z

    def cross(self, a: Any, b: Any) -> Any:
        return self.Array3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x)

    def norm(self, a: Any) -> Any:
        return self.dr.sqrt(self.dot(a, a))

    def normalize(self, a: Any) -> Any:
        return a * (1.0 / self.norm(a))

    def complex(self, re: Any, im: Any) -> Any:
        return self.Complex(re, im)

    def const(self, value: float) -> Any:
        return self.dr.opaque(self.Float, float(value))

    def const32(self, value: float) -> Any:
        """A float32 opaque constant."""
        return self.dr.opaque(self.Float32, float(value))

    def single(self, a: Any) -> Any:
        """``a`` rounded to float32."""
        return self.Float32(a)

    def cconst(self, value: complex) -> Any:
        value = complex(value)
        return self.Complex(self.const(value.real), self.const(value.imag))

    def vconst(self, a: ArrayLike) -> Any:
        return self.Array3(*(self.const(c) for c in np.asarray(a, dtype=np.float64).reshape(3)))

    def table(self, values: NDArray) -> Any:
        return self.Float(aligned(values, np.float32 if self.precision == "single"
                                  else np.float64))

    def index(self, x: Any) -> Any:
        return self.UInt(x)

    def gather(self, values: Any, index: Any, active: Any = True, dtype: Any = None) -> Any:
        """``values[index]`` (0 where not ``active``); ``dtype`` a nested type such as
        ``Array2f64`` reads consecutive entries (:meth:`pair`)."""
        return self.dr.gather(type(values) if dtype is None else dtype, values, index, active)

    # loops and indexing
    def arange(self, n: int) -> Any:
        return self.dr.arange(self.UInt, n)

    def zeros(self, n: int) -> Any:
        return self.dr.zeros(self.Float, n)

    def compress(self, mask: Any) -> Any:
        """Indices of the true entries of ``mask``, in increasing order (UInt32)."""
        return self.dr.compress(mask)

    def while_loop(self, state: tuple, cond: Callable, body: Callable) -> tuple:
        """A symbolic loop: one kernel runs ``body`` while ``cond`` holds, per entry."""
        return self.dr.while_loop(state=tuple(state), cond=cond, body=body)

    def scatter(self, target: Any, value: Any, index: Any) -> None:
        """``target[index] = value`` (recorded; done with the next evaluation)."""
        self.dr.scatter(target, value, index)

    def empty(self, n: int, dtype: Any = None) -> Any:
        """A Float64 (or ``dtype``) array of ``n`` entries with its own memory (not
        initialised)."""
        a = self.dr.empty(self.Float if dtype is None else dtype, n)
        self.dr.make_opaque(a)
        return a

    def pair(self, a: Any, b: Any) -> Any:
        """``(a, b)`` as one value: scattered at index k it writes entries 2 k and 2 k + 1
        of a flat array (the memory of a complex array); gathered likewise."""
        return self.module.Array2f64(a, b)

    def host(self, a: Any) -> NDArray:
        """The values of an evaluated array in numpy: a read-only view of the array's
        memory on the CPU (no copy), a copy from a GPU."""
        if isinstance(a, int | float | bool):
            return np.asarray(a)
        return a.numpy()

    def count(self, mask: Any) -> int:
        """Number of true entries (reads one integer back)."""
        return int(self.dr.count(mask)[0]) if self.dr.width(mask) else 0

    def width(self, a: Any) -> int:
        return int(self.dr.width(a))


# --------------------------------------------------------------------- variant choice
def drjit_available() -> bool:
    """Whether Dr.Jit's LLVM (CPU) back end imports and runs here (checked once)."""
    return _drjit_llvm_runs()


@functools.cache
def _drjit_llvm_runs() -> bool:
    try:
        ns = DrJitNamespace("llvm")
        return bool(ns.Float(1.0).numpy()[0] == 1.0)
    except Exception:  # noqa: BLE001 - any failure means: use numpy
        return False


def cuda_available() -> bool:
    """Whether Dr.Jit's CUDA back end has a device here (no Mitsuba import)."""
    try:
        from ._llvm import configure_llvm

        configure_llvm()
        import drjit as dr

        return bool(dr.has_backend(dr.JitBackend.CUDA))
    except Exception:  # noqa: BLE001 - no driver, no device: not available
        return False


def _mitsuba_variant() -> str | None:
    """The variant Mitsuba runs in this process (None if Mitsuba is not imported or unset).

    Read only: this module never imports Mitsuba.
    """
    mi = sys.modules.get("mitsuba")
    if mi is None:
        return None
    try:
        return mi.variant()
    except Exception:  # noqa: BLE001 - an unusable Mitsuba has no variant to clash with
        return None


def check_variant(variant: str | None) -> str:
    """Validate the Mitsuba variant of the kernels and return it.

    ``None`` means the variant Mitsuba already runs in this process (set explicitly by
    the tracer from the scene's ``[tracing] variant``), or the default
    ``llvm_ad_mono_polarized`` when none is set. Call it where a run starts, so that a
    wrong variant is a clear error there, never a failure in the middle of a run.

    Raises
    ------
    ValueError
        An unknown variant; a CUDA variant without a CUDA GPU; or a variant whose back
        end differs from the one Mitsuba already runs in this process (the tracer's
        scenes and the kernels must share one back end).
    """
    current = _mitsuba_variant()
    if variant is None:
        variant = current if current in VARIANTS else DEFAULT_VARIANT
    if variant not in VARIANTS:
        raise ValueError(f"variant = {variant!r}: allowed {', '.join(map(repr, VARIANTS))}")
    backend = variant.split("_", 1)[0]
    if backend == "cuda" and not cuda_available():
        raise ValueError(f"variant = {variant!r}: no CUDA GPU available here (Dr.Jit "
                         f"finds no CUDA device); use {DEFAULT_VARIANT!r} (CPU)")
    if current and current.split("_", 1)[0] in ("llvm", "cuda") and (
            current.split("_", 1)[0] != backend):
        raise ValueError(f"variant = {variant!r}: Mitsuba already runs {current!r} in this "
                         "process; the tracer and the kernels must use the same back end "
                         "(one [tracing] variant per process)")
    return variant


def drjit_namespace(variant: str | None = None) -> DrJitNamespace:
    """The Dr.Jit namespace of a Mitsuba variant (``llvm_*`` CPU, default; ``cuda_*`` GPU).

    ``variant`` None: the one Mitsuba runs, else the default (:func:`check_variant`).

    Raises
    ------
    ValueError
        As :func:`check_variant`.
    """
    variant = check_variant(variant)
    return _drjit_namespace(variant.split("_", 1)[0])


def exact_cuda_math() -> None:
    """Turn off Dr.Jit's fast-math mode, which the CUDA back end needs to be float64-exact.

    With ``JitFlag.FastMath`` on (Dr.Jit's default), the scattering amplitudes of eqs
    P1-P4 on ``drjit.cuda`` departed from numpy's by up to 7e-7 of each channel's largest
    amplitude on an H100 (approximate arithmetic in the generated PTX); with it off, by
    at most 2e-15, as on the LLVM back end. Dr.Jit's flags are global to the process,
    which runs one Mitsuba variant.
    """
    import drjit as dr

    dr.set_flag(dr.JitFlag.FastMath, False)


def _check_precision(precision: str) -> None:
    if precision not in PRECISIONS:
        raise ValueError(f"precision = {precision!r}: allowed "
                         f"{', '.join(map(repr, PRECISIONS))}")


@functools.cache
def _drjit_namespace(backend: str, precision: str = "double") -> DrJitNamespace:
    return DrJitNamespace(backend, precision)


def namespace(backend: str = "drjit", variant: str | None = None):
    """The namespace of a kernel back end.

    Parameters
    ----------
    backend : {"numpy", "drjit", "auto"}
        numpy reference, Dr.Jit of ``variant``, or Dr.Jit when its CPU back end works
        (or a CUDA ``variant`` is asked for) and numpy otherwise.
    variant : str, optional
        Mitsuba variant selecting ``drjit.llvm`` (default) or ``drjit.cuda``.
    """
    if backend == "numpy":
        return NUMPY
    if backend == "drjit":
        return drjit_namespace(variant)
    if backend == "auto":
        if (variant is not None and variant.startswith("cuda")) or drjit_available():
            return drjit_namespace(variant)
        return NUMPY
    raise ValueError(f"backend = {backend!r}: allowed 'numpy', 'drjit', 'auto'")


# -------------------------------------------------------------------------- residency
#: (namespace, id(array), kind) -> (weak reference to the numpy array, device value, buffers)
_RESIDENT: dict[tuple[str, int, str], tuple[weakref.ref, Any, list]] = {}


def _is_namespace_value(xp, a: Any) -> bool:
    """Whether ``a`` already lives in Dr.Jit namespace ``xp`` (no conversion needed)."""
    return isinstance(a, xp.Float | xp.Complex | xp.Array3 | xp.Bool | xp.UInt | xp.Float32)


def resident(xp, a: NDArray, kind: str = "array") -> Any:
    """The namespace value of a read-only numpy array, converted once while it lives.

    Parameters
    ----------
    xp : NumpyNamespace or DrJitNamespace
    a : ndarray
        Values; (N,) float for ``"array"``, (N,) complex for ``"complex"``, (N, 3) for
        ``"vec3"``, (N,) bool for ``"bool"``. Only an array that cannot be written
        (``a.flags.writeable`` False) is kept: a writeable one could change under its
        device copy, so it is converted at every call.
    kind : {"array", "complex", "vec3", "bool"}

    Returns
    -------
    Namespace value (numpy namespace: the array itself, or a :class:`Vec3` of its columns).

    Notes
    -----
    The device copy is dropped when the numpy array is garbage-collected (a weak
    reference), so a held sea's facets stay on the device exactly as long as the engine
    holds their geometry.
    """
    if xp.is_numpy:
        a = np.asarray(a)
        if kind == "vec3":
            return Vec3(a[..., 0], a[..., 1], a[..., 2])
        return a
    if not isinstance(a, np.ndarray) or a.flags.writeable:
        return _convert(xp, a, kind, [])
    key = (xp.name, id(a), kind)
    hit = _RESIDENT.get(key)
    if hit is not None and hit[0]() is a:
        return hit[1]
    keep: list = []
    value = _convert(xp, a, kind, keep)
    _RESIDENT[key] = (weakref.ref(a, lambda _, key=key: _RESIDENT.pop(key, None)), value, keep)
    return value


def _convert(xp, a: ArrayLike, kind: str, keep: list) -> Any:
    """numpy -> Dr.Jit (64-byte-aligned buffers appended to ``keep``: LLVM aliases them)."""
    def real(v):
        buf = aligned(np.asarray(v, dtype=np.float64).reshape(-1))
        keep.append(buf)
        return xp.Float(buf)

    if kind == "array":
        return real(a)
    if kind == "complex":
        a = np.asarray(a, dtype=np.complex128)
        return xp.Complex(real(a.real), real(a.imag))
    if kind == "vec3":
        a = np.asarray(a, dtype=np.float64)
        if a.shape[-1:] != (3,):
            raise ValueError(f"vectors must have shape (..., 3), got {a.shape}")
        return xp.Array3(*(real(a[..., k]) for k in range(3)))
    if kind == "bool":
        buf = aligned(np.asarray(a, dtype=bool).reshape(-1), np.bool_)
        keep.append(buf)
        return xp.Bool(buf)
    raise ValueError(f"kind = {kind!r}: allowed 'array', 'complex', 'vec3', 'bool'")


# ------------------------------------------------------------------ CUDA array interface
class _DLDevice(ctypes.Structure):
    _fields_ = [("device_type", ctypes.c_int32), ("device_id", ctypes.c_int32)]


class _DLDataType(ctypes.Structure):
    _fields_ = [("code", ctypes.c_uint8), ("bits", ctypes.c_uint8), ("lanes", ctypes.c_uint16)]


class _DLTensor(ctypes.Structure):
    _fields_ = [("data", ctypes.c_void_p), ("device", _DLDevice), ("ndim", ctypes.c_int32),
                ("dtype", _DLDataType), ("shape", ctypes.POINTER(ctypes.c_int64)),
                ("strides", ctypes.POINTER(ctypes.c_int64)), ("byte_offset", ctypes.c_uint64)]


def data_pointer(array: Any) -> int:
    """Address of the first entry of an evaluated Dr.Jit array (host or device memory).

    Read through the array's DLPack capsule (which is left unconsumed: the array keeps
    owning its memory, and must outlive every use of the address).
    """
    capsule = array.__dlpack__()
    get = ctypes.pythonapi.PyCapsule_GetPointer
    get.restype = ctypes.c_void_p
    get.argtypes = [ctypes.py_object, ctypes.c_char_p]
    tensor = _DLTensor.from_address(get(capsule, b"dltensor"))
    return int(tensor.data or 0) + int(tensor.byte_offset)


class _Flags:
    c_contiguous = True


class CudaArrayView:
    """A contiguous Dr.Jit array seen as an n-d array of ``dtype`` through
    ``__cuda_array_interface__`` (version 3), for GPU libraries such as cufinufft.

    Parameters
    ----------
    array : Dr.Jit array
        Evaluated, contiguous; kept alive by the view.
    dtype : numpy dtype
        Element type seen by the consumer (complex128 over an interleaved Float64 array).
    shape : tuple of int
        Its shape (C order).
    """

    flags = _Flags()

    def __init__(self, array: Any, dtype: Any, shape: tuple[int, ...]) -> None:
        self._array = array
        self.dtype = np.dtype(dtype)
        self.shape = tuple(int(s) for s in shape)
        nbytes = int(np.prod(self.shape)) * self.dtype.itemsize
        have = int(array.__len__()) * np.dtype(_element_dtype(array)).itemsize
        if nbytes != have:
            raise ValueError(f"a {self.shape} {self.dtype} view needs {nbytes} bytes, "
                             f"the array has {have}")
        self._ptr = data_pointer(array)

    @property
    def size(self) -> int:
        return int(np.prod(self.shape))

    @property
    def ndim(self) -> int:
        return len(self.shape)

    def reshape(self, shape: tuple[int, ...]) -> CudaArrayView:
        return CudaArrayView(self._array, self.dtype, shape)

    @property
    def __cuda_array_interface__(self) -> dict:
        return {"shape": self.shape, "typestr": self.dtype.str, "data": (self._ptr, False),
                "strides": None, "version": 3}


def _element_dtype(array: Any) -> Any:
    name = type(array).__name__
    return {"Float64": np.float64, "Float": np.float32, "Float32": np.float32,
            "UInt": np.uint32, "UInt32": np.uint32, "Int": np.int32, "Int32": np.int32,
            "Bool": np.bool_}[name]


def cuda_array(array: Any, dtype: Any, shape: tuple[int, ...]) -> CudaArrayView:
    """:class:`CudaArrayView` of an evaluated Dr.Jit array (see there)."""
    return CudaArrayView(array, dtype, shape)


def cuda_synchronize() -> None:
    """Wait for all work queued on the GPU: Dr.Jit's stream and any other library's.

    Dr.Jit and cufinufft queue kernels on their own CUDA streams; before one reads what
    the other wrote, the context is synchronised (``cuCtxSynchronize`` of the driver,
    the library every CUDA program loads). Dr.Jit and the CUDA runtime of cufinufft both
    work in the device's primary context, which Dr.Jit does not leave current on the
    calling thread: where no context is current, the primary context of the device is
    made current for the call.
    """
    import drjit as dr

    dr.sync_thread()
    lib = ctypes.CDLL("libcuda.so.1")
    current = ctypes.c_void_p()
    _cuda_check(lib.cuCtxGetCurrent(ctypes.byref(current)), "cuCtxGetCurrent")
    if current.value:
        _cuda_check(lib.cuCtxSynchronize(), "cuCtxSynchronize")
        return
    device, ctx = ctypes.c_int(), ctypes.c_void_p()
    _cuda_check(lib.cuDeviceGet(ctypes.byref(device), 0), "cuDeviceGet")
    _cuda_check(lib.cuDevicePrimaryCtxRetain(ctypes.byref(ctx), device),
                "cuDevicePrimaryCtxRetain")
    try:
        _cuda_check(lib.cuCtxPushCurrent_v2(ctx), "cuCtxPushCurrent")
        try:
            _cuda_check(lib.cuCtxSynchronize(), "cuCtxSynchronize")
        finally:
            lib.cuCtxPopCurrent_v2(ctypes.byref(ctypes.c_void_p()))
    finally:
        lib.cuDevicePrimaryCtxRelease_v2(device)


def _cuda_check(err: int, what: str) -> None:
    if err != 0:
        raise RuntimeError(f"{what} failed with CUDA error {err}")


# ------------------------------------------------------------------------- boundaries
class Boundary:
    """numpy <-> namespace conversions of one kernel call (a stage boundary).

    Inputs become namespace arrays (Dr.Jit: 64-byte-aligned copies, kept alive here until
    the kernel has run, since the LLVM back end aliases them); :meth:`numpy` evaluates
    every output in one ``eval`` and returns numpy arrays.

    Parameters
    ----------
    xp : NumpyNamespace or DrJitNamespace
    n : int, optional
        Number of entries (facets, scatterers): width-1 outputs are broadcast to it.
    """

    def __init__(self, xp, n: int | None = None) -> None:
        self.xp = xp
        self.n = n
        self._keep: list[NDArray] = []

    def _device(self, a: Any, kind: str, dtype: Any) -> Any | None:
        """``a`` as it is (already a namespace value), its resident copy (a read-only
        float64 array, :func:`resident`), or None (convert it here)."""
        if self.xp.is_numpy:
            return None
        if _is_namespace_value(self.xp, a):
            return a
        if (isinstance(a, np.ndarray) and not a.flags.writeable and a.dtype == dtype):
            return resident(self.xp, a, kind)
        return None

    def array(self, a: ArrayLike) -> Any:
        """A real (N,) input [float64]."""
        if self.xp.is_numpy:
            return np.asarray(a, dtype=np.float64)
        dev = self._device(a, "array", np.float64)
        if dev is not None:
            return dev
        return _convert(self.xp, a, "array", self._keep)

    def complex(self, a: ArrayLike) -> Any:
        """A complex (N,) input [complex128]."""
        if self.xp.is_numpy:
            return np.asarray(a, dtype=np.complex128)
        dev = self._device(a, "complex", np.complex128)
        if dev is not None:
            return dev
        return _convert(self.xp, a, "complex", self._keep)

    def vec3(self, a: ArrayLike) -> Any:
        """A (..., 3) input as a namespace vector."""
        if not self.xp.is_numpy:
            dev = self._device(a, "vec3", np.float64)
            if dev is not None:
                return dev
            return _convert(self.xp, a, "vec3", self._keep)
        a = np.asarray(a, dtype=np.float64)
        if a.shape[-1:] != (3,):
            raise ValueError(f"vectors must have shape (..., 3), got {a.shape}")
        return Vec3(a[..., 0], a[..., 1], a[..., 2])

    def numpy(self, *outs: Any) -> list:
        """Evaluate ``outs`` together (one kernel) and return them as numpy arrays.

        Each output is an array, a :class:`Vec3`/``Array3f64`` (returned (N, 3)), a
        :class:`Mat2` (returned (N, 2, 2)) or :class:`Rows` (returned (M, N)). Entries
        are written into one preallocated array per output (real and imaginary parts
        separately: no packing kernel).
        """
        groups = []
        for o in outs:
            if isinstance(o, Rows):
                groups.append((list(o.entries), "rows"))
            elif isinstance(o, Mat2):
                groups.append((list(o.flat()), (2, 2)))
            elif isinstance(o, Vec3) or (not self.xp.is_numpy
                                         and isinstance(o, self.xp.Array3)):
                groups.append(([o.x, o.y, o.z], (3,)))
            else:
                groups.append(([o], None))
        self.xp.eval(*[e for g, _ in groups for e in g if not _is_constant(e)])
        self._keep.clear()
        out: list[NDArray] = []
        for entries, tail in groups:
            a = self._assemble(entries, tail)
            if any(a is b for b in out):  # one array returned twice (r_rx = r_tx)
                a = a.copy()
            out.append(a)
        return out

    def _parts(self, a: Any) -> tuple[NDArray, NDArray | None]:
        """Host real part and imaginary part (None for a real entry) of one entry."""
        if _is_constant(a) or self.xp.is_numpy:
            a = np.asarray(a)
            return (a.real, a.imag) if np.iscomplexobj(a) else (a, None)
        if self.xp.dr.is_complex_v(a):  # Complex2f64, or Complex2f of a float32 stage
            return (np.asarray(a.real.numpy(), dtype=np.float64),
                    np.asarray(a.imag.numpy(), dtype=np.float64))
        a = np.asarray(a.numpy())
        return (a.astype(np.float64) if a.dtype == np.float32 else a), None

    def _assemble(self, entries: list, tail: tuple[int, ...] | str | None) -> NDArray:
        parts = [self._parts(e) for e in entries]
        shape = np.broadcast_shapes(*(p[0].shape for p in parts))
        if self.n is not None and shape in ((), (1,)):
            shape = (self.n,)  # constants broadcast to the entries
        if tail is None and parts[0][1] is None and parts[0][0].shape == shape:
            return parts[0][0]  # a real array as computed: no copy
        complex_ = any(im is not None for _, im in parts)
        dtype = np.complex128 if complex_ else np.float64
        if tail == "rows":
            out = np.empty((len(entries),) + shape, dtype=dtype)
            columns = [out[j] for j in range(len(entries))]
        else:
            out = np.empty(shape + (len(entries),), dtype=dtype)
            columns = [out[..., j] for j in range(len(entries))]
        for col, (re, im) in zip(columns, parts, strict=True):
            if complex_:
                col.real = re
                col.imag = 0.0 if im is None else im
            else:
                col[...] = re
        if tail == "rows":
            return out
        if tail is None:
            return out[..., 0]
        return out.reshape(shape + tail)


class Rows:
    """Outputs of one kernel stacked as the rows of one (M, N) array (:meth:`Boundary.numpy`)."""

    __slots__ = ("entries",)

    def __init__(self, entries: list) -> None:
        self.entries = list(entries)


def _is_constant(a: Any) -> bool:
    return isinstance(a, int | float | complex)
