"""Reductions of a run's dataset to a few numbers (a sweep's ``--reduce``).

:func:`reduce_run` gives, per channel, the mean NRCS map, the mean clutter intensity over
the range gates the sea fills (:func:`clutter_gates`) and the K-distribution shape of those
intensities (:mod:`seaecho.processing.statistics`). It takes any dataset with the variables
of a raw run (netCDF, Zarr or in memory), so that a sweep's workers reduce a case without
writing it.
"""

from __future__ import annotations

import numpy as np

from ..constants import C0
from .statistics import k_shape_moments, k_shape_zlogz

__all__ = ["clutter_gates", "reduce_run"]


def clutter_gates(ds) -> np.ndarray:
    """Mask (pulse, fast_time) of the range gates filled by the sea tile.

    A gate is kept when its delay lies at least half a delay resolution inside the span
    of the bistatic delays (|p - tx| + |p - rx|) / c of the grid nodes p (z = 0) at that
    pulse: 0.5 / bandwidth (the pulse length without modulation), about the -4 dB half
    width of the compressed sinc main lobe, so that a kept gate's main lobe lies on sea.
    """
    x, y = ds["x"].values, ds["y"].values
    sx = max(1, x.size // 64)
    sy = max(1, y.size // 64)
    xs = np.unique(np.concatenate([x[::sx], x[-1:]]))
    ys = np.unique(np.concatenate([y[::sy], y[-1:]]))
    gx, gy = np.meshgrid(xs, ys)
    nodes = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=-1)  # (N, 3)
    tx, rx = ds["tx_position"].values, ds["rx_position"].values  # (P, 3)
    path = (np.linalg.norm(nodes[None] - tx[:, None], axis=-1)
            + np.linalg.norm(nodes[None] - rx[:, None], axis=-1))  # (P, N)
    bw = float(ds.attrs.get("waveform_bandwidth_hz", 0.0))
    res = 1.0 / bw if bw > 0 else float(ds.attrs["waveform_duration_s"])
    lo = path.min(axis=1) / C0 + 0.5 * res
    hi = path.max(axis=1) / C0 - 0.5 * res
    t = ds["fast_time"].values
    return (t[None, :] >= lo[:, None]) & (t[None, :] <= hi[:, None])


def reduce_run(ds) -> dict[str, float]:
    """Reduced products of a run's dataset (netCDF, Zarr or in memory).

    Per channel ``c`` (HH, HV, VH, VV):

    * ``sigma0_<c>``: mean of the NRCS map ``sigma0`` over the cells [m^2/m^2] (the
      scene's sigma0 at the sigma-map pulse; NaN without sea clutter);
    * ``power_<c>``: mean intensity <z> = <|compressed|^2> over the sea's range gates
      (:func:`clutter_gates`) of every pulse [W];
    * ``k_shape_zlogz_<c>``, ``k_shape_moments_<c>``: K-distribution shape nu of the
      same intensities (:func:`seaecho.processing.statistics.k_shape_zlogz`, eq ST4,
      Blacknell & Tough 2001; :func:`~seaecho.processing.statistics.k_shape_moments`,
      eq ST3); NaN where the estimator has no value (e.g. sub-exponential tails);
    * ``n_gates``: number of (pulse, gate) samples used.

    Targets in the scene are part of the intensities: reduce scenes without targets for
    clutter statistics.
    """
    out: dict[str, float] = {}
    channels = [str(c) for c in ds["channel"].values]
    sea = "sigma0" in ds.variables
    if sea:
        pols = [str(p) for p in ds["polarisation"].values]
        s0 = ds["sigma0"].values
        for c in channels:
            out[f"sigma0_{c}"] = float(np.mean(s0[pols.index(c)]))
        gates = clutter_gates(ds)
    else:
        for c in channels:
            out[f"sigma0_{c}"] = float("nan")
        gates = np.ones((ds.sizes["pulse"], ds.sizes["fast_time"]), dtype=bool)
    out["n_gates"] = float(gates.sum())
    comp = ds["compressed"].values
    for k, c in enumerate(channels):
        z = np.abs(comp[:, k, :][gates]) ** 2
        out[f"power_{c}"] = float(z.mean()) if z.size else float("nan")
        for name, fn in (("k_shape_zlogz", k_shape_zlogz), ("k_shape_moments",
                                                             k_shape_moments)):
            try:
                out[f"{name}_{c}"] = float(fn(z[z > 0]))
            except ValueError:
                out[f"{name}_{c}"] = float("nan")
    return out
