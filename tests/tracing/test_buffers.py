"""Aligned buffers for the Dr.Jit kernels (seaecho.backend.aligned)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.backend import ALIGNMENT, aligned


@settings(max_examples=30, deadline=None)
@given(n=st.integers(0, 300), offset=st.integers(0, 7),
       dtype=st.sampled_from([np.float64, np.float32]))
def test_aligned_copy_keeps_values_and_starts_on_a_cache_line(n, offset, dtype):
    base = np.random.default_rng(n).normal(size=(n + 8, 3))
    a = base[offset:offset + n, 1]  # strided, arbitrarily aligned
    out = aligned(a, dtype)
    assert out.dtype == dtype and out.flags.c_contiguous
    assert n == 0 or out.ctypes.data % ALIGNMENT == 0  # (an empty view has no data)
    np.testing.assert_array_equal(out, a.astype(dtype))

