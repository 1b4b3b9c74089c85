"""Zarr runs: an interrupted run continued with resume gives the uninterrupted bytes; a
store of another run, or a corrupt one, is refused."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import zarr
from dask_helpers import tiny_scene

from seaecho.cli import main
from seaecho.io.run import open_run
from seaecho.io.zarr_run import StoreError, part_path
from seaecho.simulation import Simulation

ROOT = Path(__file__).resolve().parents[2]
CAL = ROOT / "scenes" / "calibration_point_target.toml"


def _files(store: Path) -> dict[str, bytes]:
    return {str(p.relative_to(store)): p.read_bytes() for p in sorted(store.rglob("*"))
            if p.is_file()}


def _interrupted(sc, out: Path, at: int, block: int = 2) -> list[int]:
    """Run ``sc`` into ``out`` and interrupt it when pulse ``at`` starts."""
    sim = Simulation(sc)
    orig, seen = sim.pulse, []

    def pulse(p):
        if p == at:
            raise KeyboardInterrupt
        seen.append(p)
        return orig(p)

    sim.pulse = pulse
    with pytest.raises(KeyboardInterrupt):
        sim.run(out, progress=False, chunk=block)
    return seen


def test_resumed_run_has_the_uninterrupted_bytes(tmp_path):
    sc = tiny_scene(n_pulses=8)
    full = Simulation(sc).run(tmp_path / "full.zarr", progress=False, chunk=2)
    out = tmp_path / "cut.zarr"
    _interrupted(sc, out, at=5)
    # never mistaken for a finished store: only the .part folder exists
    assert not out.exists() and part_path(out).is_dir()
    # the block after the interruption was written but its record lost (a crash
    # between the chunk and its record): it is computed again
    (part_path(out) / "blocks" / "000000001.json").unlink()
    with pytest.raises(StoreError, match="interrupted run"):  # not silently restarted
        Simulation(sc).run(out, progress=False, chunk=2)
    sim = Simulation(sc)
    orig, computed = sim.pulse, []
    sim.pulse = lambda p: computed.append(p) or orig(p)
    sim.run(out, progress=False, resume=True)
    assert computed == [2, 3, 4, 5, 6, 7]  # blocks 1, 2, 3; block 0 was kept
    assert not part_path(out).exists()
    assert _files(out) == _files(full)  # every chunk and metadata file, byte for byte
    with open_run(out) as ds:
        np.testing.assert_array_equal(ds["raw"].values[6], Simulation(sc).pulse(6))
    # resuming a finished store of the same run does nothing
    Simulation(sc).run(out, progress=False, resume=True)
    assert _files(out) == _files(full)


@pytest.mark.parametrize(("change", "message"), [
    ({"seed": 2}, "seed 1, this run has seed 2"),
    ({"wind": 4.0}, r"another scene \(fields sea.wind_speed_m_s differ\)"),
])
def test_store_of_another_run_is_refused(tmp_path, change, message):
    out = tmp_path / "a.zarr"
    _interrupted(tiny_scene(n_pulses=6), out, at=3)
    with pytest.raises(StoreError, match=message):
        Simulation(tiny_scene(n_pulses=6, **change)).run(out, progress=False, resume=True)
    assert part_path(out).is_dir()  # left for the user to decide


def test_other_version_or_corrupt_store_is_refused(tmp_path):
    sc = tiny_scene(n_pulses=6)
    out = tmp_path / "a.zarr"
    _interrupted(sc, out, at=5)
    part = part_path(out)
    manifest = json.loads((part / "run.json").read_text())
    (part / "run.json").write_text(json.dumps(dict(manifest, seaecho_version="0.0.1")))
    with pytest.raises(StoreError, match="written by seaecho 0.0.1"):
        Simulation(sc).run(out, progress=False, resume=True)
    (part / "run.json").write_text(json.dumps(manifest))
    raw = zarr.open_array(part / "data.zarr" / "raw", mode="r+")
    raw[2, 0, 0] = raw[2, 0, 0] * 2  # block 1 (pulses 2, 3) no longer matches its record
    with pytest.raises(StoreError, match="block 1 .pulses 2 to 3. does not match"):
        Simulation(sc).run(out, progress=False, resume=True)
    (part / "run.json").write_text("{not json")
    with pytest.raises(StoreError, match="not a readable seaecho run"):
        Simulation(sc).run(out, progress=False, resume=True)


def test_cli_interrupt_resume_and_refusal(tmp_path, capsys, monkeypatch):
    out = tmp_path / "cal.zarr"
    args = ["run", str(CAL), "-o", str(out), "--pulses", "6", "--no-figures", "-q",
            "--block-pulses", "2"]
    orig = Simulation.pulse

    def pulse(self, p):
        if p == 3:
            raise KeyboardInterrupt
        return orig(self, p)

    monkeypatch.setattr(Simulation, "pulse", pulse)
    assert main(args) == 130
    assert "continue with --resume" in capsys.readouterr().err
    monkeypatch.setattr(Simulation, "pulse", orig)
    assert main(args) == 2  # an interrupted run is there: not overwritten silently
    assert "--resume" in capsys.readouterr().err
    other = [a if a != "6" else "5" for a in args]
    assert main([*other, "--resume"]) == 2
    err = capsys.readouterr().err
    assert "another scene (fields radar.n_pulses differ)" in err and "Traceback" not in err
    assert main([*args, "--resume"]) == 0
    full = tmp_path / "full.zarr"
    assert main([a if a != str(out) else str(full) for a in args]) == 0
    assert _files(out) == _files(full)
