"""Run-time guard: no pulse writes a non-finite sample.

:func:`check_pulse` is called where a pulse's echoes are summed
(:meth:`seaecho.simulation.Simulation.pulse`), so it knows which scatterer set each
echo came from. If a scatterer's delay or amplitude, or a sample of the summed pulse, is
NaN or infinite, it raises :class:`NonFiniteEchoError` naming the pulse and the
scatterers (sea facets with their count and first index, the point targets by name, or
the scattering centres of a hull, ``[[objects]]`` with ``scatterer = true``, by name);
the CLI prints it and exits with status 2, and the run's temporary file is removed, so
no file with NaN is left. :func:`check_dataset` does the same for everything else the run
writes (tracks, surface, sigma maps), once, before writing. The scene checks of
``seaecho.checks.preflight`` refuse the degenerate geometries known to produce them; this guard
catches any that remain.

Cost: one sum per array on the usual (finite) path, O(K) for K scatterers, small against
the pulse's own O(K) work; the per-element search only runs once something is wrong.
"""

from __future__ import annotations

import json

import numpy as np

from ..config import SceneError
from ..config.base import short_repr


class NonFiniteEchoError(SceneError):
    """A pulse produced NaN or Inf: the run stops (CLI exit status 2), no file is left."""


def _finite(a) -> bool:
    """All elements finite (fast path: the sum of finite values is finite unless it
    overflows; then the elements are checked one by one). A list or tuple (one array per
    channel) is checked array by array: stacking it would copy every channel."""
    if isinstance(a, list | tuple) and any(isinstance(x, np.ndarray) for x in a):
        return all(_finite(x) for x in a)
    a = np.asarray(a)
    if a.size == 0:
        return True
    with np.errstate(over="ignore", invalid="ignore"):
        if np.isfinite(a.sum()):
            return True
    return bool(np.isfinite(a).all())


def _bad_columns(echo) -> np.ndarray:
    """Indices of the scatterers whose delay or amplitude (any channel) is not finite."""
    bad = ~np.isfinite(np.asarray(echo.tau))
    amp = np.asarray(echo.amplitudes)
    if amp.ndim == 2:
        bad |= ~np.isfinite(amp).all(axis=0)
    return np.flatnonzero(bad)


def echo_kinds(sim, pulse: int) -> list[str]:
    """Names of the scatterer sets of :meth:`Simulation.pulse`, in its order: the sea
    facets (if sea clutter is on), the point targets (if any), then one per hull
    (``[[objects]]`` with ``scatterer = true``) that has scattering centres at ``pulse``."""
    kinds = []
    if getattr(sim, "sea", None) is not None:
        kinds.append("sea facets")
    targets = sim.models.radar.targets
    if targets is not None and len(targets):
        kinds.append("point targets")
    hulls = getattr(sim, "hulls", None)
    if hulls is not None:  # HullEchoes.echoes skips the hulls without centres
        kinds += [f"hull '{h.name}'" for i, h in enumerate(hulls.hulls)
                  if len(hulls.signature(i, pulse).centres)]
    return kinds


def _host(echo):
    """A host (numpy) copy of a device echo (``DeviceEcho.to_host``), else the echo."""
    return echo.to_host() if hasattr(echo, "to_host") else echo


def check_pulse(sim, pulse: int, raw, echoes) -> None:
    """Raise :class:`NonFiniteEchoError` if ``pulse``'s echoes or samples are not finite.

    Parameters
    ----------
    sim : seaecho.simulation.Simulation
        The simulation (its radar model names the targets, its hulls the objects).
    pulse : int
        Pulse index.
    raw : ndarray (C, n_samples) complex
        The pulse's summed samples [sqrt(W)].
    echoes : list of ScattererEcho or DeviceEcho
        The scatterer sets summed into ``raw``, in the order of :func:`echo_kinds`. A
        device echo (GPU) is only examined, copied to the host, once ``raw`` is found
        non-finite.
    """
    raw_ok = _finite(raw)
    problems = []
    for i, echo in enumerate(echoes):
        if hasattr(echo, "to_host"):
            if raw_ok:
                continue
            echo = _host(echo)
        if _finite(echo.tau) and _finite(echo.amplitudes):
            continue
        kinds = echo_kinds(sim, pulse)
        kind = kinds[i] if i < len(kinds) else f"scatterer set {i}"
        cols = _bad_columns(echo)
        if kind == "point targets":
            all_names = sim.models.radar.targets.names
            names = [all_names[j] for j in cols[:5]]
            what = "point target" + ("s " if len(cols) > 1 else " ") + ", ".join(
                short_repr(n) for n in names) + (" ..." if len(cols) > 5 else "")
        elif kind.startswith("hull"):
            what = f"{cols.size} scattering centres of {kind} ([[objects]] scatterer)"
        else:
            what = f"{cols.size} {kind} (first index {cols[0] if cols.size else '?'})"
        problems.append(f"non-finite delay or amplitude from {what}")
    if not raw_ok:
        n_bad = int((~np.isfinite(np.asarray(raw))).sum())
        problems.append(f"{n_bad} non-finite samples in the summed echo"
                        + ("" if len(problems) else " (all scatterers were finite: the "
                           "accumulation or the thermal noise)"))
    if problems:
        t = float(sim.radar.emission_time(pulse))
        raise NonFiniteEchoError(
            f"pulse {pulse} (t = {t:.6g} s): " + "; ".join(problems)
            + ". The run is stopped and no file is written: the scene's geometry or values "
            "are outside what the models can evaluate (see `seaecho check`)")


