"""``seaecho sweep SCENE.toml --set NAME=VALUES ... -o DIR``: Monte-Carlo realisations and
parameter studies, serially or on a Dask cluster (:mod:`seaecho.distributed`).

VALUES is a value in TOML syntax (``8``, ``"hh"``, ``[0, 0, 10]``), a comma list of them
(``4,8,12``; ``jonswap,elfouhaily``) or an inclusive range ``start:stop:step``
(``4:16:2`` is 4, 6, ..., 16; integers if all three are), or ``start:stop`` of integers
(step 1: ``run.seed=1:3`` is 1, 2, 3). The cases are the Cartesian
product of the ``--set`` options (the last varies fastest), each validated like a scene
file before any work starts (:func:`seaecho.config.overrides.with_overrides`).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

#: At most this many cases in one sweep.
MAX_CASES = 1_000_000
_NUM = r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?"
_RANGE = re.compile(rf"^\s*({_NUM})\s*:\s*({_NUM})\s*:\s*({_NUM})\s*$")
_INT = r"[+-]?\d+"
_INT_RANGE = re.compile(rf"^\s*({_INT})\s*:\s*({_INT})\s*$")
#: What a range looks like, for the messages.
RANGE_SYNTAX = ("a range is start:stop:step (stop included, e.g. 4:16:2 or 0.1:0.5:0.1), "
                "or start:stop for integers with step 1 (e.g. run.seed=1:3)")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "sweep", help="run a scene over a grid of overrides (Monte-Carlo, parameter studies)",
        description="Run the Cartesian product of scene overrides (--set NAME=VALUES), "
        "each case a run written to DIR/case_NNNNN.nc or, with --reduce, a few numbers "
        "(mean sigma0, clutter power and K shape per channel); the table of cases goes "
        "to DIR/summary.csv and DIR/summary.nc. Every case is validated before any work "
        "starts; a case that fails is reported with its error and the others go on "
        "(exit status 1).",
    )
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("--set", dest="sets", action="append", required=True,
                   metavar="NAME=VALUES",
                   help="dotted field name and its values: a TOML value, a comma list, or "
                   "an inclusive range start:stop:step (e.g. sea.wind_speed_m_s=4:16:2, "
                   "run.seed=0:99:1)")
    p.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (created if missing)")
    p.add_argument("--reduce", action="store_true",
                   help="write no run files, only the reduced products in the summary")
    p.add_argument("--pulses", type=int, metavar="N",
                   help="simulate only the first N pulses of every case")
    p.add_argument("--block-pulses", type=int, metavar="N", help="pulses per block")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--workers", type=int, metavar="N",
                   help="one case per task on a local Dask cluster of N worker processes")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on an existing Dask cluster; DIR must be on a file system the "
                   "workers see")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar")
    p.add_argument("--max-memory-gb", type=float, metavar="GB", help="refuse the cases "
                   "whose estimated peak memory (times the workers) exceeds this")
    p.set_defaults(func=run)


def parse_values(text: str) -> tuple[str, list]:
    """``"NAME=VALUES"`` -> (NAME, [values]) (module docstring).

    Raises
    ------
    seaecho.config.SceneError
        A malformed name or range.
    """
    from ..config import SceneError
    from ..config.overrides import parse_assignment

    name, _, raw = text.partition("=")
    m = _RANGE.match(raw)
    m2 = _INT_RANGE.match(raw)
    if m2 and "=" in text:  # start:stop of integers, step 1
        parse_assignment(f"{name}=0")  # checks the name
        a, b = int(m2.group(1)), int(m2.group(2))
        if b < a:
            raise SceneError(f"--set {text}: a range start:stop needs stop >= start; "
                             + RANGE_SYNTAX)
        if b - a + 1 > MAX_CASES:
            raise SceneError(f"--set {text}: {b - a + 1} values, at most {MAX_CASES}")
        return name.strip(), list(range(a, b + 1))
    if m and "=" in text:
        parse_assignment(f"{name}=0")  # checks the name
        start, stop, step = (m.group(i) for i in (1, 4, 7))
        if all(re.fullmatch(r"[+-]?\d+", v) for v in (start, stop, step)):
            a, b, d = int(start), int(stop), int(step)
            n = (b - a) // d + 1 if d > 0 and b >= a else 0
            values = list(range(a, b + 1, d)) if n else []
        else:
            a, b, d = float(start), float(stop), float(step)
            n = int((b - a) / d + 1e-9) + 1 if d > 0 and b >= a else 0
            values = [round(a + i * d, 12) for i in range(n)] if n <= MAX_CASES else []
        if n < 1:
            raise SceneError(f"--set {text}: a range start:stop:step needs step > 0 and "
                             "stop >= start; " + RANGE_SYNTAX)
        if n > MAX_CASES:
            raise SceneError(f"--set {text}: {n} values, at most {MAX_CASES}")
        return name.strip(), values
    parts = _split_top_level(raw)
    values = [parse_assignment(f"{name}={part}")[1] for part in parts]
    return parse_assignment(f"{name}={raw}")[0], values


def _split_top_level(raw: str) -> list[str]:
    """Split at commas outside brackets and quotes."""
    parts, depth, quote, cur = [], 0, "", []
    for ch in raw:
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append("".join(cur))
            cur = []
            continue
        cur.append(ch)
    parts.append("".join(cur))
    return parts


def preflight_cases(cases, base_dir: Path, max_memory_gb: float | None,
                    workers: int | None, block: int | None) -> dict[int, str]:
    """The cases `seaecho run` would refuse (``seaecho.checks.preflight.check_run``: geometry,
    files, memory), each with its message: they are reported as failed, not run."""
    from ..checks.preflight import check_run
    from ..config import SceneError

    refused = {}
    for c in cases:
        try:
            check_run(c.scene, f"case {c.index}", base_dir=base_dir,
                      max_memory_gb=max_memory_gb, figures=False, workers=workers,
                      block=block)
        except SceneError as exc:
            refused[c.index] = f"SceneError: {exc}"
    return refused


def run(args: argparse.Namespace) -> int:
    from ..api import first_pulses
    from ..config import load_scene
    from . import UsageError, check_memory_option

    grid: dict[str, list] = {}
    for text in args.sets:
        name, values = parse_values(text)
        if name in grid:
            raise UsageError(f"--set {name}: given twice")
        grid[name] = values
    n_cases = 1
    for v in grid.values():
        n_cases *= len(v)
    if n_cases > MAX_CASES:
        raise UsageError(f"{n_cases} cases: at most {MAX_CASES}")
    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers {args.workers}: must be >= 1")
    if args.block_pulses is not None and args.block_pulses < 1:
        raise UsageError(f"--block-pulses {args.block_pulses}: must be >= 1")
    out = Path(args.output)
    if str(out.parent) and not out.parent.is_dir():
        raise UsageError(f"output directory {out.parent} does not exist")
    if out.exists() and not out.is_dir():
        raise UsageError(f"-o {out}: exists and is not a folder")

    from .. import distributed
    from ..config import SceneError

    scene = load_scene(args.scene)
    try:
        cases = distributed.sweep_cases(scene, grid, source=args.scene)
    except SceneError as exc:  # e.g. "1.5:3" read as a string: name the range syntax
        if any(isinstance(v, str) and ":" in v for vs in grid.values() for v in vs):
            raise SceneError(f"{exc}\n(--set: {RANGE_SYNTAX})") from None
        raise
    if args.pulses is not None:
        cases = [distributed.Case(c.index, c.overrides, first_pulses(c.scene, args.pulses))
                 for c in cases]
    base_dir = Path(args.scene).parent
    check_memory_option(args.max_memory_gb)
    refused = preflight_cases(cases, base_dir, args.max_memory_gb, args.workers,
                              args.block_pulses)
    out.mkdir(exist_ok=True)
    kw = dict(base_dir=base_dir, reduce=args.reduce, block=args.block_pulses,
              progress=not args.quiet, refused=refused)
    if args.workers is None and args.scheduler is None:
        rows = distributed.sweep(cases, out, **kw)
    else:
        with distributed.cluster(args.workers, args.scheduler) as client:
            rows = distributed.sweep(cases, out, client=client, **kw)
    csv_path, nc_path = distributed.write_summary(rows, out)
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} cases: {len(rows) - len(failed)} done, {len(failed)} failed; "
          f"wrote {csv_path} and {nc_path}")
    for r in failed:
        print(f"seaecho: case {r['case']} failed: {r['error']}", file=sys.stderr)
    return 1 if failed else 0
