"""Random streams derived from the scene's seed.

Every random draw in seaecho comes from a stream of the scene's seed made here, so a
scene file and a seed give the same output bit for bit. Draws that belong to a pulse or a
time step come from ``generator(seed, stream, index)``: a :class:`numpy.random.Generator`
of a :class:`~numpy.random.SeedSequence` with a spawn key ``(stream id, index...)``, so
pulses can be computed in any order, in parallel or on other machines, with identical
results (docs/conventions.md).

The per-facet speckle of a held sea (millions of deviates per sea state) comes instead
from :func:`facet_gaussians`: a counter-based generator, Philox4x32-7 (Salmon et al.
2011), keyed by the same spawn key and counted by facet and draw, evaluated in one
kernel on the scene's Dr.Jit back end (its threads, or the GPU) where it runs. A facet's
draw depends only on (seed, stream, block, facet, draw), whatever the order of the
pulses, the number of threads or workers, or the facets drawn beside it.

References
----------
.. [1] J. K. Salmon, M. A. Moraes, R. O. Dror and D. E. Shaw, "Parallel random numbers:
   as easy as 1, 2, 3", Proc. SC11 (2011), doi:10.1145/2063384.2063405 (Philox4x32 and
   its known-answer vectors).
.. [2] G. E. P. Box and M. E. Muller, "A note on the generation of random normal
   deviates", Ann. Math. Statist. 29(2), 610-611 (1958).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

#: Named streams; the numbers are part of the file format of reproducibility: never reuse
#: or renumber one.
STREAMS: dict[str, int] = {
    "surface": 0,
    "speckle": 1,
    "platform": 2,
    "noise": 3,
    "targets": 4,
    # per-facet speckle of the unresolved-tilt quadrature nodes (held sea: per block;
    # evolving sea: index 0, one static phase per facet and node)
    "speckle-tilt": 5,
    # per-facet speckle of breaking zones (held sea: per block)
    "breaking": 6,
    # anchor draws of the evolving speckle: (family, anchor index)
    "speckle-evolution": 7,
    # the transmitted phase of a random-phase (magnetron) radar: pulse index
    "transmit-phase": 8,
    # fluctuating point targets (Swerling cases): counter (target, dwell or pulse index)
    "target-fluctuation": 9,
    # land clutter (docs/land.md): per-facet Weibull power and phase, index the
    # [[land]] entry
    "land": 10,
    # the seed of each tile of a radar-wide sea ([sea] coverage = "radar"): index (level,
    # zigzag(ix), zigzag(iy)) of the tile in its level's lattice
    "sea-tile": 11,
}

#: Philox4x32 constants (Salmon et al. 2011, table 2 and section 5.1): round multipliers
#: and the Weyl key increments.
_PHILOX_M = (0xD2511F53, 0xCD9E8D57)
_PHILOX_W = (0x9E3779B9, 0xBB67AE85)
#: Rounds of Philox4x32 (Dr.Jit's default; Random123 tests 7 and 10).
PHILOX_ROUNDS = 7


def _spawn_key(stream: str, index: tuple) -> tuple[int, ...]:
    if stream not in STREAMS:
        raise ValueError(f"stream = {stream!r}: unknown; allowed: {sorted(STREAMS)}")
    if any(int(i) < 0 for i in index):
        raise ValueError(f"index = {index}: must be >= 0")
    return (STREAMS[stream], *(int(i) for i in index))


def generator(seed: int, stream: str, *index: int) -> np.random.Generator:
    """The generator of ``stream`` (and optional ``index``, e.g. a pulse) for ``seed``."""
    key = _spawn_key(stream, index)
    return np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=key))


def philox_key(seed: int, stream: str, *index: int) -> int:
    """The 64-bit Philox key of ``stream`` (and ``index``) for ``seed`` [-]: the first
    word of the :class:`~numpy.random.SeedSequence` that :func:`generator` seeds from."""
    ss = np.random.SeedSequence(int(seed), spawn_key=_spawn_key(stream, index))
    return int(ss.generate_state(1, np.uint64)[0])


def philox4x32(key: int, counter: tuple) -> tuple[NDArray[np.uint32], ...]:
    """Philox4x32 with :data:`PHILOX_ROUNDS` rounds in numpy: four uint32 words per counter.

    Parameters
    ----------
    key : int
        64-bit key; its high word is Random123's ``k0``, its low word ``k1`` (the
        convention of Dr.Jit's ``Philox4x32(seed, ...)``).
    counter : (c0, c1, c2, c3)
        The 128-bit counter as four uint32 words (arrays broadcast against each other).

    Returns
    -------
    (x0, x1, x2, x3) : uint32 arrays

    References
    ----------
    Salmon et al. (2011), section 5.1: each round maps (x0, x1, x2, x3) to
    (hi(M1 x2) ^ x1 ^ k0, lo(M1 x2), hi(M0 x0) ^ x3 ^ k1, lo(M0 x0)), then adds the
    Weyl increments to the key.
    """
    m32 = np.uint64(0xFFFFFFFF)
    c = [np.asarray(v, dtype=np.uint64) & m32 for v in counter]
    c = list(np.broadcast_arrays(*c))
    k0, k1 = (int(key) >> 32) & 0xFFFFFFFF, int(key) & 0xFFFFFFFF
    for _ in range(PHILOX_ROUNDS):
        p0 = c[0] * np.uint64(_PHILOX_M[0])  # exact: 32 x 32 bits fit in 64
        p1 = c[2] * np.uint64(_PHILOX_M[1])
        c = [(p1 >> np.uint64(32)) ^ c[1] ^ np.uint64(k0), p1 & m32,
             (p0 >> np.uint64(32)) ^ c[3] ^ np.uint64(k1), p0 & m32]
        k0 = (k0 + _PHILOX_W[0]) & 0xFFFFFFFF
        k1 = (k1 + _PHILOX_W[1]) & 0xFFFFFFFF
    return tuple(v.astype(np.uint32) for v in c)


def _normal_pair_numpy(words: tuple) -> tuple[NDArray, NDArray]:
    """Two standard normal deviates from one Philox output (Box-Muller, as Dr.Jit's
    ``Philox4x32.next_float64x2_normal``)."""
    x0, x1, x2, x3 = (w.astype(np.uint64) for w in words)
    one = np.uint64(0x3FF0000000000000)
    u = [(((hi << np.uint64(32)) | lo) >> np.uint64(12) | one).view(np.float64) - 1.0
         for lo, hi in ((x0, x1), (x2, x3))]
    angle = 2.0 * np.pi * u[1]
    scale = np.sqrt(-np.log2(1.0 - u[0])) * np.sqrt(2.0 * np.log(2.0))
    return np.cos(angle) * scale, np.sin(angle) * scale


def uniform_pair(seed: int, stream: str, counter: tuple, *index: int
                 ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Two independent uniform deviates in (0, 1] per counter: Philox4x32-7 at key
    :func:`philox_key` ``(seed, stream, *index)``, each deviate from 53 bits of two of
    its four words (as :func:`facet_gaussians`). A pure function of (seed, stream,
    index, counter): any subset of counters can be drawn in any order.

    Parameters
    ----------
    seed : int
        The scene's seed.
    stream : str
        One of :data:`STREAMS`.
    counter : (c0, c1, c2, c3)
        uint32 words (arrays broadcast against each other).
    *index : int
        Stream index.

    Returns
    -------
    (u1, u2) : float64 arrays in (0, 1]
    """
    words = philox4x32(philox_key(seed, stream, *index), counter)
    x0, x1, x2, x3 = (w.astype(np.uint64) for w in words)
    scale = 2.0 ** -53
    return tuple(1.0 - (((hi << np.uint64(32)) | lo) >> np.uint64(11)).astype(np.float64)
                 * scale for lo, hi in ((x0, x1), (x2, x3)))


