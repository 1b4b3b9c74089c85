"""Fuzzing, broken side: every mutation of a valid scene ends in exit 0 or in exit 2 with
one message naming the field; never a traceback, never a file left behind; `check`
refuses what `run` refuses; a run that exits 0 wrote finite data."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from fuzz_harness import MAX_MEMORY_GB, assert_clean, examples, run_cli, scene_text
from fuzz_mutations import KINDS, Mutation, mutations
from fuzz_schema import scenes
from hypothesis import HealthCheck, event, example, given, note, settings
from hypothesis import strategies as st

SLOW = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]
#: Mutated scenes whose run is estimated longer than this are only checked [s].
MAX_RUN_S = 30.0


def _text(m) -> str:
    return m.text if m.text is not None else scene_text(m.data)


#: Refusals of a valid scene for its size: a mutation that is itself valid (a target
#: added far away, an optional name removed) may push the run or its image over the
#: memory or pixel limits; such a refusal names the fields that set the size, not the
#: mutated one.
RESOURCE_REFUSALS = ("does not fit in memory", "pixels, more than", "the image can hold")


def _names_the_field(m, err: str) -> bool:
    if any(r in err for r in RESOURCE_REFUSALS):
        return "[image]." in err or "[radar]." in err or "[sea]." in err
    return not m.names or any(n in err for n in m.names)


@pytest.mark.parametrize("kind", KINDS)
def test_check_of_a_mutated_scene_is_clean(kind):
    @settings(max_examples=examples(10), deadline=None, suppress_health_check=SLOW)
    @given(m=mutations(st.one_of(scenes(runnable=False), scenes()), kinds=(kind,)))
    def check(m):
        _check_is_clean(m)

    check()


def _check_is_clean(m):
    text = _text(m)
    note(f"{m.kind} mutation, names {m.names}\n{text[:3000]}")
    out = run_cli("check", text)
    event(f"{m.kind} -> exit {out.rc}" + (" (radar)" if "[radar]" in text else ""))
    assert_clean(out, f"{m.kind}: {text[:3000]}")
    if out.rc == 2:
        assert _names_the_field(m, out.err), (m.kind, m.names, out.err)


CAL = Path(__file__).resolve().parents[2] / "scenes" / "calibration_point_target.toml"


def _calibration(**radar) -> dict:
    """The calibration scene's dict with ``[radar]`` fields (dotted: waveform.x) changed."""
    import tomllib

    data = tomllib.loads(CAL.read_text())
    for key, value in radar.items():
        section, _, field = key.rpartition(".")
        (data["radar"][section] if section else data["radar"])[field] = value
    return data


@settings(max_examples=examples(6), deadline=None, suppress_health_check=SLOW)
@given(m=mutations(scenes()))
# Too large for memory whole and in 2 pulses (4e7 samples a pulse): check and run both
# refuse it, which is consistent (a random run once drew such a scene, and the test
# demanded that run accept it)
@example(m=Mutation("value", _calibration(window_start_m=0.0, window_end_m=3.0e7), None, ()))
def test_run_of_a_mutated_scene_agrees_with_check(m):
    _check_then_run(m)


def _with(data: dict, **sections) -> dict:
    """``data`` with top-level sections added or updated."""
    for name, fields in sections.items():
        data.setdefault(name, {}).update(fields)
    return data


def _trihedral_with_transmitter_at(position_m: list[float]) -> dict:
    """The trihedral calibration scene, its mesh found from anywhere, its transmitter at
    ``position_m`` (looking up): inside the hull's launch sphere at the object's origin,
    a scene `check` accepted and whose `run` stopped with a traceback in the tracer."""
    import tomllib

    tri = CAL.with_name("calibration_trihedral.toml")
    data = tomllib.loads(tri.read_text())
    data["objects"][0]["file"] = str(tri.parent / data["objects"][0]["file"])
    data["transmitter"]["position_m"] = position_m
    data["transmitter"]["antenna"]["look_at_m"] = [0.0, 0.0, 20.0]
    return data


#: Found by a random hunt of ``radar`` mutations (361 scenes): a sea whose band between
#: the grid and the two-scale split has no crosswind slope (mss 0.0038 upwind, 0
#: crosswind) with [tracing] subfacet_shadowing: `check` accepted it, `run` refused it
#: ("subfacet = (...): slope variances must be > 0", the facet engine's check).
NO_CROSSWIND_SLOPE = """
[sea]
spreading_s = 48.73988068731162
wind_speed_m_s = 23.28596850472772
wind_direction_deg = -169.37073213074484
fetch_m = 62388696.41978159
size_x_m = 5.685519159554115
size_y_m = 8.331399962082116
nx = 14
ny = 16
salinity_psu = 1.1008150990472901e-218

[ship]
length_m = 183.17110004653793
beam_m = 33.81807562298543
draft_m = 18.018766808656537
heading_deg = -189.0519272144531
turbulent_wake_length_m = 69155.60513784636
speed_kn = 38.37292819773275

[radar]
carrier_frequency_hz = 1478356726.5181434
sampling_rate_hz = 49071032.26972335
prf_hz = 4788.408665552279
start_time_s = 0.02004534829205995
channels = ["VV", "HH"]
sea_update_pulses = 3
accumulation_precision = "double"
noise_figure_db = 8.336408753386127
noise_bandwidth_hz = 21909903720.34179
taylor_nbar = 47
taylor_sidelobe_db = 150.0
sigma_map_pulse = 0

[radar.waveform]
kind = "pulse"
duration_s = 1.192092896e-07

[transmitter]
roll_deg = -81.66433849431854
position_m = [1643.5932768100283, 8.317957358894541e-51, 200.0]

[transmitter.perturbation]
position_sigma_m = [1.1, 9.999999999999998, 0.3434485124022291]
position_tau_s = 2.340236489539287e-275
attitude_tau_s = 2.225073858507e-311

[transmitter.antenna]
pattern = "dipole"
width_m = 0.35548562548432827
height_m = 0.21448964950475388
azimuth_deg = 51.87288309536052
depression_deg = -73.37892223179371

[tracing]
shadowing = "smith"
subfacet_shadowing = true
refresh_interval_s = 24.0
"""


