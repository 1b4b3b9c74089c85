"""Scenes from Python: lazy top-level API, loading, parsing, overrides, the summary.

The summary's numbers are checked against closed forms: the Pierson-Moskowitz significant
wave height H_s = 0.2092 U19.5^2 / g (Pierson & Moskowitz 1964, in the form the scene
files quote), the bistatic ground-range resolution c / (B (sin theta_i + sin theta_s))
of an in-plane geometry and its monostatic limit c / (2 B sin theta_i) (Willis,
*Bistatic Radar*, 2005, ch. 8), and the stripmap azimuth resolution D / 2 of an aperture
of length D (Cumming & Wong, *Digital Processing of SAR Data*, 2005, ch. 4).

"The paper": Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import seaecho
from seaecho.config import SceneError
from seaecho.config import load_scene as config_load_scene

ROOT = Path(__file__).resolve().parents[2]
SIM1 = ROOT / "scenes" / "paper_sim1_bistatic_64m.toml"
SIM2 = ROOT / "scenes" / "paper_sim2_sar_128m_wind55.toml"
C0 = 299_792_458.0  # [m/s], exact (SI 2019)
G = 9.80665  # [m/s^2], standard gravity


def test_import_seaecho_loads_nothing_heavy():
    code = ("import sys, seaecho; heavy = [m for m in ('numpy', 'xarray', 'pydantic', "
            "'seaecho.api', 'seaecho.config') if m in sys.modules]; print(heavy); "
            "seaecho.load_scene; print('seaecho.api' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=120).stdout.split("\n")
    assert out[0] == "[]" and out[1] == "True"


def test_top_level_names():
    for name in seaecho.__all__:
        assert name in dir(seaecho) and getattr(seaecho, name) is not None
    assert seaecho.simulate is seaecho.api.simulate
    with pytest.raises(AttributeError, match="no attribute 'simulated'"):
        seaecho.simulated  # noqa: B018


def test_load_parse_and_overrides_keep_the_scene_and_its_folder():
    scene = seaecho.load_scene(SIM1)
    assert isinstance(scene, seaecho.Scene) and scene.base_dir == SIM1.parent
    # the same fields as the schema's loader gives
    assert scene.model_dump() == config_load_scene(SIM1).model_dump()
    text = seaecho.parse_scene(SIM1.read_text(), base_dir=SIM1.parent)
    assert text.model_dump() == scene.model_dump() and text.base_dir == SIM1.parent
    assert seaecho.parse_scene(scene.model_dump(mode="json")).model_dump() == scene.model_dump()
    windy = seaecho.with_overrides(scene, {"sea.wind_speed_m_s": 8.0, "radar.n_pulses": 16})
    assert (windy.sea.wind_speed_m_s, windy.radar.n_pulses) == (8.0, 16)
    assert windy.base_dir == SIM1.parent
    assert scene.sea.wind_speed_m_s == 4.53  # the input is not changed


def test_overrides_keep_every_scene_file_as_it_is():
    # An override round-trips the scene through all its fields, defaults included (as a
    # run's scene_json, which seaecho image reads back): a validator must not refuse a
    # default written out (the bistatic SAR scene's boat is no scatterer, and the ray
    # density of scatterers is only refused when given another value).
    for path in sorted((ROOT / "scenes").glob("*.toml")):
        scene = seaecho.load_scene(path)
        assert seaecho.with_overrides(scene, {}).model_dump() == scene.model_dump(), path
    bistatic = seaecho.load_scene(ROOT / "scenes" / "bistatic_sar_128m_wind55.toml")
    small = seaecho.with_overrides(bistatic, {"sea.size_x_m": 64.0, "sea.nx": 256})
    assert small.sea.shape == (256, 256) and not small.objects[0].scatterer


@pytest.mark.parametrize(("overrides", "fragments"), [
    ({"sea.wind_speedd_m_s": 8.0}, ["[sea].wind_speedd_m_s", "unknown key",
                                    "wind_speed_m_s"]),
    ({"sea.wind_speed_m_s": -3.0}, ["[sea].wind_speed_m_s = -3.0", "greater than or equal to"]),
    ({"radar.n_pulses": 0}, ["[radar].n_pulses = 0"]),
    ({"sea.nx": 63}, ["nx = 63", "must be even"]),
    ({"radar.waveform.bandwidth_hz": "wide"}, ["[radar].waveform.bandwidth_hz", "wide"]),
    ({"targets.3.rcs_m2": 1.0}, ["targets", "index 3"]),
    ({"sea..nx": 64}, ["override name 'sea..nx'"]),
])
def test_overrides_name_the_field_and_what_is_allowed(overrides, fragments):
    with pytest.raises(SceneError) as err:
        seaecho.with_overrides(seaecho.load_scene(SIM1), overrides)
    for fragment in fragments:
        assert fragment in str(err.value)


def test_parse_errors():
    with pytest.raises(SceneError, match="not valid TOML.*seaecho.load_scene"):
        seaecho.parse_scene("scenes/paper_sim1_bistatic_64m.toml")
    with pytest.raises(SceneError, match="sea: missing required field"):
        seaecho.parse_scene({"name": "no sea"})
    with pytest.raises(SceneError, match="not found"):
        seaecho.load_scene(ROOT / "scenes" / "none.toml")


def _rows(scene) -> dict[str, str]:
    return {k: v for _, rows in seaecho.api.scene_summary(scene).sections for k, v in rows}


def _number(text: str, before: str) -> float:
    """The number just before ``before`` in ``text``."""
    head = text.split(before)[0].split()
    return float(head[-1])


def test_summary_of_simulation_1_bistatic():
    scene = seaecho.load_scene(SIM1)
    rows = _rows(scene)
    # The paper states theta_i = 20 deg, theta_s = 30 deg at the tile centre
    assert "incidence 20 deg" in rows["transmitter"]
    assert "incidence 30 deg" in rows["receiver"]
    assert rows["bistatic angle"] == "10 deg"  # both in the x-z plane, same side
    # In-plane bistatic ground resolution c / (B (sin 20 + sin 30)), B = 150 MHz
    import math
    expected = C0 / (150e6 * (math.sin(math.radians(20)) + math.sin(math.radians(30))))
    assert _number(rows["range"], "m on the ground") == pytest.approx(expected, rel=2e-3)
    assert "8 pulses x 4 channels" in rows["arrays"]
    text = scene.summary()
    assert text.startswith("seaecho scene 'paper-sim1-bistatic-64m'")
    assert repr(scene) == text == str(scene)
    html = scene._repr_html_()
    assert html.startswith('<div class="seaecho-scene"><table') and "bistatic angle" in html


def test_summary_of_simulation_2_stripmap_sar():
    rows = _rows(seaecho.load_scene(SIM2))
    # Pierson-Moskowitz: H_s = 0.2092 U19.5^2 / g = 0.50 m for U19.5 = 4.84 m/s
    assert _number(rows["expected Hs"], "m (whole") == pytest.approx(
        0.2092 * 4.84**2 / G, rel=0.01)
    import math
    # monostatic at 45 deg: c / (2 B sin 45), B = 75 MHz
    assert _number(rows["range"], "m on the ground") == pytest.approx(
        C0 / (2 * 75e6 * math.sin(math.radians(45))), rel=2e-3)
    # stripmap with a 4 m aperture: D / 2 = 2 m (the flight, 160 m, is longer than the
    # 32 m footprint)
    assert _number(rows["azimuth"], "m (synthetic") == pytest.approx(2.0, rel=2e-3)
    assert "image" in rows


def test_summary_without_radar_and_repr_never_raises():
    scene = seaecho.parse_scene("[sea]\nwind_speed_m_s = 5.0\nsize_x_m = 64.0\nnx = 64\n")
    text = scene.summary()
    assert "Sea" in text and "Radar" not in text
    # a scene that cannot be summarised still prints its fields
    broken = seaecho.with_overrides(seaecho.load_scene(SIM1), {"radar.n_pulses": 2})
    object.__setattr__(broken, "sea", None)
    assert "no summary" in repr(broken)


def test_summary_hs_of_the_tiles_band_is_the_pierson_moskowitz_integral():
    # the Pierson-Moskowitz wavenumber spectrum S(K) = a0 / 2 K^-3 exp(-B / K^2), B = b0
    # g^2 / U19.5^4, a0 = 8.1e-3, b0 = 0.74 (Pierson & Moskowitz 1964, in the form the
    # scene files quote) integrates in closed form over a band K1 < K < K2 to
    # a0 / (4 B) [exp(-B / K2^2) - exp(-B / K1^2)]; the tile resolves 2 pi / L < K < pi / dx.
    # A 32 m tile at U19.5 = 10 m/s holds about half of the sea's height variance.
    import math

    u, size, n = 10.0, 32.0, 64
    scene = seaecho.parse_scene(f'[sea]\nspectrum = "pierson-moskowitz"\nwind_speed_m_s = {u}'
                                f'\nsize_x_m = {size}\nnx = {n}\n')
    text = _rows(scene)["expected Hs"]
    b = 0.74 * G**2 / u**4
    k1, k2 = 2 * math.pi / size, math.pi / (size / n)
    var = 8.1e-3 / (4 * b) * (math.exp(-b / k2**2) - math.exp(-b / k1**2))
    assert _number(text, "m in the tile") == pytest.approx(4 * math.sqrt(var), rel=5e-3)
    assert _number(text, "m (whole") == pytest.approx(0.2092 * u**2 / G, rel=5e-3)
    assert 4 * math.sqrt(var) < 0.8 * 0.2092 * u**2 / G  # the band matters here
