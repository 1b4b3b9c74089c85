"""Overrides of scene fields by dotted name: ``sea.wind_speed_m_s = 8``.

One implementation serves the command line (``--set NAME=VALUE``, sweeps) and the Python
API: :func:`with_overrides` takes a scene (or its dict) and a mapping of dotted names to
values, writes each value into the scene's dict and validates the result like a scene
file, so a bad name or value gets the same message as in a file, e.g.
``[sea].wind_speed_m_s = -3.0: Input should be greater than 0 (...)``.

Names
-----
A name is the path of a field through the sections of a scene file, joined by dots:
``sea.nx``, ``radar.waveform.bandwidth_hz``, ``transmitter.antenna.look_at_m``. An array of
tables is indexed by position: ``targets.0.position_m``, ``objects.1.material``. A name
may create a section that the scene lacks (``ship.speed_kn`` on a scene without a ship);
the section's required fields must then be given too.

Values
------
From Python, any value a scene file could hold (numbers, strings, booleans, lists). From
the command line, :func:`parse_assignment` reads ``NAME=VALUE`` with VALUE in TOML syntax
(``8``, ``1.5e9``, ``true``, ``[0, 0, 10]``, ``"hh"``); a VALUE that is not TOML is
taken as a string (``sea.spectrum=elfouhaily``).
"""

from __future__ import annotations

import copy
import re
import tomllib
from collections.abc import Iterable, Mapping
from typing import Any

from .loading import SceneError, parse_scene, scene_to_toml_dict
from .scene import Scene

__all__ = ["parse_assignment", "parse_assignments", "with_overrides"]

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*(\.([A-Za-z_][A-Za-z0-9_]*|[0-9]+))*$")


def parse_assignment(text: str) -> tuple[str, Any]:
    """``"NAME=VALUE"`` -> ``(NAME, value)``, VALUE read as TOML (else as a string).

    Raises
    ------
    SceneError
        No ``=``, or a malformed name.
    """
    name, sep, raw = text.partition("=")
    name = name.strip()
    if not sep:
        raise SceneError(f"override {_cut(text)!r}: expected NAME=VALUE, e.g. "
                         "sea.wind_speed_m_s=8")
    _check_name(name)
    raw = raw.strip()
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except (tomllib.TOMLDecodeError, RecursionError):
        value = raw
    return name, value


def parse_assignments(texts: Iterable[str]) -> dict[str, Any]:
    """Several ``NAME=VALUE`` strings -> an ordered dict (a repeated name: last wins)."""
    out: dict[str, Any] = {}
    for text in texts:
        name, value = parse_assignment(text)
        out[name] = value
    return out


def with_overrides(scene: Scene | Mapping[str, Any], overrides: Mapping[str, Any],
                   source: str = "overrides") -> Scene:
    """The scene with fields replaced by dotted name, validated like a scene file.

    Parameters
    ----------
    scene : Scene or mapping
        A validated scene, or the dict of a scene file (parsed TOML).
    overrides : mapping of str to value
        Dotted field names (module docstring) and their new values.
    source : str
        What the error messages name as the origin of the scene.

    Returns
    -------
    Scene
        A new validated scene (the input is not changed), with the same folder
        (:attr:`Scene.base_dir`).

    Raises
    ------
    SceneError
        A malformed name, a name that does not lead into a section (e.g. a field of a
        number), or a result that is not a valid scene (unknown field, value out of range,
        ...): the message names the field, the value and what is allowed.
    """
    data = scene_to_toml_dict(scene) if isinstance(scene, Scene) else copy.deepcopy(
        dict(scene))
    for name, value in overrides.items():
        _check_name(name)
        _assign(data, name, value)
    return parse_scene(data, source=f"{source} ({', '.join(overrides) or 'none'})",
                       base_dir=scene.base_dir if isinstance(scene, Scene) else None)


def _check_name(name: str) -> None:
    if not _NAME.match(name):
        raise SceneError(f"override name {_cut(name)!r}: expected dotted field names such as "
                         "sea.wind_speed_m_s or targets.0.position_m")


def _assign(data: dict[str, Any], name: str, value: Any) -> None:
    parts = name.split(".")
    node: Any = data
    for i, part in enumerate(parts[:-1]):
        where = ".".join(parts[: i + 1])
        nxt = parts[i + 1]
        if isinstance(node, list):
            index = _index(part, node, where)
            if node[index] is None or not isinstance(node[index], dict | list):
                raise SceneError(f"override {name}: {where} is not a section")
            node = node[index]
            continue
        if not isinstance(node, dict):
            raise SceneError(f"override {name}: {'.'.join(parts[:i])} is not a section")
        if part not in node or node[part] is None:
            node[part] = [] if nxt.isdigit() else {}
        node = node[part]
    last = parts[-1]
    if isinstance(node, list):
        node[_index(last, node, name)] = value
    elif isinstance(node, dict):
        node[last] = value
    else:
        raise SceneError(f"override {name}: {'.'.join(parts[:-1])} is not a section")


def _index(part: str, seq: list, where: str) -> int:
    if not part.isdigit():
        raise SceneError(f"override {where}: {part!r} is not an index (the array has "
                         f"{len(seq)} entries: 0 to {len(seq) - 1})")
    index = int(part)
    if index >= len(seq):
        raise SceneError(f"override {where}: index {index} out of range (the array has "
                         f"{len(seq)} entries)")
    return index


def _cut(text: str, n: int = 80) -> str:
    return text if len(text) <= n else text[: n - 3] + "..."
