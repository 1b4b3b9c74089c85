"""The package import graph follows the pipeline's layer order (docs/design.md).

Every ``import`` of a seaecho module, at module level or inside a function, is read from
the source with :mod:`ast`; a module may import its own package and the packages of
earlier layers, never a later one. The stages never import the scene-file schema
(``config``): only the builder, the orchestrator and the command line read scenes. And
only ``tracing`` imports mitsuba or sionna.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "seaecho"

#: Layers, earliest first: a package (or top-level module) imports itself and earlier
#: layers only. ``geometry`` (frames and polarisation bases, facets) comes before
#: ``scattering``, whose per-facet formulas use those frames.
LAYERS = [
    {"seaecho", "constants", "conventions", "rng", "warnings", "_llvm", "backend"},
    {"config"},
    {"ocean"},
    {"wake"},
    {"sea"},
    {"geometry"},
    {"scattering"},
    {"targets"},
    {"tracing"},
    {"radar"},
    {"processing"},
    {"detection"},
    {"io"},
    {"imaging"},
    {"plotting"},
    {"build"},
    {"checks", "summary"},
    {"simulation", "coverage", "multistatic"},
    {"distributed"},
    {"api"},
    {"cli"},
    {"__main__"},
]
#: Stages: they take stage models, never the scene (``config``).
STAGES = {"ocean", "wake", "sea", "scattering", "geometry", "targets", "tracing", "radar",
          "processing", "detection", "io"}
RANK = {name: i for i, layer in enumerate(LAYERS) for name in layer}
#: The only imports that reach up the layers, each deferred (inside a function) and for
#: display or convenience, never for the pipeline: the top-level package re-exports the
#: Python API lazily (PEP 562 ``__getattr__``), so that ``import seaecho`` loads nothing
#: heavy (tests/api/test_api_scene.py checks it); a ``Scene`` prints its summary
#: (``repr``, a notebook's display), which ``seaecho.summary`` computes with the builder.
LAZY_REEXPORTS = {("seaecho", "seaecho.api"), ("seaecho.config.scene", "seaecho.summary")}


def _package(module: str) -> str:
    """'seaecho.radar.system' -> 'radar'; 'seaecho' -> 'seaecho'."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else parts[0]


@functools.cache
def _imports() -> tuple[tuple[str, str, int], ...]:
    """(importing module, imported seaecho module, line) for every seaecho import (read
    once per session: every test of this file uses it)."""
    out = []
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC.parent).with_suffix("")
        parts = list(rel.parts)
        is_pkg = parts[-1] == "__init__"
        if is_pkg:
            parts = parts[:-1]
        module = ".".join(parts)
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = parts if is_pkg else parts[:-1]
                    base = base[: len(base) - (node.level - 1)]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if not target.startswith("seaecho"):
                    continue
                if node.module is None or target == "seaecho":  # from . import x
                    out += [(module, f"{target}.{a.name}", node.lineno) for a in node.names]
                else:
                    out.append((module, target, node.lineno))
            elif isinstance(node, ast.Import):
                out += [(module, a.name, node.lineno) for a in node.names
                        if a.name.startswith("seaecho")]
    return tuple(out)


def test_every_package_has_a_layer():
    found = {_package(m) for m, _, _ in _imports()}
    found |= {p.stem if p.is_file() else p.name for p in SRC.iterdir()
              if (p.suffix == ".py" or (p.is_dir() and (p / "__init__.py").exists()))}
    found.discard("__init__")
    assert found <= set(RANK), sorted(found - set(RANK))


def test_no_import_reaches_a_later_layer():
    bad = []
    for module, target, line in _imports():
        if (module, target) in LAZY_REEXPORTS:
            continue
        a, b = _package(module), _package(target)
        if b == "__version__":  # ``from .. import __version__`` is the package itself
            b = "seaecho"
        if RANK[b] > RANK[a]:
            bad.append(f"{module}:{line} imports {target} ({a} before {b} in the pipeline)")
    assert not bad, "\n".join(bad)


def test_no_import_cycle_between_packages():
    # Implied by the layer order; stated on its own so that a failure names the cycle.
    graph: dict[str, set[str]] = {}
    for module, target, _ in _imports():
        if (module, target) in LAZY_REEXPORTS:
            continue
        a, b = _package(module), _package(target)
        b = "seaecho" if b == "__version__" else b
        if a != b:
            graph.setdefault(a, set()).add(b)

    def visit(node, stack):
        if node in stack:
            pytest.fail("import cycle: " + " -> ".join(stack[stack.index(node):] + [node]))
        for nxt in graph.get(node, ()):
            visit(nxt, stack + [node])

    for start in graph:
        visit(start, [])


def _modules() -> set[str]:
    """Every module of the source, dotted (``seaecho.io.run``; a package by its name)."""
    out = set()
    for path in SRC.rglob("*.py"):
        parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
        out.add(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return out


def test_no_import_cycle_between_modules():
    # Modules, not only packages: no module imports (at module level or inside a
    # function) a module that imports it back, directly or through others. ``from .x
    # import name`` counts as importing module ``x``, or the package when ``name`` is not
    # a module. Strongly connected components of the graph (Tarjan) name each cycle.
    modules = _modules()
    graph: dict[str, set[str]] = {}
    for module, target, _ in _imports():
        if (module, target) in LAZY_REEXPORTS:
            continue
        if target not in modules:
            target = target.rsplit(".", 1)[0]
        if target in modules and target != module:
            graph.setdefault(module, set()).add(target)
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    cycles = []

    def connect(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while component[-1:] != [v]:
                component.append(stack.pop())
            if len(component) > 1:
                cycles.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            connect(v)
    assert not cycles, "import cycles between modules: " + "; ".join(
        " <-> ".join(c) for c in cycles)


def test_stages_never_read_the_scene_schema():
    bad = [f"{m}:{line} imports {t}" for m, t, line in _imports()
           if _package(m) in STAGES and _package(t) == "config"]
    assert not bad, "\n".join(bad)


def test_only_tracing_imports_mitsuba_or_sionna():
    bad = []
    for path in sorted(SRC.rglob("*.py")):
        if "tracing" in path.relative_to(SRC).parts:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import) else
                     [node.module or ""] if isinstance(node, ast.ImportFrom) and not
                     node.level else [])
            bad += [f"{path.relative_to(SRC)}:{node.lineno} imports {n}" for n in names
                    if n.split(".")[0] in ("mitsuba", "sionna")]
    assert not bad, "\n".join(bad)
