"""Write a scene (a dict of TOML values) back as TOML text.

The standard library reads TOML (``tomllib``) but does not write it. This writer covers
what scene files hold: tables, arrays of tables, arrays, strings, booleans, integers,
floats (``nan`` and ``inf`` included, so that broken scenes can be written too) and
dates/times.
``tomllib.loads(dumps(d)) == d`` for any such dict whose keys are strings (tested).
"""

from __future__ import annotations

import datetime
import json
import math
from typing import Any


def _key(k: str) -> str:
    bare = k and all(c.isalnum() and c.isascii() or c in "_-" for c in k)
    return k if bare else _string(k)


def _string(s: str) -> str:
    # JSON string escapes are valid TOML basic-string escapes, except that JSON may
    # write \u escapes for surrogates TOML does not allow: keep only scalar values
    text = json.dumps(s, ensure_ascii=False)
    return text.replace("\x7f", "\\u007f")


def _scalar(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, datetime.date | datetime.time):
        return v.isoformat()
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def _value(v: Any) -> str:
    """An inline value; iterative, so arrays nested thousands deep can be written."""
    out: list[str] = []
    stack: list[tuple[bool, Any]] = [(False, v)]  # (is literal text, item)
    while stack:
        literal, x = stack.pop()
        if literal:
            out.append(x)
        elif isinstance(x, dict):
            items = list(x.items())
            stack.append((True, "}"))
            for i in reversed(range(len(items))):
                stack.append((False, items[i][1]))
                stack.append((True, (", " if i else "") + f"{_key(items[i][0])} = "))
            stack.append((True, "{"))
        elif isinstance(x, list | tuple):
            stack.append((True, "]"))
            for i in reversed(range(len(x))):
                stack.append((False, x[i]))
                if i:
                    stack.append((True, ", "))
            stack.append((True, "["))
        else:
            out.append(_scalar(x))
    return "".join(out)


def _is_table_array(v: Any) -> bool:
    return isinstance(v, list | tuple) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _table(d: dict, prefix: str, lines: list[str]) -> None:
    subtables = []
    for k, v in d.items():
        if isinstance(v, dict) or _is_table_array(v):
            subtables.append((k, v))
        else:
            lines.append(f"{_key(k)} = {_value(v)}")
    for k, v in subtables:
        name = f"{prefix}.{_key(k)}" if prefix else _key(k)
        if isinstance(v, dict):
            lines.append(f"\n[{name}]")
            _table(v, name, lines)
        else:
            for item in v:
                lines.append(f"\n[[{name}]]")
                _table(item, name, lines)


def dumps(data: dict[str, Any]) -> str:
    """TOML text of ``data`` (tables as ``[a.b]`` headers, lists of tables as ``[[a]]``)."""
    lines: list[str] = []
    _table(data, "", lines)
    return "\n".join(lines).lstrip("\n") + "\n"


__all__ = ["dumps"]
