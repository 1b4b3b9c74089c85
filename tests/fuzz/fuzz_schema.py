"""Hypothesis strategies for scene files, generated from the pydantic schema itself.

:func:`section` walks a model's fields: each field's strategy comes from its annotation
(``float``, ``int``, ``bool``, ``str``, ``Literal``, ``tuple[...]``, ``X | None``, nested
models, ``Annotated`` items) and its constraints (``gt``/``ge``/``lt``/``le``,
``min_length``/``max_length``, ``pattern``); optional fields may be left out. Nothing
lists the fields by hand, so a field added to the schema is fuzzed at once.

Two things are not in the field annotations and are given here:

- **caps** (:data:`TINY`): tighter ranges for a few fields so that a valid scene runs in
  well under a second (grid <= 16 x 16, <= 3 pulses, short windows, platforms above the
  sea, targets near the tile), keyed by ``(model name, field)``;
- **couplings** (:data:`COUPLINGS`): the model validators' rules between fields (an lfm
  pulse has a bandwidth, a fixed platform has a position and no velocity, ...), as
  functions that choose which fields appear together and draw their values from the
  same schema strategies.

:func:`field_paths` lists every (path, field info) of the schema, for the mutations.
"""

from __future__ import annotations

import math
import types
import typing
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hypothesis import strategies as st
from pydantic import BaseModel, TypeAdapter, ValidationError

from seaecho.config import Scene, parse_scene
from seaecho.config.consistency import allowed_channels
from seaecho.config.radar import MIN_SECTOR_DEG, PlatformConfig, RadarConfig, TargetConfig
from seaecho.config.ship import ShipConfig
from seaecho.config.tracing import ObjectConfig

ROOT = Path(__file__).resolve().parents[2]
MESH = ROOT / "scenes" / "meshes" / "motor_boat_10m.ply"
#: The mesh of echoing objects (scatterer = true): a 0.5 m trihedral, a cheap trace.
SCATTERER_MESH = ROOT / "scenes" / "meshes" / "trihedral_0p5m.ply"
#: Fields an object may set only with scatterer = true.
SCATTERER_FIELDS = ("max_bounces", "rays_per_wavelength", "signature_refresh_deg",
                    "signature_refresh_s", "signature_cell_m", "sea_multipath")

#: Largest magnitude drawn for an unbounded number.
UNBOUNDED = 1.0e6


# ---------------------------------------------------------------------- constraints
def constraints(metadata) -> dict[str, Any]:
    """gt/ge/lt/le/min_length/max_length/pattern of a field's metadata list."""
    out: dict[str, Any] = {}
    for m in metadata or ():
        for name in ("gt", "ge", "lt", "le", "min_length", "max_length", "pattern"):
            value = getattr(m, name, None)
            if value is not None:
                out[name] = value
    return out


def _unwrap(annotation) -> tuple[Any, list]:
    """(inner type, extra metadata) of an ``Annotated[...]`` annotation."""
    if typing.get_origin(annotation) is typing.Annotated:
        inner, *extra = typing.get_args(annotation)
        meta = []
        for e in extra:
            meta += list(getattr(e, "metadata", [e]))
        return inner, meta
    return annotation, []


def non_none(annotation) -> Any:
    """``X`` of ``X | None`` (the annotation itself otherwise)."""
    args = typing.get_args(annotation)
    if type(None) in args:
        rest = [a for a in args if a is not type(None)]
        return rest[0] if len(rest) == 1 else typing.Union[tuple(rest)]  # noqa: UP007
    return annotation


def is_model(annotation) -> bool:
    return isinstance(annotation, type) and issubclass(annotation, BaseModel)


def number_range(kind: type, c: dict) -> tuple[float, float, bool, bool]:
    """(low, high, low excluded, high excluded) of a numeric field."""
    lo, lo_open = (c["gt"], True) if "gt" in c else (c.get("ge", -UNBOUNDED), False)
    hi, hi_open = (c["lt"], True) if "lt" in c else (c.get("le", UNBOUNDED), False)
    return lo, hi, lo_open, hi_open


