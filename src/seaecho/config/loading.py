"""Loading scene files (TOML) into a validated :class:`~seaecho.config.scene.Scene`.

Errors are turned into one :class:`SceneError` whose message names the field (as
``[section].key``), the value found, and what is allowed, so the CLI can print it and exit
with status 2 without a traceback.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from .scene import Scene


class SceneError(ValueError):
    """A scene file that cannot be used: unreadable, not TOML, or invalid."""


def _field_description(model: type[BaseModel], loc: tuple[Any, ...]) -> str | None:
    """Walk ``loc`` through nested models and return the last field's description."""
    current: Any = model
    description = None
    for part in loc:
        if isinstance(part, int):
            continue
        fields = getattr(current, "model_fields", None)
        if not fields or part not in fields:
            return description
        info = fields[part]
        description = info.description
        annotation = info.annotation
        current = _first_model(annotation)
    return description


def _first_model(annotation: Any) -> Any:
    """The first pydantic model found in a (possibly Optional / list) annotation."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()) or ():
        found = _first_model(arg)
        if found is not None:
            return found
    return None


def _format_loc(loc: tuple[Any, ...]) -> str:
    if not loc:
        return "(top level)"
    head, *rest = loc
    text = f"[{head}]" if isinstance(head, str) and rest else str(head)
    for part in rest:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else part)
    return text


def format_validation_error(exc: ValidationError, model: type[BaseModel] = Scene) -> str:
    """One readable message for every error in ``exc``: field, value, what is allowed."""
    lines = []
    for err in exc.errors(include_url=False):
        loc = tuple(err["loc"])
        # pydantic puts the union member's class name in loc for tagged unions; drop those
        loc = tuple(p for p in loc if not (isinstance(p, str) and p[:1].isupper()))
        msg = err["msg"].removeprefix("Value error, ")
        where = _format_loc(loc)
        value = err.get("input")
        if err["type"] == "missing":
            text = f"{where}: missing required field"
        elif err["type"] == "extra_forbidden":
            allowed = _allowed_keys(model, loc[:-1])
            text = f"{where}: unknown key (allowed: {', '.join(allowed)})"
        elif isinstance(value, dict):
            text = f"{where}: {msg}"
        else:
            text = f"{where} = {json.dumps(value, default=str)}: {msg}"
        description = _field_description(model, loc)
        if description and err["type"] != "extra_forbidden":
            text += f" ({description})"
        lines.append(text)
    return "\n".join(lines)


def _allowed_keys(model: type[BaseModel], loc: tuple[Any, ...]) -> list[str]:
    current: Any = model
    for part in loc:
        if isinstance(part, int):
            continue
        fields = getattr(current, "model_fields", {})
        if part not in fields:
            return []
        current = _first_model(fields[part].annotation)
    return sorted(getattr(current, "model_fields", {}))


def parse_scene(data: dict[str, Any], source: str = "<scene>") -> Scene:
    """Validate a scene given as a dict (the parsed TOML)."""
    try:
        return Scene.model_validate(data)
    except ValidationError as exc:
        raise SceneError(f"{source}: invalid scene\n{format_validation_error(exc)}") from None


def load_scene(path: str | Path) -> Scene:
    """Read and validate a TOML scene file.

    Raises
    ------
    SceneError
        If the file is missing, unreadable, not valid TOML or not a valid scene; the
        message names the field, the value and what is allowed.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SceneError(f"{path}: scene file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError(f"{path}: cannot read scene file ({exc})") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{path}: not valid TOML ({exc})") from None
    except RecursionError:
        raise SceneError(f"{path}: not valid TOML for seaecho: arrays or tables nested too "
                         "deeply (a scene file needs at most a few levels)") from None
    return parse_scene(data, source=str(path))


def scene_to_toml_dict(scene: Scene) -> dict[str, Any]:
    """The scene as a plain dict (None fields dropped), ready to write back as TOML/JSON."""
    return scene.model_dump(mode="json", exclude_none=True)


__all__ = ["SceneError", "format_validation_error", "load_scene", "parse_scene",
           "scene_to_toml_dict"]
