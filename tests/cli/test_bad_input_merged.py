"""Bad input through what the run grew: distributed runs and sweeps, hull echoes
(``[[objects]] scatterer = true``) and ``[image]``. Same rules as ``test_bad_input``: exit
2, one message naming the field, no traceback, no file left; a sweep case that `seaecho
run` would refuse is reported as failed and not run."""

from __future__ import annotations

import csv
import shutil
from pathlib import Path

import numpy as np
import pytest

from seaecho.cli import main

ROOT = Path(__file__).resolve().parents[2]
CAL = (ROOT / "scenes" / "calibration_point_target.toml").read_text()
TRIHEDRAL = ROOT / "scenes" / "calibration_trihedral.toml"
#: The calibration scene's transmitter, 300 m up; moved under the sea below.
HIGH = "position_m = [-500.0, 0.0, 300.0]"
UNDER = "position_m = [-500.0, 0.0, -5.0]"


def _scene(tmp_path: Path, text: str, name: str = "s.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def _cli(capsys, *args) -> tuple[int, str, str]:
    rc = main(list(args))
    cap = capsys.readouterr()
    assert "Traceback" not in cap.err
    return rc, cap.out, cap.err


def test_run_with_workers_gets_the_same_refusal_before_any_cluster(tmp_path, capsys):
    # The preflight runs before the Dask cluster starts: same message, exit 2, no file
    scene = _scene(tmp_path, CAL.replace(HIGH, UNDER, 1))
    msgs = []
    for extra in ([], ["--workers", "2"], ["--workers", "2", "--block-pulses", "2"]):
        out = tmp_path / ("x.zarr" if extra else "x.nc")
        rc, _, err = _cli(capsys, "run", str(scene), "-o", str(out), "-q", *extra)
        assert rc == 2 and "[transmitter].position_m" in err and "z = -5" in err
        msgs.append(err.replace(str(out), "OUT"))
    assert msgs[0] == msgs[1] == msgs[2]
    assert sorted(tmp_path.iterdir()) == [scene]


def test_workers_multiply_the_memory_estimate(tmp_path):
    import tomllib

    from seaecho.checks.resources import estimate
    from seaecho.config import parse_scene
    from seaecho.config.toml_writer import dumps  # noqa: F401 - the writer round-trips

    scene = parse_scene(tomllib.loads(CAL))
    one, four = estimate(scene, figures=False), estimate(scene, figures=False, workers=4)
    worker = sum(v for k, v in one.terms.items() if k not in ("figures", "antenna pattern"))
    assert four.terms["workers"] == pytest.approx(4 * worker)
    assert four.peak_bytes > 4 * one.peak_bytes


def test_sweep_override_out_of_range_is_the_file_message(tmp_path, capsys):
    # A --set value is validated like a scene file: same message, exit 2, no output folder
    scene = _scene(tmp_path, CAL)
    rc, _, err = _cli(capsys, "sweep", str(scene), "--set", "radar.n_pulses=0,2",
                      "-o", str(tmp_path / "out"), "-q")
    assert rc == 2 and "[radar].n_pulses = 0" in err
    bad = _scene(tmp_path, CAL.replace("n_pulses = ", "n_pulses = 0 #", 1), "bad.toml")
    rc2, _, err2 = _cli(capsys, "check", str(bad))
    assert rc2 == 2 and err2.split("\n")[1] == err.split("\n")[1]
    assert not (tmp_path / "out").exists()


def test_sweep_case_the_run_would_refuse_is_failed_not_run(tmp_path, capsys):
    # transmitter.position_m = [-500, 0, -5] passes the schema; `seaecho run` refuses it
    # (antenna under the sea): that case is a failed row with the run's message, the
    # other case runs
    scene = _scene(tmp_path, CAL)
    out = tmp_path / "out"
    rc, _, err = _cli(capsys, "sweep", str(scene), "--set",
                      "transmitter.position_m=[-500.0, 0.0, 300.0],[-500.0, 0.0, -5.0]",
                      "--pulses", "2", "-o", str(out), "-q")
    assert rc == 1 and "case 1 failed" in err and "[transmitter].position_m" in err
    with (out / "summary.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert [r["status"] for r in rows] == ["ok", "failed"]
    assert sorted(p.name for p in out.glob("case_*.nc")) == ["case_00000.nc"]


def test_missing_hull_mesh_is_refused_by_check_in_any_facet_mode(tmp_path, capsys):
    # An [[objects]] scatterer is loaded by the run whatever the facet mode (its echo):
    # `check` used to look for object files only with a ray-traced sea
    scene = _scene(tmp_path, TRIHEDRAL.read_text())  # no meshes/ beside it
    rc, _, err = _cli(capsys, "check", str(scene))
    assert rc == 2 and "[[objects]] #0 (trihedral)" in err and "no such file" in err


def test_hull_traces_enter_the_estimate(tmp_path):
    from seaecho.checks.resources import estimate, hull_sizes
    from seaecho.config import load_scene

    scene = load_scene(TRIHEDRAL)
    (h,) = hull_sizes(scene, TRIHEDRAL.parent)
    # 0.5 m trihedral (three right triangles of legs 0.5 m): its vertices are 0.5 m from
    # its corner, the origin; 4 rays per wavelength at 10 GHz: delta = 7.49 mm,
    # (2 r / delta)^2 = 1.78e4 launch cells
    assert h.radius == pytest.approx(0.5, rel=1e-6)
    assert h.grid == pytest.approx((2 * 0.5 / (0.0299792458 / 4)) ** 2, rel=1e-6)
    assert h.launches == 1 and h.traces >= 1
    est = estimate(scene, base_dir=TRIHEDRAL.parent)
    # a batch of min(2^18, grid) rays at 1200 bytes and 24 bytes per launch cell, plus
    # the cached centres
    assert est.terms["hull traces"] >= 1224 * h.grid
    assert est.hull_rays == h.grid * h.traces


def test_non_finite_hull_echo_is_named(tmp_path, monkeypatch):
    from seaecho.checks.guards import NonFiniteEchoError
    from seaecho.config import load_scene
    from seaecho.simulation import Simulation
    from seaecho.tracing.hull_echo import HullEchoes

    real = HullEchoes.echoes

    def echoes(self, geometry, pulse, seen=None):
        out = real(self, geometry, pulse, seen)
        out[0].amplitudes[:, :3] = np.nan
        return out

    monkeypatch.setattr(HullEchoes, "echoes", echoes)
    sim = Simulation(load_scene(TRIHEDRAL), base_dir=TRIHEDRAL.parent)
    with pytest.raises(NonFiniteEchoError, match=r"pulse 0 .*3 scattering centres of hull "
                       r"'trihedral'"):
        sim.pulse(0)


@pytest.mark.parametrize(("image", "named"), [
    # found by the fuzzing suite: the run wrote the raw file, then focusing failed (exit 2
    # with the raw file left)
    ("looks = [1, 1000]", "[image].looks"),
    ("pixel_m = 0.001", "[image].pixel_m = 0.001"),
])
def test_image_the_run_cannot_focus_is_refused_before_the_raw(tmp_path, capsys, image,
                                                              named):
    scene = _scene(tmp_path, CAL + f"\n[image]\n{image}\n")
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "x.nc"), "-q"] if command == "run" else []
        rc, _, err = _cli(capsys, command, str(scene), *extra)
        assert rc == 2 and named in err, err
    assert sorted(tmp_path.iterdir()) == [scene]


