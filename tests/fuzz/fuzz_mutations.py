"""Mutations of valid scenes for the fuzzing suite.

A mutation takes a valid scene dict (from :mod:`fuzz_schema`) and breaks one thing:

- ``value``: another valid value of one field, over the schema's whole range (not the
  caps of a tiny scene): the scene may be valid, or refused for what it asks of others;
- ``type``: a value of another type (string, boolean, integer, float, array, table,
  date-time, huge integer);
- ``range``: a number just outside its field's bounds (read from the schema), or an
  extreme (+-1e308, 5e-324, 2^63);
- ``nonfinite``: NaN, +inf or -inf;
- ``missing``: a key or a whole section removed;
- ``unknown``: a key added, often an existing key with its case changed (``Ny``);
- ``nesting``: a value replaced by arrays nested 2 to 3000 deep;
- ``geometry``: degenerate geometry (a target on an antenna or crossing it, an antenna
  looking at itself, an antenna at or under the sea surface);
- ``text``: the TOML text itself garbled (a character deleted, doubled or replaced, the
  file cut short);
- ``radar``: one to three fields of ``[radar]``, ``[radar.waveform]``, ``[transmitter]``,
  ``[receiver]`` (their antennas and perturbations), ``[[targets]]`` or ``[image]`` set to
  valid values that stress the models: a bound itself (``ge``, ``le``), the next float
  past an open bound (``gt``, ``lt``: 5e-324 for ``gt = 0``), an extreme of an unbounded
  field (+-1e300), the present value scaled by 1e-6 .. 1e6, or any value of the schema's
  range; and sometimes ``[run] output`` (a Zarr store, a missing folder). The scene may
  be valid or refused; what `check` accepts, `run` must run.

Each mutation returns the new scene and what a refusal must name (a key, or None where
the message cannot name one, e.g. garbled TOML).
"""

from __future__ import annotations

import copy
import datetime
import math
import typing
from dataclasses import dataclass
from typing import Any

from fuzz_schema import constraints, field_paths, non_none
from fuzz_schema import value as schema_value
from hypothesis import strategies as st

from seaecho.config import Scene


@dataclass
class Mutation:
    kind: str
    data: dict | None  #: the mutated scene (None for ``text``: see ``text``)
    text: str | None  #: garbled TOML text (``text`` mutations only)
    names: tuple[str, ...]  #: one of these must appear in a refusal; () if none can


def leaves(d: Any, path: tuple = ()) -> list[tuple]:
    """Paths of every value in a nested dict/list (tables, arrays and scalars)."""
    out = []
    if isinstance(d, dict):
        for k, v in d.items():
            out.append(path + (k,))
            out += leaves(v, path + (k,))
    elif isinstance(d, list | tuple):
        for i, v in enumerate(d):
            out.append(path + (i,))
            out += leaves(v, path + (i,))
    return out


def get(d: Any, path: tuple) -> Any:
    for p in path:
        d = d[p]
    return d


def put(d: Any, path: tuple, value: Any) -> None:
    """Set ``path`` in place (tuples on the way become lists)."""
    parent = get(d, path[:-1])
    parent[path[-1]] = value


def thaw(d: Any) -> Any:
    """Deep copy with every tuple as a list (mutable)."""
    if isinstance(d, dict):
        return {k: thaw(v) for k, v in d.items()}
    if isinstance(d, list | tuple):
        return [thaw(v) for v in d]
    return copy.copy(d)


def key_names(path: tuple) -> tuple[str, ...]:
    """The string keys of a path, innermost first (a refusal names one of them)."""
    return tuple(str(p) for p in reversed(path) if isinstance(p, str))


_SCHEMA = {tuple(p for p in path): info for path, _, info in field_paths(Scene)}


def schema_info(path: tuple):
    """Field info of a scene path (list indices dropped), or None."""
    return _SCHEMA.get(tuple(p for p in path if isinstance(p, str)))


OTHER_TYPES = [
    "text", "", True, False, 7, 0, -3, 1.5, [1.0, 2.0], [], {"a": 1}, {},
    datetime.datetime(1979, 5, 27, 7, 32), datetime.date(2000, 1, 1), 2**70, [[1], [2]],
]


def category(v: Any) -> str:
    """TOML type of a value; integers and floats are both numbers (an integer is a valid
    float), so replacing one by the other is not a type change."""
    if isinstance(v, bool):
        return "bool"
    if isinstance(v, int | float):
        return "number"
    if isinstance(v, str):
        return "str"
    if isinstance(v, list | tuple):
        return "array"
    if isinstance(v, dict):
        return "table"
    return "datetime"


def other_type(value: Any) -> st.SearchStrategy:
    """A value of another TOML type than ``value``."""
    return st.sampled_from([v for v in OTHER_TYPES if category(v) != category(value)])