def facet_gaussians(n: int, count: int, seed: int, stream: str, *index: int,
                    xp: Any = None) -> list[Any]:
    """``count`` circular complex Gaussians of unit variance per facet, each of shape (n,).

    Draw ``j`` of facet ``i`` is ``(X + j Y) / sqrt(2)`` with ``(X, Y)`` the Box-Muller
    pair of Philox4x32-7 at key :func:`philox_key` ``(seed, stream, *index)`` and counter
    ``(i, 0, 0, j)``: a pure function of (seed, stream, index, facet, draw).

    Parameters
    ----------
    n : int
        Number of facets (< 2^32).
    count : int
        Draws per facet.
    seed : int
        The scene's seed.
    stream : str
        One of :data:`STREAMS`.
    *index : int
        Stream index (the block of held pulses).
    xp : DrJitNamespace or NumpyNamespace, optional
        Back end: a Dr.Jit namespace evaluates the draws in one kernel there and
        returns its evaluated ``Complex`` arrays; None or numpy returns read-only
        numpy complex arrays. The uint32 words are the same on every back end; the
        deviates agree to a few ulps (Dr.Jit's and numpy's ``log2``, ``sin``, ``cos``).

    Returns
    -------
    list of ``count`` arrays
    """
    n, count = int(n), int(count)
    if not 0 <= n < 2**32:
        raise ValueError(f"n = {n} facets: must be in [0, 2^32)")
    if count < 0:
        raise ValueError(f"count = {count}: must be >= 0")
    key = philox_key(seed, stream, *index)
    r = np.sqrt(0.5)
    if xp is None or xp.is_numpy:
        out = []
        for j in range(count):
            x, y = _normal_pair_numpy(philox4x32(key, (np.arange(n), 0, 0, j)))
            g = np.empty(n, dtype=np.complex128)
            g.real, g.imag = x * r, y * r
            g.setflags(write=False)
            out.append(g)
        return out
    m, dr = xp.module, xp.dr
    # the key as an opaque value, not a literal: one kernel serves every block and stream
    rng = m.Philox4x32(dr.opaque(m.UInt64, key), dr.arange(m.UInt32, n), m.UInt32(0),
                       m.UInt32(0), PHILOX_ROUNDS)
    out = []
    for _ in range(count):
        v = rng.next_float64x2_normal()
        out.append(xp.Complex(v[0] * r, v[1] * r))
    if out:
        dr.eval(*out)
    return out


__all__ = ["PHILOX_ROUNDS", "STREAMS", "facet_gaussians", "generator", "philox4x32",
           "philox_key", "uniform_pair"]
