"""The scatterers' radar equation as a recorded kernel, replayed at every pulse.

:meth:`seaecho.radar.system.RadarSystem.scatterer_echo` evaluates eqs (R1) and (R3)
(:func:`seaecho.radar.kernels.echo_terms`) for a set of scatterers (a hull's scattering
centres, point targets, land facets, the sea's reference path) as one Dr.Jit kernel.
Traced, Dr.Jit runs the Python of ``echo_terms`` at every pulse to build that kernel
(about 2 ms of host time per call on an H100's host, more than the kernel itself).
:class:`FrozenEchoTerms` records it once with ``drjit.freeze`` and replays the recording
at the next pulses, as :class:`seaecho.radar.resident.ResidentSea` does for the sea's
fused kernel:

- the scatterers' positions, velocities and scattering amplitudes enter as the recording's
  inputs (Dr.Jit arrays made at the boundary, :class:`seaecho.backend.Boundary`);
- the pulse's platform vectors (positions, receiver velocity, vertical axes, antenna
  axes), the only per-pulse values of the kernel, enter as inputs too: while recording,
  ``vconst`` of the geometry's arrays returns those inputs
  (:class:`_BoundGeometry`);
- the working precision, whether the directions are asked for and which of the
  platform vectors are one and the same array are arguments of the recording: a change
  of any of them records again, as does a change of an input's type or a set of one
  scatterer (Dr.Jit's rules for width-1 inputs); another number of scatterers replays
  the same recording (Dr.Jit sizes the recorded kernels by their inputs), which matters
  for the sets whose size changes from pulse to pulse (the land's facets in the beam, a
  hull's centres above the horizon).

A replay runs the same kernel on the same values as the trace: the same bytes (tests,
on ``drjit.llvm``). The radar's constants (carrier, power, antennas, channels) are
constants of the recording, which belongs to its :class:`RadarSystem`.
"""

from __future__ import annotations

import threading
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..backend import Boundary, Mat2, Rows
from .kernels import echo_terms

__all__ = ["FROZEN_LIMIT", "FrozenEchoTerms", "geometry_inputs"]

#: Recordings a :class:`FrozenEchoTerms` keeps (one per precision, directions flag and
#: aliasing of the platform vectors, input types; the oldest is dropped beyond it).
FROZEN_LIMIT = 16
#: Recordings after which Dr.Jit warns (a caller whose inputs change type at every pulse
#: would record at every pulse: traced would be cheaper).
FROZEN_WARN_AFTER = 16


def _view_key(a: Any) -> tuple | None:
    """(address, shape, strides) of a numpy array: the same for every view of the same
    entries."""
    if not isinstance(a, np.ndarray):
        return None
    return (a.__array_interface__["data"][0], a.shape, a.strides)


class _BoundGeometry:
    """A Dr.Jit namespace whose ``vconst`` returns bound values for given numpy arrays.

    While a frozen pulse is recorded, the platform vectors of the pulse's geometry are
    the frozen function's inputs: ``vconst(a)`` of one of those arrays, or of a view of
    the same entries (``np.asarray``, a column), returns its input instead of a constant
    that the recording would keep. Every other attribute is the namespace's.
    """

    def __init__(self, xp: Any, bindings: dict[tuple, Any], arrays: tuple) -> None:
        self._xp = xp
        self._bindings = bindings
        self._arrays = arrays

    def __getattr__(self, name: str) -> Any:
        return getattr(self._xp, name)

    def vconst(self, a: Any) -> Any:
        hit = self._bindings.get(_view_key(a))
        if hit is not None:
            return hit
        if isinstance(a, np.ndarray) and any(np.shares_memory(a, b) for b in self._arrays):
            raise RuntimeError("a platform vector of the pulse would be frozen as a "
                               "constant (a view of the geometry that is not bound)")
        return self._xp.vconst(a)


