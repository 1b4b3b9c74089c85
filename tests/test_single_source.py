"""Each physics formula has one home, and the layers import each other in one direction.

The numpy reference path and the Dr.Jit kernels evaluate the same functions
(``seaecho.backend``); a formula written a second time (in a kernel module, say) would
let the two paths drift apart while parity tests on their shared inputs still pass. The
test reads the code (docstrings and comments left out) for constants and expressions
that only one formula uses, for the literals of the physical laws and constants (the
dispersion relation, viscosity, von Karman, friction-velocity laws, windows, the Kelvin
wavenumber), and checks the import graph:

- geometry never imports scattering, radar or tracing (frames are geometry);
- only ``seaecho.backend`` and the tracing stage import Dr.Jit (a formula reaching for
  ``drjit`` directly would bypass the namespace and exist for one path only);
- only the tracing stage imports Mitsuba / Sionna RT.
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "seaecho"


@functools.cache
def _modules() -> dict[str, ast.Module]:
    return {str(p.relative_to(SRC)): ast.parse(p.read_text()) for p in sorted(SRC.rglob("*.py"))}


@functools.cache
def _code(name: str) -> str:
    """The module's code without docstrings (ast.unparse drops comments).

    A tree of its own, parsed again from the file (the shared one of :func:`_modules` is
    left whole): the same code as unparsing that one, for one unparse less per module."""
    tree = ast.parse((SRC / name).read_text())
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (isinstance(body, list) and body and isinstance(body[0], ast.Expr)
                and isinstance(body[0].value, ast.Constant)
                and isinstance(body[0].value.value, str)):
            body[0] = ast.Pass()
    return ast.unparse(tree)


#: expression that identifies a formula -> the one module allowed to contain it
MARKERS = {
    # blend weights, eqs B3-B4: (beta / 6 pi)^8, (beta / 20 pi)^1.5
    r"\b6(\.0)?\s*\*\s*(np|math)\.pi\b": "scattering/blend.py",
    r"\b20(\.0)?\s*\*\s*(np|math)\.pi\b": "scattering/blend.py",
    # Gram-Charlier coefficients of Cox & Munk (eq K4) and the Gaussian's 2 pi (eq K3)
    r"\.c(21|03|40|22|04)\b": "scattering/slopes.py",
    r"log\(2(\.0)?\s*\*\s*(np|math)\.pi\)": "scattering/slopes.py",
    # eq K1: log(pi |q|^4 / q_N^4)
    r"log\((np|math)\.pi\)\s*-\s*4": "scattering/kirchhoff.py",
    # eq S7 prefactor 4 sqrt(pi) k^2
    r"4(\.0)?\s*\*\s*(np|math)\.sqrt\((np|math)\.pi\)": "scattering/spm.py",
    # eq R1: (4 pi)^1.5 (radar equation, amplitude form)
    r"\(4(\.0)?\s*\*\s*(np|math)\.pi\)\s*\*\*\s*1\.5": "radar/equation.py",
}


@pytest.mark.parametrize("pattern,home", list(MARKERS.items()))
def test_formula_constants_live_in_one_module(pattern, home):
    found = sorted(name for name in _modules() if re.search(pattern, _code(name)))
    assert found == [home], f"{pattern!r} found in {found}, expected only in {home}"


#: laws and physical constants: expression -> the modules allowed to contain it (an empty
#: set: nowhere, the law is reached through its function). The code is read as
#: ``ast.unparse`` writes it (``1.05e-6`` reads ``1.05e-06``).
LAWS = {
    # the dispersion relation (eq 15' of ocean/dispersion.py): written once, in ocean/dispersion.py
    r"\bSURFACE_TENSION_OVER_DENSITY\b": {"constants.py", "ocean/dispersion.py",
                                           "ocean/surface.py"},  # (a default argument)
    r"\btanh\(\s*\w+\s*\*\s*(depth|d|h)\b": {"ocean/dispersion.py"},
    r"sqrt\(\s*(G|g)\s*[*/]\s*\w*k": set(),
    r"\(\s*(G|g)\s*\+\s*\w+\s*\*\s*\w+\s*\*\s*\w+\s*\)": {"ocean/dispersion.py"},
    r"\b370(\.0)?\b": set(),  # k_m: CAPILLARY_WAVENUMBER, from the relation
    # the kinematic viscosity of sea water, the vacuum permittivity, the von Karman
    # constant, air's density and viscosity: seaecho/constants.py
    r"\b1\.05e-0?6\b": {"constants.py"},
    r"8\.854|1\.2566370": {"constants.py"},
    r"(?m)^\w*(KARMAN|KAPPA)\w*\s*=\s*[0-9]": {"constants.py"},
    r"\b1\.225\b|\b1\.47e-0?5\b": {"constants.py"},
    # friction-velocity and roughness laws (Stewart, Wu 1982, Donelan 1993, Charnock):
    # ocean/wind.py, picked by name by their users
    r"\b0\.065\s*\*": {"ocean/wind.py"},
    r"\b3\.7e-0?5\b": {"ocean/wind.py"},
    r"\b0\.018\b": {"ocean/wind.py"},
    # weighting windows: processing/windows.py (no numpy or scipy window elsewhere)
    r"np\.(hamming|hanning|bartlett|blackman|kaiser)\(|windows\.(taylor|hamming|hann)\b":
        set(),
    r"\b0\.54\b": {"processing/windows.py"},
    # the Kelvin wavenumber g / V^2 (and 2 pi V^2 / g): wake/michell.py
    # (Kriebel & Seelig's height scale V^2 / g in wake/empirical.py is not a wavelength)
    r"\b(g|G)\s*/\s*[\w.]*speed\s*\*\*\s*2|pi\s*\*\s*\w*\s*\*?\s*speed\s*\*\*\s*2":
        {"wake/michell.py"},
}


@pytest.mark.parametrize("pattern,homes", list(LAWS.items()))
def test_each_law_and_constant_is_written_once(pattern, homes):
    found = {name for name in _modules() if re.search(pattern, _code(name))}
    assert found <= homes, (f"{pattern!r} found in {sorted(found - homes)}: import it from "
                            f"{sorted(homes) or 'its function'} instead")


def test_resources_imports_the_sizes_it_models():
    """checks/resources.py takes the block, cache and batch sizes from their modules, not copies."""
    code = _code("checks/resources.py")
    copies = re.findall(r"(?m)^(CHUNK|SBR_BATCH|SIGNATURE_CACHE|IMAGE_BLOCK)\s*=", code)
    assert not copies, f"checks/resources.py redefines {copies}"
    import inspect

    import seaecho.checks.resources as res
    from seaecho.imaging.focus import focus
    from seaecho.io.run import DEFAULT_BLOCK_PULSES
    from seaecho.tracing.hull_echo import SIGNATURE_CACHE
    from seaecho.tracing.sbr import SBROptions
    assert res.CHUNK == 2 * DEFAULT_BLOCK_PULSES
    assert res.SIGNATURE_CACHE == SIGNATURE_CACHE
    assert res.SBR_BATCH == SBROptions().batch
    assert res.IMAGE_BLOCK == inspect.signature(focus).parameters["block_pulses"].default


def _imports(tree: ast.Module, name: str) -> set[str]:
    """Absolute names of the modules ``name`` (a path under seaecho/) imports."""
    package = ["seaecho", *Path(name).with_suffix("").parts][:-1]  # its package
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            out.add(mod)
            out.update(f"{mod}.{a.name}" for a in node.names)
    return out


def test_geometry_never_imports_the_later_stages():
    for name, tree in _modules().items():
        if name.startswith("geometry/"):
            bad = {m for m in _imports(tree, name)
                   if m.startswith(("seaecho.scattering", "seaecho.radar", "seaecho.tracing"))}
            assert not bad, f"{name} imports {sorted(bad)}"


def test_scattering_does_not_reach_into_geometry_buffers_or_later_stages():
    for name, tree in _modules().items():
        if name.startswith("scattering/"):
            bad = {m for m in _imports(tree, name)
                   if m.startswith(("seaecho.geometry.buffers", "seaecho.radar",
                                    "seaecho.tracing"))}
            assert not bad, f"{name} imports {sorted(bad)}"


def test_only_the_backend_and_tracing_import_drjit_mitsuba_sionna():
    for name, tree in _modules().items():
        mods = _imports(tree, name)
        if any(m == "drjit" or m.startswith("drjit.") for m in mods):
            assert name == "backend.py" or name.startswith("tracing/"), name
        if any(m.split(".")[0] in ("mitsuba", "sionna") for m in mods):
            assert name.startswith("tracing/"), name