def value(annotation, metadata=(), path: tuple = ()) -> st.SearchStrategy:
    """A valid value of a field from its annotation and constraints."""
    annotation, extra = _unwrap(non_none(annotation))
    c = constraints(list(metadata) + extra)
    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Literal:
        return st.sampled_from(args)
    if annotation is bool:
        return st.booleans()
    if annotation is int:
        lo, hi, lo_open, hi_open = number_range(int, c)
        return st.integers(int(lo) + lo_open, int(hi) - hi_open)
    if annotation is float:
        lo, hi, lo_open, hi_open = number_range(float, c)
        return st.floats(lo, hi, exclude_min=lo_open, exclude_max=hi_open,
                         allow_nan=False, allow_infinity=False)
    if annotation is str:
        if "pattern" in c:
            ascii_ = st.characters(max_codepoint=127)
            return st.from_regex(c["pattern"], fullmatch=True, alphabet=ascii_).filter(
                lambda s: c.get("min_length", 0) <= len(s) <= c.get("max_length", 10**9))
        return st.text(min_size=c.get("min_length", 0),
                       max_size=min(c.get("max_length", 40), 40)).map(str.strip).filter(
            lambda s: len(s) >= c.get("min_length", 0))
    if origin is tuple:
        if len(args) == 2 and args[1] is Ellipsis:
            lo = c.get("min_length", 0)
            hi = min(c.get("max_length", 5), max(lo, 5))
            item = value(args[0], (), path + (0,))
            return st.lists(item, min_size=lo, max_size=hi).map(tuple)
        return st.tuples(*(value(a, (), path + (i,)) for i, a in enumerate(args)))
    if is_model(annotation):
        return section(annotation, path)
    if origin in (typing.Union, types.UnionType):  # e.g. a level or 'off'
        return st.one_of(*(value(a, metadata, path) for a in args))
    raise NotImplementedError(f"no strategy for {annotation!r} at {path}")


# ---------------------------------------------------------------------------- models
def field_value(model: type[BaseModel], name: str, path: tuple = ()) -> st.SearchStrategy:
    """The strategy of one field of ``model``: its cap if it has one, else the schema's."""
    cap = CAPS.get((model.__name__, name))
    if cap is not None:
        return cap
    info = model.model_fields[name]
    strategy = value(info.annotation, info.metadata, path + (name,))
    if is_model(non_none(info.annotation)):
        return strategy
    # The field's own validators (e.g. no control characters in names), whatever they are
    adapter = _adapter(model, name)
    return strategy.filter(lambda v: _valid(adapter, v))


_ADAPTERS: dict[tuple[str, str], TypeAdapter] = {}


def _adapter(model: type[BaseModel], name: str) -> TypeAdapter:
    key = (model.__name__, name)
    if key not in _ADAPTERS:
        info = model.model_fields[name]
        _ADAPTERS[key] = TypeAdapter(typing.Annotated[info.annotation, *info.metadata]
                                     if info.metadata else info.annotation)
    return _ADAPTERS[key]


def _valid(adapter: TypeAdapter, v: Any) -> bool:
    try:
        adapter.validate_python(v)
    except ValidationError:
        return False
    return True


def section(model: type[BaseModel], path: tuple = ()) -> st.SearchStrategy[dict]:
    """A valid dict for ``model``: every required field, each optional one or not."""

    @st.composite
    def build(draw):
        d: dict[str, Any] = {}
        for name, info in model.model_fields.items():
            if (model.__name__, name) in SKIP:
                continue
            if info.is_required() or draw(st.booleans()):
                d[name] = draw(field_value(model, name, path))
        couple = COUPLINGS.get(model.__name__)
        if couple is not None:
            d = couple(draw, d, lambda n: field_value(model, n, path))
        return d

    return build()