def out_of_range(info, draw) -> Any:
    """A number just outside the field's bounds, or an extreme."""
    c = constraints(info.metadata) if info is not None else {}
    annotation = non_none(info.annotation) if info is not None else float
    is_int = annotation is int
    choices: list[Any] = [1.0e308, -1.0e308, 5e-324, -5e-324, -0.0, 2**63, -(2**63) - 1]
    if "gt" in c:
        choices.append(c["gt"])
    if "ge" in c:
        choices.append(c["ge"] - (1 if is_int else max(abs(c["ge"]) * 1e-9, 1e-300)))
    if "lt" in c:
        choices.append(c["lt"])
    if "le" in c:
        choices.append(c["le"] + (1 if is_int else max(abs(c["le"]) * 1e-9, 1e-300)))
    value = draw(st.sampled_from(choices))
    if is_int and isinstance(value, float) and math.isfinite(value):
        value = int(value) if abs(value) < 2**80 else value
    return value


def nested(depth: int) -> Any:
    v: Any = 1.0
    for _ in range(depth):
        v = [v]
    return v


KINDS = ("value", "type", "range", "nonfinite", "missing", "unknown", "nesting", "geometry",
         "text", "radar")

#: Sections the ``radar`` mutation changes (first key of a path).
RADAR_SECTIONS = ("radar", "transmitter", "receiver", "targets", "image")


def edge_value(info, current: Any, draw) -> Any:
    """A valid value of a numeric field that stresses the models (module docstring):
    a bound, the next float past an open bound, +-1e300 where unbounded, or ``current``
    scaled by a power of ten; None for a non-numeric field."""
    annotation = non_none(info.annotation)
    if typing.get_origin(annotation) is typing.Annotated:
        annotation = typing.get_args(annotation)[0]
    if annotation not in (int, float) or isinstance(current, bool):
        return None
    c = constraints(info.metadata)
    is_int = annotation is int
    choices: list[Any] = []
    if "ge" in c:
        choices.append(c["ge"])
    if "le" in c:
        choices.append(c["le"])
    if "gt" in c:
        choices.append(c["gt"] + 1 if is_int else math.nextafter(c["gt"], math.inf))
    if "lt" in c:
        choices.append(c["lt"] - 1 if is_int else math.nextafter(c["lt"], -math.inf))
    if not is_int:
        if "gt" not in c and "ge" not in c:
            choices.append(-1.0e300)
        if "lt" not in c and "le" not in c:
            choices.append(1.0e300)
    if isinstance(current, int | float) and math.isfinite(current) and current:
        scaled = current * 10.0 ** draw(st.integers(-6, 6))
        choices.append(int(scaled) if is_int and abs(scaled) < 2**62 else scaled)
    if not choices:
        return None
    v = draw(st.sampled_from(choices))
    return int(v) if is_int and isinstance(v, float) and math.isfinite(v) else v


@st.composite
def mutations(draw, scenes: st.SearchStrategy[dict], kinds=KINDS) -> Mutation:
    """A valid scene from ``scenes`` with one thing broken (module docstring)."""
    from fuzz_harness import scene_text

    data = thaw(draw(scenes))
    kind = draw(st.sampled_from(kinds))
    paths = leaves(data)
    if kind == "text":
        text = scene_text(data)
        i = draw(st.integers(0, max(len(text) - 1, 0)))
        how = draw(st.sampled_from(["delete", "double", "replace", "cut"]))
        if how == "delete":
            text = text[:i] + text[i + 1:]
        elif how == "double":
            text = text[:i + 1] + text[i:]
        elif how == "replace":
            text = text[:i] + draw(st.sampled_from(list("[]{}=\"',.#\n\\ 0aZ\x00\x7f"))) \
                + text[i + 1:]
        else:
            text = text[:i]
        return Mutation(kind, None, text, ())
    if kind == "geometry" and "radar" in data:
        return _geometry(draw, data)
    if kind == "radar":
        return _radar(draw, data, paths)
    if kind == "geometry":
        kind = "nonfinite"
    if kind == "unknown":
        tables = [()] + [p for p in paths if isinstance(get(data, p), dict)]
        where = draw(st.sampled_from(tables))
        table = get(data, where)
        existing = [k for k in table if isinstance(k, str)]
        if existing and draw(st.booleans()):
            base = draw(st.sampled_from(existing))
            key = draw(st.sampled_from([base.upper(), base.title(), base.swapcase(),
                                        base + "_", base.replace("_", "-"), " " + base]))
        else:
            key = draw(st.from_regex(r"[A-Za-z_][A-Za-z0-9_-]{0,12}", fullmatch=True))
        if key in table:
            key = key + "X"
        table[key] = draw(st.sampled_from(OTHER_TYPES))
        return Mutation(kind, data, None, (key.strip() or key,))
    path = draw(st.sampled_from(paths))
    names = key_names(path)
    if kind == "missing":
        parent = get(data, path[:-1])
        if isinstance(parent, dict):
            del parent[path[-1]]
        else:
            parent.pop(path[-1])
        return Mutation(kind, data, None, names)
    info = schema_info(path)
    if kind == "value":
        from fuzz_schema import is_model

        fields = [q for q in paths if schema_info(q) is not None
                  and not is_model(non_none(schema_info(q).annotation))]
        if not fields:
            return Mutation(kind, data, None, ())
        path = draw(st.sampled_from(fields))
        info = schema_info(path)
        put(data, path, thaw(draw(schema_value(info.annotation, info.metadata))))
        return Mutation(kind, data, None, ())
    if kind == "type":
        value = draw(other_type(get(data, path)))
    elif kind == "range":
        value = out_of_range(info, draw)
    elif kind == "nonfinite":
        value = draw(st.sampled_from([math.nan, math.inf, -math.inf]))
    else:  # nesting
        value = nested(draw(st.sampled_from([2, 5, 50, 400, 3000])))
        names = names + ("nested too deeply",)
    put(data, path, value)
    return Mutation(kind, data, None, names)