def test_image_pixels_enter_the_estimate(tmp_path):
    import tomllib

    from seaecho.checks.resources import estimate, image_shape
    from seaecho.config import parse_scene

    d = tomllib.loads(CAL)
    d["image"] = {"pixel_m": 0.5, "extent_m": [-20.0, 20.0, -10.0, 10.0]}
    scene = parse_scene(d)
    assert image_shape(scene) == (40, 80)
    est = estimate(scene)
    assert est.pixels == 3200 and est.terms["image"] > 3200 * 4 * 160


def test_trihedral_scene_copies_still_check(tmp_path, capsys):
    shutil.copytree(TRIHEDRAL.parent / "meshes", tmp_path / "meshes")
    scene = _scene(tmp_path, TRIHEDRAL.read_text())
    rc, out, _ = _cli(capsys, "check", str(scene))
    assert rc == 0 and "hull rays" in out


def test_scene_json_of_a_run_with_an_occluder_reads_back():
    # Found by the fuzzing suite: a run's scene_json holds every field with its default;
    # an occluding object's SBR defaults (max_bounces = 3...) read back as "set", so
    # `seaecho image` and [image] after a run refused the run's own scene
    import json
    import tomllib

    from seaecho.config import parse_scene
    from seaecho.io.dataset import scene_attrs

    d = tomllib.loads(CAL)
    d["objects"] = [{"name": "boat", "file": "meshes/motor_boat_10m.ply"}]  # occluder
    scene = parse_scene(d)
    data = json.loads(scene_attrs(scene)["scene_json"])
    assert data["objects"][0]["max_bounces"] == 3  # the default, written out
    assert parse_scene(data) == scene
    data["objects"][0]["max_bounces"] = 2
    with pytest.raises(Exception, match="max_bounces: only with scatterer = true"):
        parse_scene(data)


