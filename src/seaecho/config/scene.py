"""The whole scene: one model composed of the sections of a scene file.

Sections (a TOML table each):

- ``[sea]``      sea state, spectrum, tile and grid (:class:`SeaConfig`), required
- ``[ship]``     a ship and its wake (:class:`ShipConfig`), optional
- ``[[ships]]``  several ships (the same keys each, with a ``name``), optional
- ``[run]``      seed, output, times (:class:`RunConfig`)
- ``[[receivers]]`` several receivers of one transmitter (:class:`ReceiverConfig`),
  instead of ``[receiver]``

- ``[[land]]``   coastlines (:class:`LandConfig`), optional

Sections that later stages add (radar, platforms, tracing, objects, targets) are
registered here too, each in its own module of this package.
"""

from __future__ import annotations

from pathlib import Path

from pydantic import Field, PrivateAttr, model_serializer, model_validator

from .base import Name, Section, Text
from .image import ImageConfig
from .land import LandConfig
from .propagation import PropagationConfig
from .radar import PlatformConfig, RadarConfig, TargetConfig
from .receivers import MAX_RECEIVERS, ReceiverConfig
from .run import RunConfig
from .scattering import ScatteringConfig
from .sea import SeaConfig
from .ship import ShipConfig
from .tracing import ObjectConfig, TracingConfig


class Scene(Section):
    """A validated scene file.

    It knows its folder and shows a readable summary. Made by
    :func:`~seaecho.config.load_scene` (which records the file's folder,
    :attr:`base_dir`), :func:`~seaecho.config.parse_scene` and
    :func:`~seaecho.config.with_overrides`; every builder takes it. Printed, or shown in a
    notebook, it gives :meth:`summary`. Frozen: change it with ``with_overrides``.
    """

    name: Name = Field("", max_length=200, description="a short name for the scene")
    description: Text = Field("", max_length=5000, description="free text")
    sea: SeaConfig = Field(..., description="the sea [sea]")
    ship: ShipConfig | None = Field(None, description="the ship and its wake [ship]")
    ships: tuple[ShipConfig, ...] = Field(
        (), max_length=100, description="several ships and their wakes [[ships]] (instead "
        "of [ship])"
    )
    run: RunConfig = Field(default_factory=RunConfig, description="run options [run]")
    radar: RadarConfig | None = Field(
        None, description="the radar: waveform, pulses, noise [radar]"
    )
    transmitter: PlatformConfig | None = Field(
        None, description="transmitting platform and antenna [transmitter]"
    )
    receiver: PlatformConfig | None = Field(
        None, description="receiving platform and antenna [receiver]; omit for monostatic"
    )
    receivers: tuple[ReceiverConfig, ...] = Field(
        (), max_length=MAX_RECEIVERS,
        description="several receivers of the one transmitter [[receivers]] (multistatic; "
        "instead of [receiver])",
    )
    targets: tuple[TargetConfig, ...] = Field(
        (), max_length=10_000, description="point targets [[targets]]"
    )
    scattering: ScatteringConfig = Field(
        default_factory=ScatteringConfig,
        description="per-facet scattering model and sea motion [scattering]",
    )
    tracing: TracingConfig = Field(
        default_factory=TracingConfig, description="facet mode and ray tracing [tracing]"
    )
    objects: tuple[ObjectConfig, ...] = Field(
        (), max_length=1000, description="meshes / XML scenes that occlude the sea [[objects]]"
    )
    land: tuple[LandConfig, ...] = Field(
        (), max_length=100, description="coastlines that occlude and echo [[land]] "
        "(constant-gamma land clutter; docs/land.md)"
    )
    image: ImageConfig | None = Field(
        None, description="SAR focusing after the raw data [image]; omit for raw data only"
    )
    propagation: PropagationConfig = Field(
        default_factory=PropagationConfig,
        description="the Earth's curvature and refraction [propagation]",
    )

    _base_dir: Path | None = PrivateAttr(default=None)

    @model_serializer(mode="wrap")
    def _without_empty_receivers(self, handler):
        # A scene without [[receivers]] dumps as before they existed: its files' scene_json
        # (and so their bytes, and a Zarr run's identity) are unchanged
        data = handler(self)
        if not self.receivers and isinstance(data, dict):
            data.pop("receivers", None)
        if not self.land and isinstance(data, dict):  # likewise a scene without [[land]]
            data.pop("land", None)
        return data

    @model_validator(mode="after")
    def _across_sections(self) -> Scene:
        from .consistency import check_scene

        check_scene(self)
        return self

    @property
    def all_ships(self) -> tuple[ShipConfig, ...]:
        """Every ship: ``[ship]`` (one) or ``[[ships]]``."""
        return (self.ship,) if self.ship is not None else tuple(self.ships)

    def ship_names(self) -> tuple[str, ...]:
        """The ships' names (``ship0``, ``ship1``, ... where none is given)."""
        return tuple(s.name or f"ship{i}" for i, s in enumerate(self.all_ships))

    @property
    def base_dir(self) -> Path | None:
        """Folder of the scene file (``[[objects]]`` paths are relative to it), or None."""
        return self._base_dir

    # The display calls up to seaecho.summary, which builds the radar to give the scene's
    # geometry and resolution cells: a deferred import, the schema's one upward edge
    # (tests/test_layers.py lists it; docs/design.md).
    def summary(self) -> str:
        """Sea state, geometry, radar, resolution cells and run size, as text
        (:func:`seaecho.summary.scene_summary`)."""
        from ..summary import scene_summary

        return scene_summary(self).text()

    def _repr_html_(self) -> str:
        from ..summary import scene_summary

        return scene_summary(self).html()

    def __repr__(self) -> str:
        try:
            return self.summary()
        except Exception as exc:  # a repr must not raise; the fields still say it all
            return f"{super().__repr__()}\n(no summary: {exc})"

    __str__ = __repr__


__all__ = ["Scene"]
