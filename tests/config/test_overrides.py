"""Overrides by dotted name (one implementation for the command line and the API)."""

from pathlib import Path

import pytest

from seaecho.config import SceneError, load_scene
from seaecho.config.overrides import parse_assignment, parse_assignments, with_overrides

ROOT = Path(__file__).resolve().parents[2]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"


def test_values_replace_fields_and_the_rest_is_kept():
    scene = load_scene(SIM1)
    new = with_overrides(scene, {"sea.wind_speed_m_s": 8.0, "radar.n_pulses": 3,
                                 "radar.waveform.bandwidth_hz": 100e6,
                                 "transmitter.antenna.look_at_m": [1.0, 2.0, 0.0]})
    assert new.sea.wind_speed_m_s == 8.0
    assert new.radar.n_pulses == 3
    assert new.radar.waveform.bandwidth_hz == 100e6
    assert tuple(new.transmitter.antenna.look_at_m) == (1.0, 2.0, 0.0)
    assert new.ship == scene.ship and new.sea.nx == scene.sea.nx
    assert scene.sea.wind_speed_m_s == 4.53  # the input scene is unchanged


def test_array_of_tables_by_index():
    scene = load_scene(SIM1)
    new = with_overrides(scene, {"objects.0.material": "concrete"})
    assert new.objects[0].material == "concrete"
    with pytest.raises(SceneError, match=r"index 3 out of range \(the array has 1"):
        with_overrides(scene, {"objects.3.material": "metal"})


@pytest.mark.parametrize(("name", "value", "fragments"), [
    ("sea.wind_speed_m_s", -3.0, ["[sea].wind_speed_m_s", "-3.0"]),
    ("sea.no_such_field", 1, ["no_such_field", "unknown key"]),
    ("radar.waveform.kind", "square", ["waveform", "kind", "square"]),
])
def test_bad_name_or_value_names_the_field(name, value, fragments):
    with pytest.raises(SceneError) as err:
        with_overrides(load_scene(SIM1), {name: value})
    for f in fragments:
        assert f in str(err.value)


def test_name_into_a_number_is_refused():
    with pytest.raises(SceneError, match="is not a section"):
        with_overrides(load_scene(SIM1), {"sea.nx.foo": 1})


@pytest.mark.parametrize(("text", "expected"), [
    ("sea.wind_speed_m_s=8", ("sea.wind_speed_m_s", 8)),
    ("radar.carrier_frequency_hz = 1.5e9", ("radar.carrier_frequency_hz", 1.5e9)),
    ("radar.thermal_noise=true", ("radar.thermal_noise", True)),
    ("transmitter.position_m=[0, 0, 10]", ("transmitter.position_m", [0, 0, 10])),
    ("sea.spectrum=elfouhaily", ("sea.spectrum", "elfouhaily")),
    ('sea.spectrum="jonswap"', ("sea.spectrum", "jonswap")),
])
def test_command_line_assignments_read_toml_values(text, expected):
    assert parse_assignment(text) == expected


@pytest.mark.parametrize("text", ["sea.nx", "=3", "sea..nx=3", "1sea=3", "sea.nx x=3"])
def test_malformed_assignments_are_refused(text):
    with pytest.raises(SceneError):
        parse_assignment(text)


def test_repeated_name_last_wins():
    assert parse_assignments(["sea.nx=32", "sea.nx=64"]) == {"sea.nx": 64}
