"""Do the fuzzing suite's properties draw the same examples alone and after other tests?

    nice .venv/bin/python tools/fuzz_draws.py [--fuzz tests/fuzz] \\
        --before tests/radar/test_scan.py --before "tests/config tests/radar/test_scan.py"

Runs ``pytest FUZZ`` alone, then once after each ``--before`` list of test files (in the
same process: ``pytest BEFORE... FUZZ``), and once with the fuzz files in reverse order;
each run records every example each Hypothesis property draws (Hypothesis' observability
output, ``HYPOTHESIS_EXPERIMENTAL_OBSERVABILITY_NOCOVER``, in a folder of its own).
Prints, per property, the number of examples and whether every other run drew the same
ones in the same order (``--each-file``: also each fuzz file run alone, its properties
compared); exit status 1 if one differs (``docs/checks.md``, "Fuzzing suite"). Each run
runs the fuzzing suite (about a minute on a quiet machine) and the files before it.

The recording has a limit of its own: Hypothesis' observability writes each example's
arguments recursively, and an example nested deeper than Python's recursion limit (a
``nesting`` mutation, arrays up to 3000 deep) fails there with a ``RecursionError``
(``hypothesis/strategies/_internal/utils.py``, not seaecho); the failures of each run are
printed, and such a run's record of that property is not comparable.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def draws(args: list[str], label: str) -> dict[tuple[str, int], list[str]]:
    """{(property, its k-th run): [example, ...]} of ``pytest ARGS``."""
    with tempfile.TemporaryDirectory(prefix="seaecho-fuzz-draws-") as tmp:
        env = dict(os.environ, HYPOTHESIS_STORAGE_DIRECTORY=tmp,
                   HYPOTHESIS_EXPERIMENTAL_OBSERVABILITY_NOCOVER="1")
        cmd = [sys.executable, "-m", "pytest", "-q", "-rf", "-p", "no:cacheprovider",
               "-p", "no:randomly", *args]
        print(f"[{label}] {' '.join(cmd[3:])}", file=sys.stderr, flush=True)
        r = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True)
        summary = [line for line in r.stdout.splitlines() if line.startswith("FAILED")]
        summary += r.stdout.strip().splitlines()[-1:] if r.stdout else [r.stderr]
        print("\n".join(f"[{label}] {line}" for line in summary), file=sys.stderr,
              flush=True)
        runs: dict[str, list[float]] = defaultdict(list)
        out: dict[tuple[str, int], list[str]] = defaultdict(list)
        for path in sorted(Path(tmp).glob("observed/*_testcases.jsonl")):
            for line in path.read_text().splitlines():
                case = json.loads(line)
                if case.get("type") != "test_case":
                    continue
                name, start = case["property"], case["run_start"]
                if start not in runs[name]:
                    runs[name].append(start)
                out[(name, runs[name].index(start))].append(
                    f"{case['how_generated']}: {case['representation']}")
        return dict(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--fuzz", default="tests/fuzz",
                        help="the fuzzing test files or folder (default: tests/fuzz)")
    parser.add_argument("--before", action="append", default=[],
                        help="test files run before the fuzzing suite (space-separated; "
                             "repeat for several runs)")
    parser.add_argument("--each-file", action="store_true",
                        help="also run each fuzzing file alone (its properties compared)")
    args = parser.parse_args(argv)
    fuzz = args.fuzz.split()
    files = sorted(str(p.relative_to(ROOT)) for f in fuzz
                   for p in ([ROOT / f] if f.endswith(".py")
                             else sorted((ROOT / f).glob("test_*.py"))))
    runs = {"alone": draws(files, "alone")}
    for before in args.before:
        runs[f"after {before}"] = draws(before.split() + files, f"after {before}")
    if len(files) > 1:
        runs["files reversed"] = draws(files[::-1], "files reversed")
    alone_files = files if args.each_file and len(files) > 1 else []
    for f in alone_files:
        runs[f"{f} alone"] = draws([f], f"{f} alone")
    reference = runs["alone"]
    same = True
    for key in sorted(reference):  # the fuzzing properties (not those of --before)
        verdicts = []
        for label, drawn in runs.items():
            if label == "alone":
                continue
            if label.endswith(" alone") and key not in drawn:
                continue  # a file alone runs only its own properties
            ok = drawn.get(key) == reference.get(key)
            same &= ok
            verdicts.append(f"{label}: {'same' if ok else 'DIFFERENT'}")
        name, k = key
        print(f"{name} (run {k}): {len(reference.get(key, []))} examples; "
              + "; ".join(verdicts))
    print("all runs drew the same examples" if same else "the draws depend on the order")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
