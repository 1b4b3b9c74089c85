"""README.md's two set-up commands and .ci/run must agree (the project card's contract)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _readme_commands() -> list[str]:
    text = (ROOT / "README.md").read_text()
    return re.findall(r"```bash\n(.*?)\n```", text, flags=re.S)[:2]


def test_readme_starts_with_two_setup_commands():
    run_cmd, test_cmd = _readme_commands()
    assert run_cmd.startswith("./setup.sh && ")
    assert test_cmd.startswith("./setup.sh test && ")
    scene = re.search(r"(scenes/\S+\.toml)", run_cmd).group(1)
    assert (ROOT / scene).is_file()


def test_ci_runs_readme_test_command():
    _, test_cmd = _readme_commands()
    ci = (ROOT / ".ci" / "run").read_text().splitlines()
    assert test_cmd in ci