def geometry_inputs(xp, geometry) -> tuple[dict[str, Any], dict, tuple, tuple] | None:
    """The pulse's platform vectors as Dr.Jit inputs of a recording.

    Returns ``(values, bindings, plain, aliasing)``: the named Dr.Jit values, the map
    from each numpy array's view key to its value (for ``_BoundGeometry``), the
    geometry's numpy arrays (whose unbound views the recording refuses) and, for each
    named vector, the index of the first one that is the same memory (a recording in
    which two vectors are one array reads one input for both); or None when a vector is
    not a float64 numpy array (it could not be bound: traced).
    """
    tx, rx = geometry.tx, geometry.rx
    plain = (tx.position, rx.position, rx.velocity, tx.rotation, rx.rotation,
             geometry.tx_axes, geometry.rx_axes)
    if not all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in plain):
        return None
    arrays = {"tx_position": tx.position, "rx_position": rx.position,
              "rx_velocity": rx.velocity, "tx_up": tx.rotation[:, 2],
              "rx_up": rx.rotation[:, 2]}
    for side, axes in (("tx", geometry.tx_axes), ("rx", geometry.rx_axes)):
        for j in range(3):
            arrays[f"{side}_axis{j}"] = axes[:, j]
    keys = [_view_key(a) for a in arrays.values()]
    aliasing = tuple(keys.index(k) for k in keys)
    values = {name: xp.vconst(a) for name, a in arrays.items()}
    bindings = {key: values[name] for key, name in zip(keys, arrays, strict=True)}
    return values, bindings, plain, aliasing


class FrozenEchoTerms:
    """:func:`seaecho.radar.kernels.scatterer_echo` recorded once, replayed per pulse
    (module docstring).

    Parameters
    ----------
    xp : seaecho.backend.DrJitNamespace
        ``drjit.llvm`` or ``drjit.cuda``.
    radar : RadarSystem
        Its antennas, channels, carrier and power are constants of the recordings.
    """

    def __init__(self, xp, radar) -> None:
        self.xp = xp
        self.radar = radar
        self._frozen = xp.dr.freeze(self._record, limit=FROZEN_LIMIT,
                                    warn_after=FROZEN_WARN_AFTER)
        self._bound: tuple | None = None
        self._lock = threading.Lock()  # one recording or replay at a time (``_bound``)
        #: why freezing was given up (a recording Dr.Jit refused), or None
        self.error: str | None = None

    @property
    def recordings(self) -> int:
        """Number of recordings made so far [-]."""
        return int(self._frozen.n_recordings)

    def __call__(self, geometry, p: NDArray, v: NDArray, s: NDArray,
                 directions: bool = False, precision: str = "double"
                 ) -> dict[str, NDArray] | None:
        """:func:`~seaecho.radar.kernels.scatterer_echo` of (K, 3) positions [m],
        velocities [m/s] and (K, 2, 2) scattering amplitudes [m] (float64, complex128),
        the same dict of numpy arrays; None where it cannot be replayed (platform
        vectors that are not float64 numpy arrays, or a kernel Dr.Jit refused to record:
        the caller traces it)."""
        if self.error is not None:
            return None
        xp = self.xp
        bound = geometry_inputs(xp, geometry)
        if bound is None:
            return None
        values, bindings, plain, aliasing = bound
        io = Boundary(xp, p.shape[0])
        inputs = {"p": io.vec3(p), "v": io.vec3(v),
                  "s": [io.complex(s[:, a, b]) for a in range(2) for b in range(2)],
                  "geometry": values}
        with self._lock:
            self._bound = (geometry, bindings, plain)
            try:
                t = self._frozen(inputs, precision, bool(directions), aliasing)
            except RuntimeError as exc:  # a kernel Dr.Jit cannot record: traced from now on
                self.error = str(exc)
                return None
            finally:
                self._bound = None
        names = ["tau", "r_t", "r_r", "g_t", "g_r"] + (["n_i", "n_s"] if directions else [])
        res = io.numpy(*(t[n] for n in names), Rows(t["amplitudes"]))
        out = dict(zip(names, res[:-1], strict=True))
        out["amplitudes"] = res[-1].astype(np.complex128, copy=False)
        return out

    def _record(self, inputs: dict, precision: str, directions: bool,
                aliasing: tuple) -> dict[str, Any]:
        """The frozen function's body: ``echo_terms`` with the geometry bound
        (``aliasing`` is a key of the recording only)."""
        geometry, bindings, plain = self._bound
        xp = _BoundGeometry(self.xp, bindings, plain)
        xs = None if precision == "double" else self.xp.with_precision(precision)
        t = echo_terms(xp, self.radar, geometry, inputs["p"], inputs["v"],
                       Mat2(*inputs["s"]), scattering=xs)
        names = ["tau", "r_t", "r_r", "g_t", "g_r"] + (["n_i", "n_s"] if directions else [])
        out = {n: t[n] for n in names}
        out["amplitudes"] = list(t["amplitudes"])
        return out
