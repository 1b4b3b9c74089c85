"""Former home of :func:`seaecho.backend.aligned` (64-byte-aligned buffers for Dr.Jit).

The Dr.Jit set-up lives in :mod:`seaecho.backend`; this alias keeps the old import path
working for code not yet updated.
"""

from __future__ import annotations

from ..backend import ALIGNMENT, aligned

__all__ = ["ALIGNMENT", "aligned"]
