"""Several receivers over the same sea: ``[[receivers]]`` (multistatic radar).

Each ``[[receivers]]`` table is a receiving platform with its antenna, exactly as a
``[receiver]`` section (:class:`~seaecho.config.radar.PlatformConfig`: trajectory,
attitude, perturbation, ``[receivers.antenna]``), plus a ``name`` that labels the
``receiver`` dimension of the outputs and, optionally, its own ``channels`` (default: the
``[radar]`` channels). The transmitter is the scene's ``[transmitter]``, one for all
receivers. ``[receiver]`` stays the one-receiver shorthand; a scene gives one or the other
(docs/multistatic.md).
"""

from __future__ import annotations

from pydantic import Field, model_validator

from .base import Name
from .radar import PlatformConfig

#: Most receivers of a scene [-].
MAX_RECEIVERS = 64


class ReceiverConfig(PlatformConfig):
    """One receiver of a multistatic radar: a platform, its antenna, a name, channels."""

    name: Name = Field(
        ..., min_length=1, max_length=200,
        description="label of this receiver (the outputs' receiver coordinate), unique",
    )
    channels: tuple[str, ...] | None = Field(
        None, min_length=1, max_length=4,
        description="channels 'mn' this receiver records (receive port m of its antenna, "
        "transmit port n); default the [radar] channels",
    )

    @model_validator(mode="after")
    def _check_channels(self) -> ReceiverConfig:
        if self.channels is not None and len(set(self.channels)) != len(self.channels):
            raise ValueError(f"channels = {list(self.channels)}: repeated channel")
        return self

    def platform(self) -> PlatformConfig:
        """This receiver as a ``[receiver]`` section (name and channels left out)."""
        return PlatformConfig(**self.model_dump(exclude={"name", "channels"}))


__all__ = ["MAX_RECEIVERS", "ReceiverConfig"]