def field_paths(model: type[BaseModel] = Scene, path: tuple = ()
                ) -> list[tuple[tuple, Any, Any]]:
    """Every (path, annotation, field info) of the schema, nested models included."""
    out = []
    for name, info in model.model_fields.items():
        out.append((path + (name,), info.annotation, info))
        inner = non_none(info.annotation)
        if typing.get_origin(inner) is tuple and typing.get_args(inner)[-1] is Ellipsis:
            inner = typing.get_args(inner)[0]
        if is_model(inner):
            out += field_paths(inner, path + (name,))
    return out


# -------------------------------------------------------------------------- couplings
Draw = Callable[[st.SearchStrategy], Any]
Get = Callable[[str], st.SearchStrategy]


def _only(d: dict, *keep: str, drop: tuple[str, ...] = ()) -> dict:
    return {k: v for k, v in d.items() if k not in drop or k in keep}


def _sea(draw: Draw, d: dict, get: Get) -> dict:
    for n in ("nx", "ny"):
        if n in d and d[n] % 2:
            d[n] += 1 if d[n] < 16384 else -1
    if d.get("spectrum") == "jonswap" and "fetch_m" not in d:
        d["fetch_m"] = draw(get("fetch_m"))
    if "fetch_m" in d:  # within what the spectrum's fetch law describes
        from seaecho.config.sea import SeaConfig
        from seaecho.ocean.limits import fetch_range

        sea = SeaConfig.model_validate(d)
        laws = {sea.spectrum} - {"pierson-moskowitz"}
        laws |= {"elfouhaily"} if sea.spreading == "elfouhaily" else set()
        ranges = [fetch_range(law, sea.wind_speed_m_s) for law in laws]
        lo, hi = max((r[0] for r in ranges), default=0.0), min((r[1] for r in ranges),
                                                               default=math.inf)
        if laws and not lo <= d["fetch_m"] <= hi:
            d["fetch_m"] = draw(st.floats(lo, min(hi, 1.0e8, 100.0 * lo)))
    if "depth_m" in d:  # deep enough for the waves (McCowan's breaking limit)
        from seaecho.build import section_spectrum
        from seaecho.config.sea import SeaConfig
        from seaecho.ocean.limits import min_depth

        least = min_depth(section_spectrum(SeaConfig.model_validate(d)))
        if d["depth_m"] < least:
            d["depth_m"] = min(least * draw(st.floats(1.01, 10.0)), 1.0e5)
    return d


def _run(draw: Draw, d: dict, get: Get) -> dict:
    if "surface_times_s" in d:
        d["surface_times_s"] = tuple(sorted(d["surface_times_s"]))
    return d


def _ship(draw: Draw, d: dict, get: Get) -> dict:
    d = _only(d, drop=("speed_kn", "speed_m_s"))
    speed = draw(st.sampled_from(["speed_kn", "speed_m_s"]))
    d[speed] = draw(get(speed))
    from seaecho.config.ship import MIN_WAVE_SPEED_M_S
    from seaecho.constants import KNOT

    v = d[speed] * (KNOT if speed == "speed_kn" else 1.0)
    if 0 < v < MIN_WAVE_SPEED_M_S:  # a wave wake needs the slowest water wave's speed
        d[speed] = 0.0
    if not 0.01 * d["length_m"] <= d["beam_m"] < d["length_m"]:
        d["beam_m"] = min(d["length_m"] * draw(st.floats(0.02, 0.5)), 80.0)
    # no hull echo (a ray trace per ship); a route of two legs that its turn fits, or none
    d = _only(d, drop=("waypoints_m", "turn_rate_deg_s", "turn_radius_m", "hull_echo",
                       "hull_mesh", "wave_motion", "wave_response", "metacentric_height_m",
                       "hull_rays_per_wavelength"))
    if d[speed] > 0.0 and draw(st.booleans()):
        d = _only(d, drop=("heading_deg", "position_m"))
        x0, y0, a, b = draw(st.tuples(_near, _near, st.floats(50.0, 500.0),
                                      st.floats(50.0, 500.0)))
        b = b if draw(st.booleans()) else -b
        d["waypoints_m"] = ((x0, y0), (x0 + a, y0), (x0 + a, y0 + b))
        d["turn_radius_m"] = draw(st.floats(0.1, 25.0))
    return d


