"""Conventions shared by every stage (docs/conventions.md): channel order, port letters.

These are vocabulary, not physics: the order in which the four polarimetric channels form
an axis, and the letters of the two ports of each antenna polarisation basis. The scene
files (``seaecho.config``) and the radar stage (``seaecho.radar``) both read them from here.
"""

from __future__ import annotations

#: The 2x2 scattering channels S_mn (m received, n transmitted) in axis order: the (h, v)
#: matrix flattened row by row.
CHANNELS: tuple[str, str, str, str] = ("HH", "HV", "VH", "VV")

#: Port letters of each antenna polarisation basis (first port, second port): linear
#: horizontal / vertical, slant +45 / -45 deg, circular right / left (IEEE handedness).
PORTS: dict[str, tuple[str, str]] = {"hv": ("H", "V"), "slant": ("P", "M"),
                                     "circular": ("R", "L")}

__all__ = ["CHANNELS", "PORTS"]
