"""Shared base of the scene-file models.

Every section of a scene file is a frozen pydantic model that rejects unknown keys. Each
field carries its unit in its name (``_m``, ``_deg``, ``_m_s``, ...) or its description,
its allowed range as constraints, and a one-line description that error messages and
``seaecho check --explain`` show.
"""

from __future__ import annotations

import json
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, ConfigDict


class Section(BaseModel):
    """Base of every scene-file section: frozen, unknown keys rejected."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        validate_default=True,
        str_strip_whitespace=True,
        allow_inf_nan=False,
    )


def _no_control(allowed: str = ""):
    def check(text: str) -> str:
        for i, c in enumerate(text):
            if (ord(c) < 32 or ord(c) == 127) and c not in allowed:
                raise ValueError(f"control character U+{ord(c):04X} at position {i}: not "
                                 "allowed here (a NUL cannot even be written to the netCDF "
                                 "file)")
        return text

    return AfterValidator(check)


#: A name or a path: no control characters.
Name = Annotated[str, _no_control()]
#: Free text: no control characters but tab and line breaks.
Text = Annotated[str, _no_control("\t\n\r")]


#: Longest value an error message repeats [characters]; longer ones are cut.
MAX_VALUE_CHARS = 80


def short_repr(value: Any, limit: int = MAX_VALUE_CHARS) -> str:
    """``value`` as TOML-like text (JSON syntax), cut to about ``limit`` characters.

    Walks containers lazily, so a 1 MB string or a list of 10,000 tables costs no more
    than ``limit`` characters, and deep nesting does not recurse past what is shown.
    """
    out: list[str] = []
    size = 0

    def emit(text: str) -> bool:
        nonlocal size
        out.append(text)
        size += len(text)
        return size <= limit

    def walk(v: Any) -> bool:
        if isinstance(v, dict):
            if not emit("{"):
                return False
            for i, (k, item) in enumerate(v.items()):
                if not (emit((", " if i else "") + json.dumps(str(k)) + ": ") and walk(item)):
                    return False
            return emit("}")
        if isinstance(v, list | tuple):
            if not emit("["):
                return False
            for i, item in enumerate(v):
                if not ((emit(", ") if i else True) and walk(item)):
                    return False
            return emit("]")
        if isinstance(v, str):
            return emit(json.dumps(v[: limit + 1]))
        if isinstance(v, bool) or v is None or isinstance(v, int | float):
            return emit(json.dumps(v))
        return emit(json.dumps(str(v)[: limit + 1]))

    if walk(value):
        return "".join(out)
    text = "".join(out)[:limit]
    hint = ""
    if isinstance(value, str):
        hint = f", {len(value)} characters"
    elif isinstance(value, list | tuple | dict):
        hint = f", {len(value)} items"
    return f"{text}... (cut{hint})"


__all__ = ["MAX_VALUE_CHARS", "Name", "Section", "Text", "short_repr"]
