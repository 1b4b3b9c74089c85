"""Scene files: validation, clear errors, round trip; every bundled scene is valid."""

import tomllib
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seaecho.config import Scene, SceneError, load_scene, parse_scene
from seaecho.constants import KNOT

ROOT = Path(__file__).resolve().parents[2]
SCENES = sorted((ROOT / "scenes").glob("*.toml"))


@pytest.mark.parametrize("path", SCENES, ids=[p.name for p in SCENES])
def test_bundled_scenes_are_valid(path):
    scene = load_scene(path)
    assert isinstance(scene, Scene)


def test_paper_scenes_present():
    names = {p.name for p in SCENES}
    for expected in ("paper_sim1_bistatic_64m.toml", "paper_sim2_sar_128m_wind55.toml",
                     "paper_sim3_sar_128m_wind0.toml", "paper_sim4_sar_500m_u10.toml"):
        assert expected in names


def test_sim1_values_from_the_paper():
    s = load_scene(ROOT / "scenes" / "paper_sim1_bistatic_64m.toml")
    assert s.sea.size_m == (64.0, 64.0)
    assert s.sea.wind_speed_m_s == 4.53
    assert s.ship.speed == pytest.approx(10 * KNOT)
    assert (s.ship.length_m, s.ship.beam_m, s.ship.draft_m, s.ship.heading_deg) == (
        10.0, 4.0, 1.5, 35.0)


def _minimal(**sea):
    d = {"sea": {"wind_speed_m_s": 5.0, "size_x_m": 64.0, "nx": 64}}
    d["sea"].update(sea)
    return d


@pytest.mark.parametrize(
    ("data", "fragments"),
    [
        (_minimal(wind_speed_m_s=-3.0), ["[sea].wind_speed_m_s", "-3.0",
                                         "greater than or equal to 0.3", "[m/s]"]),
        (_minimal(wind_speed_m_s="fast"), ["[sea].wind_speed_m_s", '"fast"', "number"]),
        (_minimal(nx=63), ["nx = 63", "even"]),
        (_minimal(spectrum="bretschneider"), ["[sea].spectrum", "bretschneider",
                                             "pierson-moskowitz"]),
        (_minimal(colour="blue"), ["[sea].colour", "unknown key", "wind_speed_m_s"]),
        ({"sea": {"size_x_m": 1.0, "nx": 8}}, ["[sea].wind_speed_m_s", "missing"]),
        (_minimal(spectrum="jonswap"), ["fetch_m is required"]),
        ({**_minimal(), "ship": {"length_m": 10, "beam_m": 4, "draft_m": 1}},
         ["speed_kn", "speed_m_s"]),
        ({**_minimal(), "radarr": {}}, ["radarr", "unknown key"]),
        # an unbounded look-at point overflowed the preflight's distance (found by the
        # fuzzing suite): bounded as the platforms' positions
        ({**_minimal(), "transmitter": {"position_m": (0, 0, 150), "antenna": {
            "width_m": 0.5, "height_m": 0.5, "look_at_m": (1e308, 0, 0)}}},
         ["look_at_m", "1e+308", "+-1e+08"]),
    ],
)
def test_bad_values_name_field_value_and_allowed(data, fragments):
    with pytest.raises(SceneError) as info:
        parse_scene(data, source="s.toml")
    message = str(info.value)
    for fragment in fragments:
        assert fragment in message, message


def test_missing_and_malformed_files(tmp_path):
    with pytest.raises(SceneError, match="not found"):
        load_scene(tmp_path / "nope.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[sea\nwind = 3")
    with pytest.raises(SceneError, match="not valid TOML"):
        load_scene(bad)


def test_scene_is_frozen():
    scene = parse_scene(_minimal())
    with pytest.raises(Exception, match="frozen"):
        scene.sea.nx = 128  # type: ignore[misc]


@settings(max_examples=40, deadline=None)
@given(
    u=st.floats(0.3, 40.0), direction=st.floats(-360, 360), n=st.integers(2, 64),
    spectrum=st.sampled_from(["pierson-moskowitz", "elfouhaily"]),
    speed=st.one_of(st.just(0.0), st.floats(0.45, 60.0)), seed=st.integers(0, 2**63 - 1),
)
def test_round_trip(u, direction, n, spectrum, speed, seed):
    """A scene dumped to a dict and parsed again is the same scene."""
    data = _minimal(wind_speed_m_s=u, wind_direction_deg=direction, nx=2 * n,
                    spectrum=spectrum)
    data["ship"] = {"length_m": 50, "beam_m": 8, "draft_m": 3, "speed_kn": speed}
    data["run"] = {"seed": seed}
    scene = parse_scene(data)
    again = parse_scene(scene.model_dump(mode="json", exclude_none=True))
    assert again == scene


def test_bundled_scene_round_trips_through_toml_text():
    text = (ROOT / "scenes" / "paper_sim1_bistatic_64m.toml").read_text()
    scene = parse_scene(tomllib.loads(text))
    assert parse_scene(scene.model_dump(mode="json", exclude_none=True)) == scene