def check_dataset(ds) -> None:
    """Raise :class:`NonFiniteEchoError` naming every float variable of the run's static
    dataset (tracks, surface, sigma maps, ...) that holds NaN or Inf, before it is
    written."""
    bad = [name for name, v in ds.data_vars.items()
           if v.dtype.kind in "fc" and not _finite(v.values)]
    if bad:
        raise NonFiniteEchoError(
            f"non-finite values in {', '.join(bad[:8])}" + (" ..." if len(bad) > 8 else "")
            + ". The run is stopped and no file is written: the scene's geometry or values "
            "are outside what the models can evaluate (see `seaecho check`)")


def _no_truth(ds) -> np.ndarray:
    """(channel, y, x): outside the sea tile, or a channel the raw's sigma map does not
    hold (circular, slanted bases: the map is in the linear HH, HV, VH, VV)."""
    linear = np.isin(ds["channel"].values, ds["polarisation"].values)
    return ~linear[:, None, None] | (ds["tile"].values == 0)[None]


def _no_data(ds) -> np.ndarray:
    """(y, x): a pixel without data (``valid`` = 0: K < 0.1 max K, or its echoes outside
    the receive window), where a calibrated product that overflowed is NaN."""
    return ds["valid"].values == 0


def _no_data_look(ds) -> np.ndarray:
    """(y_look, x_look): a look block holding a pixel without data."""
    from ..imaging.speckle import multilook

    looks = tuple(int(v) for v in json.loads(ds.attrs["image_json"])["looks"])
    return multilook(_no_data(ds)[None].astype(float), looks)[0] > 0


#: Image variables whose NaN marks an undefined pixel, and the pixels where it may:
#: the calibrated image where no pulse is weighted (K = 0); sigma0, the Pauli powers and
#: A_eff where A_eff is undefined (NaN: K = 0, or an aperture that does not turn); the
#: truth outside the simulated sea tile and in channels it does not hold; and every
#: calibrated product at the pixels without data (``valid`` = 0), where a value beyond
#: float64 is NaN (``seaecho.imaging.focus._calibrated``).
UNDEFINED_PIXELS = {
    "image": lambda ds: (ds["gain"].values == 0) | _no_data(ds),
    "resolution_area": lambda ds: True,
    "sigma0": lambda ds: np.isnan(ds["resolution_area"].values) | _no_data(ds),
    "pauli": lambda ds: np.isnan(ds["resolution_area"].values) | _no_data(ds),
    "sigma0_filtered": _no_data,
    "pauli_filtered": _no_data,
    "sigma0_multilook": _no_data_look,
    "sigma0_truth": _no_truth,
}


def image_problems(ds) -> list[str]:
    """What is wrong with a focused image dataset (``seaecho.imaging.focus``): every float
    variable holding +-Inf, and NaN anywhere but the undefined pixels of
    :data:`UNDEFINED_PIXELS` (where NaN is the documented marker)."""
    out = []
    for name, v in ds.data_vars.items():
        if v.dtype.kind not in "fc" or _finite(v.values):
            continue
        a = np.asarray(v.values)
        n_inf = int(np.isinf(a).sum())
        nan = np.isnan(a)
        if name in UNDEFINED_PIXELS and nan.any():
            nan &= ~np.broadcast_to(UNDEFINED_PIXELS[name](ds), a.shape)
        n_nan = int(nan.sum())
        if n_inf or n_nan:
            what = [f"{n} {kind}" for n, kind in ((n_inf, "Inf"), (n_nan, "NaN"))
                    if n]
            out.append(f"{name} ({' and '.join(what)} of {a.size} values"
                       + (" at defined pixels" if n_nan and name in UNDEFINED_PIXELS
                          else "") + ")")
    return out


def check_image(ds, source: str = "") -> None:
    """Raise :class:`NonFiniteEchoError` if :func:`image_problems` finds anything, before
    the image is written."""
    bad = image_problems(ds)
    if bad:
        raise NonFiniteEchoError(
            (f"image of {source}: " if source else "image: ")
            + "non-finite values in " + "; ".join(bad)
            + ". The image is not written: the focusing overflowed or divided by zero "
            "(see `seaecho check`)")


__all__ = ["NonFiniteEchoError", "UNDEFINED_PIXELS", "check_dataset", "check_image",
           "check_pulse", "echo_kinds", "image_problems"]
