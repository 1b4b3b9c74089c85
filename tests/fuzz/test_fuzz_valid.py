"""Fuzzing, valid side: scenes drawn from the schema validate, pass `seaecho check` and
run to finite data on a tiny grid."""

from __future__ import annotations

import tomllib

from fuzz_harness import assert_clean, examples, run_cli, scene_text
from fuzz_schema import scenes
from hypothesis import HealthCheck, given, settings

from seaecho.config import parse_scene

SLOW = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much]


@settings(max_examples=examples(60), deadline=None, suppress_health_check=SLOW)
@given(data=scenes(runnable=False))
def test_schema_generated_scenes_validate_and_round_trip(data):
    """Every generated scene is valid, and written as TOML it reads back the same."""
    scene = parse_scene(data)
    text = scene_text(data)
    assert parse_scene(tomllib.loads(text)) == scene


@settings(max_examples=examples(6), deadline=None, suppress_health_check=SLOW)
@given(data=scenes())
def test_valid_scene_passes_check_and_runs_to_finite_data(data):
    text = scene_text(data)
    checked = run_cli("check", text)
    assert_clean(checked, text)
    assert checked.rc == 0, f"check refused a valid scene\n{text}\n{checked.err}"
    ran = run_cli("run", text)
    assert_clean(ran, text)
    assert ran.rc == 0, f"run refused a scene check accepted\n{text}\n{ran.err}"
    assert ran.finite is True
