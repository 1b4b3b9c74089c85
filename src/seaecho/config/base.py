"""Shared base of the scene-file models.

Every section of a scene file is a frozen pydantic model that rejects unknown keys. Each
field carries its unit in its name (``_m``, ``_deg``, ``_m_s``, ...) or its description,
its allowed range as constraints, and a one-line description that error messages and
``seaecho check --explain`` show.
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict


class Section(BaseModel):
    """Base of every scene-file section: frozen, unknown keys rejected."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        validate_default=True,
        str_strip_whitespace=True,
        allow_inf_nan=False,
    )


__all__ = ["Section"]