def _waveform(draw: Draw, d: dict, get: Get) -> dict:
    if d.get("kind", "lfm") == "lfm":
        d.setdefault("bandwidth_hz", draw(get("bandwidth_hz")))
        b, t = d["bandwidth_hz"], d["duration_s"]
        if b * t < 1.0:  # a chirp sweeps its band only if B T >= 1
            if 1.0 / t <= 1.0e10:
                d["bandwidth_hz"] = 1.0 / t * draw(st.floats(1.0, 2.0))
                while d["bandwidth_hz"] * t < 1.0:  # (1 / T) T may round below 1
                    d["bandwidth_hz"] = math.nextafter(d["bandwidth_hz"], math.inf)
            else:
                d["duration_s"] = min(1.0 / b * draw(st.floats(1.0, 2.0)), 1.0e-2)
                while b * d["duration_s"] < 1.0 and d["duration_s"] < 1.0e-2:
                    d["duration_s"] = math.nextafter(d["duration_s"], math.inf)
    else:
        d.pop("bandwidth_hz", None)
    return d


def _antenna(draw: Draw, d: dict, get: Get) -> dict:
    d = _only(d, drop=("look_at_m", "track_look_at", "azimuth_deg", "depression_deg"))
    if draw(st.booleans()):
        d["look_at_m"] = draw(get("look_at_m"))
        d["track_look_at"] = draw(st.booleans())
    else:
        d["azimuth_deg"], d["depression_deg"] = draw(get("azimuth_deg")), draw(
            get("depression_deg"))
    if d.get("pattern", "rectangular") == "rectangular":
        d.setdefault("width_m", draw(get("width_m")))
        d.setdefault("height_m", draw(get("height_m")))
    else:
        d.pop("illumination", None)  # a taper needs the rectangular aperture
    if d.get("scan", {}).get("mode", "fixed") != "fixed":  # pointed by its scan
        d = _only(d, drop=("look_at_m", "track_look_at", "azimuth_deg"))
        d.setdefault("depression_deg", draw(get("depression_deg")))
    return d


def _scan(draw: Draw, d: dict, get: Get) -> dict:
    mode = d.get("mode", "fixed")
    d = _only(d, drop=("rate_rpm", "start_deg", "sector_deg"))
    if mode == "fixed":
        return d
    d["rate_rpm"] = draw(get("rate_rpm"))
    if mode == "sector":
        d["sector_deg"] = draw(st.tuples(st.floats(-360.0, 360.0), st.floats(-360.0, 360.0))
                               .filter(lambda a: (a[0] - a[1]) % 360.0 >= MIN_SECTOR_DEG))
    elif draw(st.booleans()):
        d["start_deg"] = draw(get("start_deg"))
    return d


def _platform(draw: Draw, d: dict, get: Get) -> dict:
    d = _only(d, drop=("position_m", "velocity_m_s", "waypoint_times_s",
                       "waypoint_positions_m"))
    motion = d.get("motion", "fixed")
    if motion in ("fixed", "linear"):
        d["position_m"] = draw(get("position_m"))
        if motion == "linear":
            d["velocity_m_s"] = draw(get("velocity_m_s"))
    else:
        # the run's pulses (t in [-1, 1.03] s with the caps) inside the waypoints, so that
        # no extrapolated segment dives into the sea
        times = [-3.0]
        for t in sorted({*draw(get("waypoint_times_s")), 3.0}):
            if t - times[-1] >= 0.5 or t == 3.0:  # <= 8 km/s across the capped box
                times.append(t)
        if times[-1] - times[-2] < 0.5:
            del times[-2]
        d["waypoint_times_s"] = tuple(times)
        d["waypoint_positions_m"] = tuple(draw(get("position_m")) for _ in times)
    return d


