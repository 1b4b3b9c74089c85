"""The pulse arrays of a run's dataset, whatever its file format: their dimensions, their
attributes and the blocks of consecutive pulses they are computed and written in.

Shared by the netCDF writer (:mod:`seaecho.io.run`) and the Zarr store
(:mod:`seaecho.io.zarr_run`), which both write ``raw`` and ``compressed`` with these
dimensions and attributes.
"""

from __future__ import annotations

#: Dimensions of ``raw`` and ``compressed`` (a multistatic run adds ``receiver``).
PULSE_DIMS = ("pulse", "channel", "fast_time")

#: Attributes of the ``raw`` and ``compressed`` variables (both file formats).
RAW_ATTRS = {"units": "sqrt(W)", "long_name": "complex baseband raw echo"}
COMPRESSED_ATTRS = {"units": "sqrt(W)", "long_name": "range-compressed echo"}


def blocks_of(n_pulses: int, size: int) -> list[tuple[int, int]]:
    """``[(start, stop), ...]`` of consecutive blocks of ``size`` pulses."""
    return [(a, min(a + size, n_pulses)) for a in range(0, n_pulses, size)]


__all__ = ["COMPRESSED_ATTRS", "PULSE_DIMS", "RAW_ATTRS", "blocks_of"]
