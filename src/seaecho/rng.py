"""Random streams derived from the scene's seed.

Every random draw in seaecho comes from a :class:`numpy.random.Generator` made here, so a
scene file and a seed give the same output bit for bit. Draws that belong to a pulse or a
time step come from ``generator(seed, stream, index)``: a :class:`~numpy.random.SeedSequence`
with a spawn key ``(stream id, index...)``, so pulses can be computed in any order, in
parallel or on other machines, with identical results (docs/conventions.md).
"""

from __future__ import annotations

import numpy as np

#: Named streams; the numbers are part of the file format of reproducibility: never reuse
#: or renumber one.
STREAMS: dict[str, int] = {
    "surface": 0,
    "speckle": 1,
    "platform": 2,
    "noise": 3,
    "targets": 4,
}


def generator(seed: int, stream: str, *index: int) -> np.random.Generator:
    """The generator of ``stream`` (and optional ``index``, e.g. a pulse) for ``seed``."""
    if stream not in STREAMS:
        raise ValueError(f"stream = {stream!r}: unknown; allowed: {sorted(STREAMS)}")
    if any(int(i) < 0 for i in index):
        raise ValueError(f"index = {index}: must be >= 0")
    key = (STREAMS[stream], *(int(i) for i in index))
    return np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=key))


__all__ = ["STREAMS", "generator"]