def _radar(draw: Draw, d: dict, get: Get) -> dict:
    w = d["waveform"]
    b = w.get("bandwidth_hz", 1.0 / w["duration_s"])
    if b > d["sampling_rate_hz"]:
        d["sampling_rate_hz"] = b * draw(st.floats(1.0, 4.0))
        if w.get("kind", "lfm") == "pulse":
            d["sampling_rate_hz"] = max(d["sampling_rate_hz"], 1.0 / w["duration_s"])
    if w["duration_s"] >= 1.0 / d["prf_hz"]:
        d["prf_hz"] = 0.5 / w["duration_s"]
    if ("window_start_m" in d) != ("window_end_m" in d):
        d.pop("window_start_m", None)
        d.pop("window_end_m", None)
    if "window_start_m" in d and d["window_end_m"] <= d["window_start_m"]:
        d["window_end_m"] = d["window_start_m"] + draw(st.floats(1.0, 3000.0))
    n = d.get("n_pulses", 1)
    if d.get("sigma_map_pulse", 0) >= n:
        d["sigma_map_pulse"] = n - 1
    if "channels" in d:
        d["channels"] = tuple(dict.fromkeys(d["channels"]))
    return d


def _perturbation(draw: Draw, d: dict, get: Get) -> dict:
    for n in ("position_sigma_m", "attitude_sigma_deg"):
        if n in d:
            d[n] = tuple(min(abs(x), 1.0e4) for x in d[n])
    return d


def _target(draw: Draw, d: dict, get: Get) -> dict:
    s = ("s_hh", "s_hv", "s_vh", "s_vv")
    if "preset" in d:  # a preset sets the RCS (the scene checks its carrier band)
        return _only(d, drop=s + ("rcs_m2",))
    if "rcs_m2" in d or not any(k in d for k in s):
        d = _only(d, drop=s)
        d["rcs_m2"] = d.get("rcs_m2", draw(get("rcs_m2")))
    for k in s:
        if k in d:
            d[k] = tuple(max(-1.0e5, min(1.0e5, x)) for x in d[k])
    return d


def _tracing(draw: Draw, d: dict, get: Get) -> dict:
    from seaecho.config.tracing import MIN_REFRESH_S

    if 0 < d.get("refresh_interval_s", 0.0) < MIN_REFRESH_S:
        d["refresh_interval_s"] = 0.0
    return d


def _object(draw: Draw, d: dict, get: Get) -> dict:
    if "relative_permittivity" in d or "conductivity_s_m" in d:
        d.pop("material", None)
        d.setdefault("relative_permittivity", draw(get("relative_permittivity")))
    d["file"] = str(MESH)
    if d.get("scatterer"):
        d["file"] = str(SCATTERER_MESH)
        d["scale"] = min(d.get("scale", 1.0), 2.0)
    else:
        d = _only(d, drop=SCATTERER_FIELDS)
    return d


def _image(draw: Draw, d: dict, get: Get) -> dict:
    if "filter_size" in d:
        d["filter_size"] = min(d["filter_size"] | 1, 101)  # odd
        if d.get("speckle_filter") == "refined-lee":
            d["filter_size"] = max(d["filter_size"], 5)
    if max(d.get("looks", (1, 1))) > 1:  # the default pixel may be as large as the tile
        d.setdefault("pixel_m", 1.0)
    if "extent_m" in d:
        x0, x1, y0, y1 = d["extent_m"]
        x0, x1, y0, y1 = min(x0, x1), max(x0, x1), min(y0, y1), max(y0, y1)
        least = 2.0 * d.get("pixel_m", 1.0)  # room for the 2 x 2 looks the caps allow
        d["extent_m"] = (x0, max(x1, x0 + least), y0, max(y1, y0 + least))
    if "looks" in d:
        d["looks"] = tuple(min(max(n, 1), 1000) for n in d["looks"])
        if "extent_m" not in d:  # room for the looks: the default extent may be 1 pixel
            least = 2.0 * d.get("pixel_m", 1.0)
            d["extent_m"] = (-10.0, max(10.0, least), -10.0, max(10.0, least))
    return d


