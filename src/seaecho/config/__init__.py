"""Scene files: TOML, validated into frozen pydantic models.

This package is the only place that sees non-SI units (knots, degrees, dB); everything it
hands to the stages is SI.
"""

from .loading import SceneError, format_validation_error, load_scene, parse_scene
from .overrides import parse_assignment, parse_assignments, with_overrides
from .run import RunConfig
from .scene import Scene
from .sea import SeaConfig
from .ship import ShipConfig

__all__ = [
    "RunConfig",
    "Scene",
    "SceneError",
    "SeaConfig",
    "ShipConfig",
    "format_validation_error",
    "load_scene",
    "parse_assignment",
    "parse_assignments",
    "parse_scene",
    "with_overrides",
]
