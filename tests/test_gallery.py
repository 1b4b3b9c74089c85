"""The gallery of ``examples/`` cannot rot: every script runs in its ``--quick`` size.

The figure scripts of the paper's scattering and ocean figures (3, 4, 5) and the angle
sweep take seconds and run in every suite; those that simulate and focus a scene (6-9,
the hull echo, the bistatic SAR) take tens of seconds each on two cores and are marked
slow (``pytest -m slow``). Every script, slow or not, is checked for what the gallery
promises: a docstring naming its figures, ``main(argv)``, the public ``seaecho`` API only
(no ``seaecho.<stage>`` import but ``seaecho.warnings``), and a line in
examples/README.md with its image.

The paper: Arnold-Bos, A., Martin, A. and Khenchaf, A. (2006). A versatile bistatic &
polarimetric marine radar simulator. *Proc. 2006 IEEE Conference on Radar*,
doi:10.1109/RADAR.2006.1631862.
"""

from __future__ import annotations

import ast
import importlib
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
FAST = ["fig3_bistatic_sigma", "fig4_bistatic_map", "fig5_pm_spectra",
        "bistatic_angle_sweep"]
SLOW = ["fig6_simulation1", "fig7_simulation2", "fig8_simulation3", "fig9_simulation4",
        "hull_echo", "bistatic_sar_ship", "multistatic_ship", "scanning_ppi"]
#: The gallery's scripts, as examples/README.md lists them
GALLERY = FAST + SLOW
#: What a gallery script may import from seaecho besides the package itself
ALLOWED = {"seaecho", "seaecho.warnings"}


def _run(name: str, tmp_path: Path) -> list[Path]:
    sys.path.insert(0, str(EXAMPLES))
    try:
        module = importlib.import_module(name)
        return module.main(["--quick", "--out", str(tmp_path)])
    finally:
        sys.path.remove(str(EXAMPLES))


@pytest.mark.parametrize("name", GALLERY)
def test_script_uses_the_public_api_and_is_listed(name):
    path = EXAMPLES / f"{name}.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    doc = ast.get_docstring(tree) or ""
    assert "--quick" in doc and "--out" in doc, name
    assert any(isinstance(n, ast.FunctionDef) and n.name == "main" for n in tree.body)
    imported = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import)
                for a in n.names} | {n.module for n in ast.walk(tree)
                                     if isinstance(n, ast.ImportFrom) and n.module}
    inner = {m for m in imported if m.startswith("seaecho")} - ALLOWED
    assert not inner, f"{name} imports {sorted(inner)}: the gallery uses seaecho's API"
    readme = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    assert f"{name}.py" in readme, f"{name} is not in examples/README.md"


@pytest.mark.parametrize("name", FAST)
def test_fast_script_runs(name, tmp_path):
    paths = _run(name, tmp_path)
    assert paths and all(p.parent == tmp_path and p.stat().st_size > 10_000 for p in paths)


@pytest.mark.slow
@pytest.mark.parametrize("name", SLOW)
def test_simulating_script_runs(name, tmp_path):
    paths = _run(name, tmp_path)
    assert paths and all(p.parent == tmp_path and p.stat().st_size > 10_000 for p in paths)


def test_readme_images_are_the_scripts_outputs():
    # every image examples/README.md shows is one a listed script writes
    import re

    readme = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    shown = set(re.findall(r"\(\.\./docs/gallery/([\w.]+\.png)\)", readme))
    assert shown
    written = "".join((EXAMPLES / f"{n}.py").read_text(encoding="utf-8") for n in GALLERY)
    written += (EXAMPLES / "_gallery.py").read_text(encoding="utf-8")
    for png in shown:
        stem = png.removesuffix(".png")
        assert png in written or stem.rsplit("_", 1)[0] in written, png