def _scene(draw: Draw, d: dict, get: Get) -> dict:
    if "ship" in d:  # [ship] or [[ships]]
        d.pop("ships", None)
    if d.get("ships"):
        d["ships"] = tuple({**sh, "name": f"ship{i}"} for i, sh in enumerate(d["ships"]))
    from seaecho.config.radar import PRESET_BANDS

    carrier = (d.get("radar") or {}).get("carrier_frequency_hz", 0.0)
    if not any(lo <= carrier <= hi for lo, hi in PRESET_BANDS.values()):
        d["targets"] = tuple({**_only(g, drop=("preset",)), "rcs_m2": g.get("rcs_m2", 1.0)}
                             if "preset" in g else g for g in d.get("targets", ()))
    objects = []
    for i, obj in enumerate(d.get("objects", ())):
        obj = {**obj, "name": f"{obj['name']}{i}"}  # unique names
        if "ship" not in d or "waypoints_m" in d["ship"]:  # a straight [ship] only
            obj.pop("follow_ship", None)
        objects.append(obj)
    if objects:
        d["objects"] = tuple(objects)
    image, radar = d.get("image"), d.get("radar")
    if radar is not None and objects:  # an ITU material defined at the carrier
        from seaecho.tracing.sbr import material_permittivity

        for obj in objects:
            try:
                if obj.get("material"):
                    material_permittivity(radar["carrier_frequency_hz"],
                                          itu_type=obj["material"])
            except ValueError:
                obj["material"] = "metal"
    if image is not None and radar is not None:
        # at least 2 x 2 pixels (the default pixel c / (8 B) may exceed a small tile)
        w = radar["waveform"]
        pixel = image.get("pixel_m", 3.0e8 / (8.0 * w.get("bandwidth_hz",
                                                          1.0 / w["duration_s"])))
        x0, x1, y0, y1 = image.get("extent_m", (-10.0, 10.0, -10.0, 10.0))
        if "extent_m" in image or not (d.get("targets") or radar.get("sea_clutter", True)
                                       ) or 2.1 * pixel > min(
                d["sea"]["size_x_m"], d["sea"].get("size_y_m", d["sea"]["size_x_m"])):
            image["extent_m"] = (x0, max(x1, x0 + 2.1 * pixel), y0, max(y1, y0 + 2.1 * pixel))
    radar, tx = d.get("radar"), d.get("transmitter")
    if radar is not None and tx is None:
        d["transmitter"] = tx = draw(get("transmitter"))
    if radar is not None:
        minimal = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 8.0, "nx": 8},
                   "transmitter": tx, "receiver": d.get("receiver")}
        if minimal["receiver"] is None:
            del minimal["receiver"]
        allowed = allowed_channels(parse_scene(minimal))
        radar["channels"] = tuple(draw(st.lists(st.sampled_from(allowed), min_size=1,
                                                max_size=4, unique=True)))
        if not radar.get("sea_clutter", True) and not d.get("targets") and (
                "window_start_m" not in radar):
            radar["sea_clutter"] = True
    return d


COUPLINGS: dict[str, Callable[[Draw, dict, Get], dict]] = {
    "SeaConfig": _sea, "RunConfig": _run, "ShipConfig": _ship, "WaveformConfig": _waveform,
    "AntennaConfig": _antenna, "PlatformConfig": _platform, "RadarConfig": _radar,
    "GaussMarkovConfig": _perturbation, "TargetConfig": _target, "ObjectConfig": _object,
    "TracingConfig": _tracing, "ImageConfig": _image, "ScanConfig": _scan,
    "Scene": _scene,
}

# ------------------------------------------------------------------------------ caps
_xy = st.floats(-2000.0, 2000.0)
_near = st.floats(-200.0, 200.0)

