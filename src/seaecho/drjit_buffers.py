"""Contiguous, 64-byte-aligned copies of numpy columns for Dr.Jit / Mitsuba kernels.

Dr.Jit's LLVM backend maps a numpy buffer without copying and compiles a kernel variant
that depends on whether each input is 64-byte aligned (aligned vector loads). numpy's
allocator gives 16-byte alignment, so the alignment of per-pulse buffers varies at random
and with it the kernel's hash: about one pulse in two recompiled a kernel (30-90 ms each,
measured on the radar, scattering and frames kernels at 522k facets). Passing every
input through :func:`aligned` keeps one compiled kernel per run.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["ALIGNMENT", "aligned"]

#: Byte alignment of the buffers (a cache line; the widest AVX-512 load).
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
