"""Loading scene files (TOML) into a validated :class:`~seaecho.config.scene.Scene`.

Errors are turned into one :class:`SceneError` whose message names the field (as
``[section].key``), the value found, and what is allowed, so the CLI can print it and exit
with status 2 without a traceback.
"""

from __future__ import annotations

import os
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from .base import MAX_VALUE_CHARS, short_repr
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


def _model_class_names(model: type[BaseModel]) -> set[str]:
    """Names of every model class reachable from ``model`` (pydantic may put them in a
    loc for a union of models; they are never keys of a scene file)."""
    names: set[str] = set()
    stack = [model]
    while stack:
        current = stack.pop()
        if current.__name__ in names:
            continue
        names.add(current.__name__)
        for info in current.model_fields.values():
            stack.extend(_models_in(info.annotation))
    return names


def _models_in(annotation: Any) -> list[type[BaseModel]]:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    found = []
    for arg in getattr(annotation, "__args__", ()) or ():
        found += _models_in(arg)
    return found


def _clean_loc(loc: tuple[Any, ...], model: type[BaseModel]) -> tuple[Any, ...]:
    """``loc`` without the union-member tags pydantic inserts (class names such as
    ``ShipConfig`` or ``function-after[...]``), keeping every key of the file: a part is
    dropped only if it is such a tag and not a field of the model reached so far."""
    classes = _model_class_names(model)
    out: list[Any] = []
    current: Any = model
    for i, part in enumerate(loc):
        fields = getattr(current, "model_fields", None) or {}
        if isinstance(part, str) and part not in fields and i < len(loc) - 1 and (
                part in classes or "[" in part):
            continue
        out.append(part)
        if isinstance(part, str) and part in fields:
            current = _first_model(fields[part].annotation)
    return tuple(out)


def _section_name(loc: tuple[Any, ...]) -> str:
    """The section of a loc as messages name it: ``[sea]``, ``[radar].waveform``."""
    if not loc:
        return "(top level)"
    if len(loc) == 1 and isinstance(loc[0], str):
        return f"[{loc[0]}]"
    return _format_loc(loc)


def format_validation_error(exc: ValidationError, model: type[BaseModel] = Scene) -> str:
    """One readable message for every error in ``exc``: field, value, what is allowed.

    Values are repeated cut to :data:`MAX_VALUE_CHARS` characters (:func:`short_repr`).
    """
    lines = []
    for err in exc.errors(include_url=False):
        loc = _clean_loc(tuple(err["loc"]), model)
        msg = err["msg"].removeprefix("Value error, ")
        where = _format_loc(loc)
        value = err.get("input")
        if err["type"] == "missing":
            text = f"{where}: missing required field"
        elif err["type"] == "extra_forbidden":
            section = _section_name(loc[:-1])
            allowed = _allowed_keys(model, loc[:-1])
            text = (f"{where}: unknown key in {section} (allowed: {', '.join(allowed)}; "
                    "keys are case-sensitive)")
        elif not loc and msg.startswith("["):
            text = msg  # a check across sections: its message names the fields
        elif isinstance(value, dict):
            text = f"{_section_name(loc)}: {msg}"  # a check of a whole section
        else:
            text = f"{where} = {short_repr(value)}: {msg}"
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


def _lists_to_tuples(data: Any) -> Any:
    """TOML arrays (lists) as tuples, so that strict validation accepts them."""
    if isinstance(data, list):
        return tuple(_lists_to_tuples(v) for v in data)
    if isinstance(data, dict):
        return {k: _lists_to_tuples(v) for k, v in data.items()}
    return data


def parse_scene(data: str | Mapping[str, Any], source: str | None = None, *,
                base_dir: str | os.PathLike | None = None) -> Scene:
    """A scene from TOML text or from a dict (the parsed TOML), validated.

    Validation is strict: a number must be written as a number (``nx = 32``, not
    ``"32"``), a boolean as ``true``/``false`` (not ``1``), an integer field takes no
    fraction (``nx = 32.0`` is refused); an integer is accepted where a float is expected.

    Parameters
    ----------
    data : str or mapping
        The text of a scene file, or its tables as nested dicts.
    source : str, optional
        What the error messages name as the scene's origin (default ``<string>`` for
        text, ``<scene>`` for a dict).
    base_dir : path, optional
        Folder that relative ``[[objects]]`` paths start from (:attr:`Scene.base_dir`;
        default: the working directory when a run needs them).

    Raises
    ------
    SceneError
        Not TOML, or not a valid scene (field, value and what is allowed).
    """
    if isinstance(data, str):
        where = "<string>" if source is None else source
        try:
            data = tomllib.loads(data)
        except tomllib.TOMLDecodeError as exc:
            hint = (" (to read a file, use seaecho.load_scene)"
                    if data.strip().endswith(".toml") else "")
            raise SceneError(f"{where}: not valid TOML ({exc}){hint}") from None
        except RecursionError:
            raise SceneError(f"{where}: not valid TOML for seaecho: arrays or tables nested "
                             "too deeply (a scene file needs at most a few levels)") from None
    elif isinstance(data, Mapping):
        where = "<scene>" if source is None else source
    else:
        raise SceneError(f"source: expected TOML text or a dict, got {type(data).__name__}")
    try:
        scene = Scene.model_validate(_lists_to_tuples(dict(data)), strict=True)
    except ValidationError as exc:
        raise SceneError(f"{where}: invalid scene\n{format_validation_error(exc)}") from None
    except RecursionError:
        raise SceneError(f"{where}: invalid scene: values nested too deeply (a scene "
                         "file needs at most a few levels of tables and arrays)") from None
    if base_dir is not None:
        scene._base_dir = Path(base_dir)
    return scene


def load_scene(path: str | os.PathLike) -> Scene:
    """Read and validate a TOML scene file; the scene's :attr:`~Scene.base_dir` is the
    file's folder (``[[objects]]`` mesh paths are relative to it).

    Raises
    ------
    SceneError
        If the file is missing, unreadable, not valid TOML or not a valid scene; the
        message names the field (``[sea].wind_speed_m_s``), the value and what is
        allowed.
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
    return parse_scene(data, source=str(path), base_dir=path.resolve().parent)


def scene_to_toml_dict(scene: Scene) -> dict[str, Any]:
    """The scene as a plain dict (None fields dropped), ready to write back as TOML/JSON."""
    return scene.model_dump(mode="json", exclude_none=True)


__all__ = ["MAX_VALUE_CHARS", "SceneError", "format_validation_error", "load_scene",
           "parse_scene", "scene_to_toml_dict", "short_repr"]
