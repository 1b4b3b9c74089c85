"""Shared helpers of the hull-echo tests: far-field monostatic / bistatic traces."""

from __future__ import annotations

import numpy as np

from seaecho.constants import C0
from seaecho.tracing.sbr import SBROptions, TraceMesh, trace_signature

F = 10.0e9
LAM = C0 / F
K = 2.0 * np.pi / LAM
#: Far enough that the phase curvature over the test objects is negligible
#: (k D^2 / (2 R) < 1e-3 rad for D < 0.5 m).
FAR = 1.0e6


def db(x):
    return 10.0 * np.log10(np.maximum(np.asarray(x, dtype=float), 1e-300))


def direction(elevation_deg: float, azimuth_deg: float = 0.0) -> np.ndarray:
    """Unit vector from the origin at an elevation above the x-y plane and an azimuth."""
    el, az = np.deg2rad(elevation_deg), np.deg2rad(azimuth_deg)
    return np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])


def trace(mesh, tx_dir, rx_dir=None, n=4.0, eps_r=None, **kw):
    """Signature of a mesh (PEC by default) with T and R far along the given directions."""
    tx = FAR * np.asarray(tx_dir, dtype=float)
    rx = tx if rx_dir is None else FAR * np.asarray(rx_dir, dtype=float)
    numeric = ("max_bounces", "cell", "prune", "edge_refine", "reciprocal")
    opts = SBROptions(rays_per_wavelength=n, **{k: v for k, v in kw.items() if k in numeric})
    rest = {k: v for k, v in kw.items() if k not in numeric}
    return trace_signature(TraceMesh.single(*mesh, eps_r=eps_r), tx, rx, F, options=opts,
                           **rest)