#: Tighter ranges for a tiny, fast, runnable scene ((model, field) -> strategy).
TINY: dict[tuple[str, str], st.SearchStrategy] = {
    ("SeaConfig", "nx"): st.integers(2, 8).map(lambda n: 2 * n),
    ("SeaConfig", "ny"): st.integers(2, 8).map(lambda n: 2 * n),
    ("SeaConfig", "size_x_m"): st.floats(4.0, 64.0),
    ("SeaConfig", "size_y_m"): st.floats(4.0, 64.0),
    ("RadarConfig", "carrier_frequency_hz"): st.floats(1.0e9, 2.0e10),
    ("RadarConfig", "sampling_rate_hz"): st.floats(1.0e6, 2.0e8),
    ("RadarConfig", "prf_hz"): st.floats(100.0, 1.0e4),
    ("RadarConfig", "n_pulses"): st.integers(1, 3),
    ("RadarConfig", "start_time_s"): st.floats(-1.0, 1.0),
    ("RadarConfig", "sea_update_pulses"): st.integers(1, 3),
    ("RadarConfig", "sigma_map_pulse"): st.integers(0, 2),
    ("RadarConfig", "window_start_m"): st.floats(0.0, 5000.0),
    ("RadarConfig", "window_end_m"): st.floats(1.0, 8000.0),
    ("WaveformConfig", "duration_s"): st.floats(1.0e-7, 2.0e-6),
    ("WaveformConfig", "bandwidth_hz"): st.floats(1.0e5, 2.0e8),
    ("PlatformConfig", "position_m"): st.tuples(_xy, _xy, st.floats(150.0, 3000.0)),
    ("PlatformConfig", "velocity_m_s"): st.tuples(st.floats(-300.0, 300.0),
                                                  st.floats(-300.0, 300.0),
                                                  st.floats(-50.0, 50.0)),
    ("PlatformConfig", "waypoint_times_s"): st.lists(st.floats(-2.0, 2.0), min_size=2,
                                                     max_size=4).map(tuple),
    ("GaussMarkovConfig", "position_sigma_m"): st.tuples(*[st.floats(0.0, 10.0)] * 3),
    ("GaussMarkovConfig", "step_s"): st.floats(1.0e-3, 10.0),
    ("AntennaConfig", "width_m"): st.floats(0.01, 0.5),
    ("AntennaConfig", "height_m"): st.floats(0.01, 0.5),
    ("AntennaConfig", "look_at_m"): st.tuples(_near, _near, st.floats(-10.0, 10.0)),
    ("TargetConfig", "position_m"): st.tuples(_near, _near, st.floats(-5.0, 50.0)),
    ("TargetConfig", "velocity_m_s"): st.tuples(*[st.floats(-50.0, 50.0)] * 3),
    ("ShipConfig", "position_m"): st.tuples(_near, _near),
    ("TracingConfig", "variant"): st.just("llvm_ad_mono_polarized"),
    ("ObjectConfig", "rays_per_wavelength"): st.floats(1.0, 2.0),
    ("ObjectConfig", "max_bounces"): st.integers(1, 2),
    ("ObjectConfig", "signature_cell_m"): st.floats(0.05, 1.0),
    ("ImageConfig", "pixel_m"): st.floats(1.0, 20.0),
    ("ImageConfig", "extent_m"): st.tuples(_near, _near, _near, _near),
    ("ImageConfig", "upsample"): st.integers(1, 4),
    ("ImageConfig", "filter_size"): st.integers(3, 9),
    ("ImageConfig", "looks"): st.tuples(st.integers(1, 2), st.integers(1, 2)),
    ("Scene", "targets"): st.lists(section(TargetConfig, ("targets",)), max_size=3).map(tuple),
    ("Scene", "objects"): st.lists(section(ObjectConfig, ("objects",)), max_size=1).map(tuple),
    ("Scene", "ships"): st.lists(section(ShipConfig, ("ships",)), max_size=2).map(tuple),
}
CAPS = {
    **TINY,
    # a level in [-300, 0] dB (its validator's range) or 'off'
    ("RadarConfig", "sea_gain_floor_db"): st.one_of(
        st.floats(-300.0, 0.0, allow_nan=False), st.just("off")),
    # (0, 600] rpm and not 0 rad/s once converted (its validator)
    ("ScanConfig", "rate_rpm"): st.floats(1.0e-300, 600.0),
    # each component within [-5, 5] m/s (its validator's range)
    ("SeaConfig", "current_m_s"): st.tuples(st.floats(-5.0, 5.0, allow_nan=False),
                                            st.floats(-5.0, 5.0, allow_nan=False)),
}
#: Fields left out of generated scenes: an output path would write beside the tests;
#: [[receivers]] (multistatic; its cross-receiver rules are tested in tests/multistatic);
#: [[land]] (a mesh of up to 2^21 cells per entry; its rules and the check's refusals are
#: tested in tests/tracing/test_land.py); [sea] coverage = "radar" (it needs a window, a
#: fixed monostatic fan beam and the sub-facet shadowing, and a run computes hundreds of
#: tiles: its refusals are tested in tests/test_coverage_sea.py).
SKIP = {("RunConfig", "output"), ("Scene", "receivers"), ("Scene", "land"),
        ("SeaConfig", "coverage")}