#: Scenes `check` accepted and `run` refused, through ``[run] output`` (found by reading
#: what `run` refuses; the hunts' scenes never set it, the ``radar`` mutation does now): a
#: folder that does not exist, and a Zarr store with ``[image]`` (the preflight checks
#: the output now).
IMAGE = {"pixel_m": 0.5, "extent_m": [-4.0, 4.0, -4.0, 4.0], "figures": False}


@settings(max_examples=examples(4), deadline=None, suppress_health_check=SLOW)
@given(m=mutations(scenes(), kinds=("radar",)))
@example(m=Mutation("radar", _with(_calibration(), run={"output": "no_such_folder/r.nc"}),
                    None, ("[run].output",)))
@example(m=Mutation("radar", _with(_calibration(), run={"output": "r.zarr"}, image=IMAGE),
                    None, ("[run].output",)))
@example(m=Mutation("radar", tomllib.loads(NO_CROSSWIND_SLOPE), None,
                    ("[tracing].subfacet_shadowing",)))
@example(m=Mutation("radar", _with(_calibration(), run={"output": "."}), None,
                    ("[run].output",)))
@example(m=Mutation("radar", _trihedral_with_transmitter_at([0.0, 0.0, 2.0]), None,
                    ("[transmitter].position_m",)))
def test_check_accepts_only_what_run_runs(m):
    """Radar-side values that stress the models (``radar`` mutations): whatever `check`
    accepts, `run` runs to finite data, and what check refuses, run refuses."""
    _check_then_run(m)


def _check_then_run(m):
    text = _text(m)
    note(f"{m.kind} mutation, names {m.names}\n{text[:3000]}")
    checked = run_cli("check", text)
    assert_clean(checked, text[:3000])
    if checked.rc == 0 and _estimated_time(text) > MAX_RUN_S:
        event(f"{m.kind} -> check 0, run skipped (estimated > {MAX_RUN_S} s)")
        return
    ran = run_cli("run", text, "--pulses", "2")
    event(f"{m.kind} -> check {checked.rc}, run {ran.rc}")
    assert_clean(ran, text[:3000])
    _agree(text, checked, ran)


def _agree(text: str, checked, ran) -> None:
    """`check` (the whole run) and `run --pulses 2` agree: a refusal of check for
    anything but memory is a refusal of run; a refusal of check for memory allows
    either (2 pulses may fit where the whole run does not; a refusal of both is
    consistent); what check accepts, run runs to finite data."""
    runnable = "[radar]" in text and "[transmitter]" in text
    memory = "does not fit in memory"
    if checked.rc == 2 and memory not in checked.err:
        assert ran.rc == 2, "run accepted what check refused\n" + checked.err
    elif checked.rc == 2:  # refused for memory (and maybe more): run may fit, or not
        assert ran.rc == 2 or ran.finite is True
    elif runnable and "needs [radar]" not in ran.err:
        assert ran.rc == 0, "run refused what check accepted\n" + ran.err
        assert ran.finite is True


def _estimated_time(text: str) -> float:
    """Estimated time of `run --pulses 2` (0 for a scene that `run` refuses at once)."""
    import tomllib

    from seaecho.checks.resources import estimate
    from seaecho.config import parse_scene

    scene = parse_scene(tomllib.loads(text))
    if scene.radar is None or scene.transmitter is None:
        return 0.0
    n = min(2, scene.radar.n_pulses)
    radar = scene.radar.model_copy(update={"n_pulses": n, "sigma_map_pulse": 0})
    return estimate(scene.model_copy(update={"radar": radar}), figures=False).time_s


@pytest.mark.parametrize("mutation", [
    ("nx = 64", "nx = -64", "[sea].nx"),
    ("wind_speed_m_s = 5.0", "wind_speed_m_s = nan", "[sea].wind_speed_m_s"),
    ("[radar]", "[radar]\nx = [[[[[[[[1]]]]]]]]", "[radar].x"),
])
def test_console_script_on_broken_scenes(tmp_path, mutation):
    """A few cases through the installed ``seaecho`` script (a new process each)."""
    old, new, named = mutation
    scene = tmp_path / "s.toml"
    scene.write_text(CAL.read_text().replace(old, new, 1))
    script = Path(sys.executable).with_name("seaecho")
    for cmd in (["check", str(scene)], ["run", str(scene), "-o", str(tmp_path / "o.nc"),
                                        "--max-memory-gb", MAX_MEMORY_GB]):
        r = subprocess.run([str(script), *cmd], capture_output=True, text=True, timeout=120)
        assert r.returncode == 2 and named in r.stderr and "Traceback" not in r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