@pytest.mark.filterwarnings("ignore::seaecho.warnings.ValidityWarning")
def test_calm_sea_without_subfacet_slopes_is_refused_by_check_as_by_run(tmp_path, capsys):
    # Found by the fuzzing suite: U19.5 = 0.3 m/s over a 5.7 m fetch has no slope between
    # the 1 m grid's 2 m waves and the 1 GHz split (0.9 m): the builder refused the run
    # ("resolves every wave", which it does not) after `check` had accepted it
    import tomllib

    from seaecho.config.toml_writer import dumps

    d = tomllib.loads(CAL)
    d["sea"] = {"wind_speed_m_s": 0.3, "fetch_m": 5.723, "size_x_m": 4.0, "nx": 4}
    d["radar"].update(carrier_frequency_hz=1.0e9, sea_clutter=True)
    scene = _scene(tmp_path, dumps(d))
    errs = []
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "x.nc"), "-q"] if command == "run" else []
        rc, _, err = _cli(capsys, command, str(scene), *extra)
        assert rc == 2 and "carry no slope" in err and "U19.5 = 0.3 m/s" in err, err
        errs.append(err.split("\n", 1)[1])
    assert errs[0] == errs[1]
    assert sorted(tmp_path.iterdir()) == [scene]


def test_itu_material_undefined_at_the_carrier_is_refused_by_check(tmp_path, capsys):
    # Found by the fuzzing suite: ITU-R P.2040 defines 'floorboard' from 50 to 100 GHz;
    # at 16.9 GHz `check` accepted it and `run` died with a traceback from Sionna's table
    # when the ray-traced sea loaded the object
    shutil.copytree(TRIHEDRAL.parent / "meshes", tmp_path / "meshes")
    text = TRIHEDRAL.read_text().replace('material = "metal"', 'material = "floorboard"')
    scene = _scene(tmp_path, text)
    for command in ("check", "run"):
        extra = ["-o", str(tmp_path / "x.nc"), "-q"] if command == "run" else []
        rc, _, err = _cli(capsys, command, str(scene), *extra)
        assert rc == 2 and "material = \"floorboard\"" in err and "P.2040" in err, err
    assert not (tmp_path / "x.nc").exists()


def test_fetch_of_the_elfouhaily_spreading_is_checked_with_any_spectrum(tmp_path, capsys):
    # Found by the fuzzing suite (a RuntimeWarning, log of a negative friction velocity):
    # with spectrum = "pierson-moskowitz" the fetch went unchecked, but the Elfouhaily
    # spreading function reads it through Elfouhaily's fetch law
    text = (CAL.replace("nx = 64", 'nx = 64\nspectrum = "pierson-moskowitz"\n'
                        'spreading = "elfouhaily"\nfetch_m = 1e-3', 1))
    rc, _, err = _cli(capsys, "check", str(_scene(tmp_path, text)))
    assert rc == 2 and "[sea].fetch_m = 0.001" in err and "elfouhaily spreading's" in err


def test_image_pixel_of_5e_324_m_is_a_message(tmp_path, capsys):
    # Found by the fuzzing suite: extent / pixel_m overflowed to infinity and `check`
    # died in OverflowError counting the pixels
    scene = _scene(tmp_path, CAL + "\n[image]\npixel_m = 5e-324\n")
    rc, _, err = _cli(capsys, "check", str(scene))
    assert rc == 2 and "[image].pixel_m = 5e-324" in err and "more than" in err
