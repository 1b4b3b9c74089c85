"""``[run]`` section: seed, output and the times at which to compute."""

from __future__ import annotations

from pydantic import Field, field_validator

from .base import Name, Section, short_repr


class RunConfig(Section):
    """How to run: random seed, output file, surface snapshot times."""

    seed: int = Field(
        0, ge=0, lt=2**63, description="seed of every random draw (same seed, same bytes)"
    )
    output: Name | None = Field(
        None, description="output file (netCDF); the CLI's -o overrides it"
    )
    surface_times_s: tuple[float, ...] = Field(
        (0.0,), min_length=1, max_length=100_000,
        description="times at which `seaecho surface` writes the sea [s]",
    )

    @field_validator("surface_times_s")
    @classmethod
    def _finite_sorted(cls, v: tuple[float, ...]) -> tuple[float, ...]:
        if any(b < a for a, b in zip(v, v[1:], strict=False)):
            raise ValueError(f"{short_repr(v)}: times must be in increasing order")
        return v


__all__ = ["RunConfig"]
