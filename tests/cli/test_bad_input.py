"""Bad scene files through `seaecho check` and `seaecho run`: exit 2, one message naming
the field, no traceback, no file left. Each case is a defect found by trying broken
scenes (the fuzzing suite in ``tests/fuzz`` generates many more)."""

from __future__ import annotations

from pathlib import Path

import pytest

from seaecho.cli import main

ROOT = Path(__file__).resolve().parents[2]
CAL = (ROOT / "scenes" / "calibration_point_target.toml").read_text()


def _scene(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return path


def _replace(old: str, new: str, text: str = CAL) -> str:
    assert old in text
    return text.replace(old, new, 1)


def _cli(capsys, *args) -> tuple[int, str]:
    rc = main(list(args))
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return rc, err


@pytest.mark.parametrize("command", ["check", "run"])
def test_deeply_nested_toml_value_is_a_message(tmp_path, capsys, command):
    # x = [[[[...]]]] 3000 levels deep: Python's TOML parser recurses past its limit
    text = "x = " + "[" * 3000 + "]" * 3000 + "\n" + CAL
    scene = _scene(tmp_path, text)
    out = tmp_path / "x.nc"
    extra = ["-o", str(out), "-q"] if command == "run" else []
    rc, err = _cli(capsys, command, str(scene), *extra)
    assert rc == 2 and "nested too deeply" in err
    assert sorted(tmp_path.iterdir()) == [scene]
