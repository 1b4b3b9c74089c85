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
  axes), the only per-pulse values of the kernel, enter as one input too (their 33
  components packed: one upload per call, where 33 opaque constants were 33 device
  allocations and fills): while recording, ``vconst`` of the geometry's arrays returns
  the components gathered from it (:class:`_BoundGeometry`);
- a read-only amplitude array (a hull's centres, held between two traces) is converted
  once while it lives; with ``device`` the outputs stay Dr.Jit arrays (the GPU's
  accumulation reads them where they are);
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

import gc
import threading
import weakref
from contextlib import contextmanager
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..backend import Boundary, Mat2, Rows
from .kernels import echo_terms

__all__ = ["FROZEN_LIMIT", "FrozenEchoTerms", "geometry_inputs", "no_garbage_collection"]

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


def geometry_inputs(geometry) -> tuple[NDArray, list, tuple, tuple] | None:
    """The pulse's platform vectors as one input of a recording.

    Returns ``(packed, keys, plain, aliasing)``: the vectors' 33 float64 components in
    one array (tx position, rx position, rx velocity, the two vertical axes, the three
    axes of each antenna: one upload per call, where one opaque constant per component
    was 33 device allocations and fills), each vector's numpy view key (for
    ``_BoundGeometry``), the geometry's numpy arrays (whose unbound views the recording
    refuses) and, for each vector, the index of the first one that is the same memory (a
    recording in which two vectors are one array reads one value for both, as the trace
    does); or None when a vector is not a float64 numpy array (it could not be bound:
    traced).
    """
    tx, rx = geometry.tx, geometry.rx
    plain = (tx.position, rx.position, rx.velocity, tx.rotation, rx.rotation,
             geometry.tx_axes, geometry.rx_axes)
    if not all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in plain):
        return None
    arrays = [tx.position, rx.position, rx.velocity, tx.rotation[:, 2], rx.rotation[:, 2]]
    arrays += [axes[:, j] for axes in (geometry.tx_axes, geometry.rx_axes) for j in range(3)]
    keys = [_view_key(a) for a in arrays]
    aliasing = tuple(keys.index(k) for k in keys)
    packed = np.concatenate([np.asarray(a, dtype=np.float64).reshape(3) for a in arrays])
    return packed, keys, plain, aliasing


def _unpacked(xp, packed, keys: list, aliasing: tuple) -> dict:
    """``_BoundGeometry``'s bindings: each vector's view key -> the three components
    gathered from the packed input (aliases share their first vector's value)."""
    values: list = []
    for i, first in enumerate(aliasing):
        if first < i:
            values.append(values[first])
            continue
        values.append(xp.Array3(*(xp.gather(packed, xp.UInt(3 * i + c))
                                  for c in range(3))))
    return dict(zip(keys, values, strict=True))


@contextmanager
def no_garbage_collection():
    """Python's cyclic garbage collector held off inside the block (a frozen function's
    recording or replay): a collection there frees other Dr.Jit arrays (old tiles'
    buffers, an amplitude upload dropped through its weakref) in the middle of the
    recording, which aborted the process (found with a radar-wide sea)."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if collecting:
            gc.enable()


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
                 directions: bool = False, precision: str = "double",
                 device: bool = False) -> dict[str, Any] | None:
        """:func:`~seaecho.radar.kernels.scatterer_echo` of (K, 3) positions [m],
        velocities [m/s] and (K, 2, 2) scattering amplitudes [m] (float64, complex128),
        the same dict of numpy arrays; None where it cannot be replayed (platform
        vectors that are not float64 numpy arrays, or a kernel Dr.Jit refused to record:
        the caller traces it).

        A read-only ``s`` (a hull's scattering centres, held between two traces) is
        uploaded once while it lives (its four components).
        ``device``: return the replay's Dr.Jit arrays as they are (``tau`` and the
        complex ``amplitudes`` only; nothing read back), for an accumulation on the
        device (:meth:`seaecho.radar.system.RadarSystem.scatterer_echo`).
        """
        if self.error is not None:
            return None
        xp = self.xp
        bound = geometry_inputs(geometry)
        if bound is None:
            return None
        packed, keys, plain, aliasing = bound
        io = Boundary(xp, p.shape[0])
        inputs = {"p": io.vec3(p), "v": io.vec3(v), "s": _amplitude_inputs(xp, io, s),
                  "geometry": io.array(packed)}
        with self._lock:
            self._bound = (geometry, keys, plain)
            try:
                with no_garbage_collection():
                    t = self._frozen(inputs, precision, bool(directions), aliasing)
            except RuntimeError as exc:  # a kernel Dr.Jit cannot record: traced from now on
                self.error = str(exc)
                return None
            finally:
                self._bound = None
        if device:
            return {"tau": t["tau"], "amplitudes": t["amplitudes"], "keep": io}
        names = ["tau", "r_t", "r_r", "g_t", "g_r"] + (["n_i", "n_s"] if directions else [])
        res = io.numpy(*(t[n] for n in names), Rows(t["amplitudes"]))
        out = dict(zip(names, res[:-1], strict=True))
        out["amplitudes"] = res[-1].astype(np.complex128, copy=False)
        return out

    def _record(self, inputs: dict, precision: str, directions: bool,
                aliasing: tuple) -> dict[str, Any]:
        """The frozen function's body: ``echo_terms`` with the geometry bound
        (``aliasing`` is a key of the recording and says which vectors share a value)."""
        geometry, keys, plain = self._bound
        bindings = _unpacked(self.xp, inputs["geometry"], keys, aliasing)
        xp = _BoundGeometry(self.xp, bindings, plain)
        xs = None if precision == "double" else self.xp.with_precision(precision)
        t = echo_terms(xp, self.radar, geometry, inputs["p"], inputs["v"],
                       Mat2(*inputs["s"]), scattering=xs)
        names = ["tau", "r_t", "r_r", "g_t", "g_r"] + (["n_i", "n_s"] if directions else [])
        out = {n: t[n] for n in names}
        out["amplitudes"] = list(t["amplitudes"])
        return out


#: Device copies of read-only amplitude arrays (key -> (weak reference, components,
#: their buffers)).
_AMPLITUDES: dict[tuple, tuple] = {}


def _amplitude_inputs(xp, io: Boundary, s: NDArray) -> list:
    """The four complex components s_hh, s_hv, s_vh, s_vv of (K, 2, 2) amplitudes as
    namespace values: converted at every call, or once while ``s`` lives where it is a
    read-only array (the same values, one upload per hull signature)."""
    if not isinstance(s, np.ndarray) or s.flags.writeable:
        return [io.complex(s[:, a, b]) for a in range(2) for b in range(2)]
    key = (xp.name, id(s))
    hit = _AMPLITUDES.get(key)
    if hit is not None and hit[0]() is s:
        return hit[1]
    held = Boundary(xp, s.shape[0])  # keeps the aligned buffers (LLVM aliases them)
    comps = [held.complex(s[:, a, b]) for a in range(2) for b in range(2)]
    _AMPLITUDES[key] = (weakref.ref(s, lambda _, key=key: _AMPLITUDES.pop(key, None)),
                        comps, held)
    return comps
