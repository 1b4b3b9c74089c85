"""Render the scene-file reference (every field, unit, range, default) as Markdown.

``python -m seaecho.config.reference > docs/scene-files.md`` regenerates the user
reference from the pydantic models, so the docs cannot drift from the schema.
"""

from __future__ import annotations

import re
import typing

from pydantic import BaseModel
from pydantic_core import PydanticUndefined

from .scene import Scene


def _constraints(info) -> str:
    parts = []
    for meta in info.metadata:
        for attr, sym in (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<="),
                          ("min_length", "len >="), ("max_length", "len <=")):
            value = getattr(meta, attr, None)
            if value is not None:
                parts.append(f"{sym} {value}")
    return ", ".join(parts)


def _type_name(annotation) -> str:
    text = str(annotation).replace("typing.", "")
    for mod in ("seaecho.config.", "pydantic."):
        text = text.replace(mod, "")
    # Annotated[str, AfterValidator(<function ... at 0x...>)]: the type, not the validator
    text = re.sub(r"Annotated\[(\w+), AfterValidator\(func=<function .*? at 0x[0-9a-f]+>\)\]",
                  r"\1", text)
    if isinstance(annotation, type):
        text = annotation.__name__
    return text.replace("|", "\\|")


def _models_in(annotation) -> list[type[BaseModel]]:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    found = []
    for arg in typing.get_args(annotation):
        found += _models_in(arg)
    return found


def render(model: type[BaseModel] = Scene, title: str = "Scene files") -> str:
    """The reference of ``model`` and every section model it contains, as Markdown."""
    lines = [f"# {title}", "",
             "Generated from the schema by `python -m seaecho.config.reference`. Units are "
             "in the field names (`_m`, `_deg`, `_m_s`, `_hz`, `_db`, ...) or the "
             "descriptions. Unknown keys are rejected.", ""]
    seen: set[type] = set()
    queue: list[tuple[str, type[BaseModel]]] = [("(top level)", model)]
    while queue:
        where, current = queue.pop(0)
        if current in seen:
            continue
        seen.add(current)
        lines += [f"## {where}: `{current.__name__}`", ""]
        doc = (current.__doc__ or "").strip().splitlines()
        if doc:
            lines += [doc[0], ""]
        lines += ["| field | type | default | allowed | description |", "|---|---|---|---|---|"]
        for name, info in current.model_fields.items():
            default = "required" if info.is_required() else (
                "(computed)" if info.default is PydanticUndefined else repr(info.default))
            desc = (info.description or "").replace("|", "\\|")
            lines.append(f"| `{name}` | {_type_name(info.annotation)} | {default} | "
                         f"{_constraints(info)} | {desc} |")
            for sub in _models_in(info.annotation):
                queue.append((f"[{name}]", sub))
        lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    print(render())