def scenes(runnable: bool = True) -> st.SearchStrategy[dict]:
    """Valid scene dicts; ``runnable``: with [radar] and [transmitter] (for `run`)."""
    base = section(Scene)
    if not runnable:
        return base

    @st.composite
    def build(draw):
        d = draw(base)
        if "radar" not in d:
            d["radar"] = draw(section(RadarConfig, ("radar",)))
        if "transmitter" not in d:
            d["transmitter"] = draw(section(PlatformConfig, ("transmitter",)))
        d = _scene(draw, d, lambda n: field_value(Scene, n))
        return _with_image_noise_held(_with_subfacet_slopes(d))

    return build()


def _with_image_noise_held(d: dict) -> dict:
    """An [image] whose thermal noise its file can hold (the preflight refuses a
    noise-equivalent RCS above ``MAX_IMAGE_NOISE_RCS``, e.g. at 5e-324 W): else 1 kW
    and the default noise figure, else no thermal noise."""
    from seaecho.checks.preflight import MAX_IMAGE_NOISE_RCS, image_noise_rcs

    if image_noise_rcs(parse_scene(d)) <= MAX_IMAGE_NOISE_RCS:
        return d
    d["radar"] = {**d["radar"], "transmit_power_w": 1.0e3}
    d["radar"].pop("noise_figure_db", None)
    if image_noise_rcs(parse_scene(d)) > MAX_IMAGE_NOISE_RCS:
        d["radar"]["thermal_noise"] = False
    return d


def _with_subfacet_slopes(d: dict) -> dict:
    """A sea whose unresolved waves carry slope at the carrier (the builder refuses a
    calm sea without sub-facet slopes, and a grid that resolves every wave longer than
    the two-scale split): else a 5 m/s fully developed sea on a grid of at least 0.5 m
    (the split, 2 pi / k_cut, is at most 0.9 m from the carriers' 1 GHz up)."""
    if not d["radar"].get("sea_clutter", True):
        return d
    import warnings

    from seaecho.build import build_sea_model

    try:
        with warnings.catch_warnings():  # the run says them; here only the outcome counts
            warnings.simplefilter("ignore")
            build_sea_model(parse_scene(d))
    except ValueError:
        sea = {k: v for k, v in d["sea"].items() if k not in ("fetch_m", "depth_m")}
        sea["size_x_m"] = max(sea["size_x_m"], 0.5 * sea["nx"])
        sea["size_y_m"] = max(sea.get("size_y_m", sea["size_x_m"]),
                              0.5 * sea.get("ny", sea["nx"]))
        d["sea"] = {**sea, "wind_speed_m_s": 5.0, "spectrum": "elfouhaily"}
    return d


def finite_floats(x: Any) -> bool:
    """True if every float in a nested structure is finite."""
    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, dict):
        return all(finite_floats(v) for v in x.values())
    if isinstance(x, list | tuple):
        return all(finite_floats(v) for v in x)
    return True