def _radar(draw, data: dict, paths: list[tuple]) -> Mutation:
    """One to three radar-side fields set to stressing valid values (module docstring)."""
    from fuzz_schema import is_model
    from fuzz_schema import value as schema_value

    fields = [q for q in paths if q and q[0] in RADAR_SECTIONS and isinstance(q[-1], str)
              and schema_info(q) is not None
              and not is_model(non_none(schema_info(q).annotation))]
    if not fields:
        return Mutation("radar", data, None, ())
    if draw(st.integers(0, 4)) == 0:  # the output `run` writes, which check checks too
        data.setdefault("run", {})["output"] = draw(st.sampled_from(
            ["out.nc", "out.zarr", "no_such_folder/out.nc", "sub.dir/out.zarr"]))
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(fields))
        info = schema_info(path)
        new = edge_value(info, get(data, path), draw) if draw(st.booleans()) else None
        if new is None:
            new = thaw(draw(schema_value(info.annotation, info.metadata)))
        put(data, path, new)
    return Mutation("radar", data, None, ())


def _geometry(draw, data: dict) -> Mutation:
    """Degenerate geometry on a scene with [radar] and [transmitter]."""
    tx = data.setdefault("transmitter", {})
    rx = data.get("receiver") or tx
    radar = data.get("radar")
    if radar is None or "antenna" not in tx:
        return Mutation("geometry", data, None, ())
    tx_pos = _position(tx)
    rx_pos = _position(rx)
    choice = draw(st.sampled_from(["target_on_tx", "target_on_rx", "target_crosses_tx",
                                   "look_at_self", "tx_at_sea", "rx_under_sea"]))
    targets = data.setdefault("targets", [])
    if choice in ("target_on_tx", "target_on_rx", "target_crosses_tx") and tx_pos is None:
        choice = "tx_at_sea"
    if choice == "target_on_tx":
        targets.append({"name": "ontx", "position_m": list(tx_pos), "rcs_m2": 1.0})
        return Mutation("geometry", data, None, ("ontx",))
    if choice == "target_on_rx" and rx_pos is not None:
        targets.append({"name": "onrx", "position_m": list(rx_pos), "rcs_m2": 1.0})
        return Mutation("geometry", data, None, ("onrx",))
    if choice in ("target_crosses_tx", "target_on_rx"):
        # through the transmitter at pulse 1 (if the transmitter is fixed)
        t1 = radar.get("start_time_s", 0.0) + 1.0 / radar["prf_hz"]
        v = [100.0, 0.0, 0.0]
        p0 = [tx_pos[0] - v[0] * t1, tx_pos[1], tx_pos[2]]
        radar["n_pulses"] = max(radar.get("n_pulses", 1), 2)
        targets.append({"name": "crosser", "position_m": p0, "velocity_m_s": v,
                        "rcs_m2": 1.0})
        return Mutation("geometry", data, None, ("crosser",) if tx.get(
            "motion", "fixed") == "fixed" else ())
    ant = tx["antenna"]
    if choice == "look_at_self" and tx_pos is not None:
        for k in ("azimuth_deg", "depression_deg"):
            ant.pop(k, None)
        ant["look_at_m"] = list(tx_pos)
        return Mutation("geometry", data, None, ("look_at_m",) if tx.get(
            "motion", "fixed") == "fixed" else ())
    section = "receiver" if choice == "rx_under_sea" and "receiver" in data else "transmitter"
    plat = data[section]
    for k in ("waypoint_times_s", "waypoint_positions_m", "velocity_m_s"):
        plat.pop(k, None)
    plat["motion"] = "fixed"
    z = 0.0 if choice == "tx_at_sea" else -5.0
    pos = list(_position(plat) or (0.0, 0.0, 0.0))
    plat["position_m"] = [pos[0], pos[1], z]
    if choice == "tx_at_sea":
        plat["antenna"].pop("azimuth_deg", None)
        plat["antenna"].pop("depression_deg", None)
        plat["antenna"].pop("scan", None)  # a scanning antenna takes depression_deg
        plat["antenna"]["look_at_m"] = [pos[0], pos[1], z]
    return Mutation("geometry", data, None, ("position_m",))


def _position(platform: dict) -> list[float] | None:
    """Position of a platform section at t = 0 for fixed / linear motion."""
    if platform.get("motion", "fixed") in ("fixed", "linear") and "position_m" in platform:
        return list(platform["position_m"])
    return None


__all__ = ["KINDS", "Mutation", "edge_value", "leaves", "mutations", "schema_info"]
