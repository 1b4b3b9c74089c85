"""The ``seaecho`` command: thin subcommands, parse -> config -> stage -> files.

Each subcommand lives in its own module of this package with two functions:
``register(subparsers)`` adds its parser (and sets ``func``), ``run(args) -> int`` does
the work. Modules import heavy dependencies inside ``run`` so that ``seaecho check`` and
``--help`` stay fast. Any :class:`~seaecho.config.SceneError` or ``ValueError`` raised for
bad input becomes one message on stderr and exit status 2, with no traceback; so do input
nested too deeply to be read (``RecursionError``) and running out of memory.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import warnings

from .. import __version__

#: Subcommand modules, in the order ``seaecho --help`` lists them.
COMMANDS = (
    "check",
    "surface",
    "run",
    "sweep",
    "image",
    "doppler",
    "detect",
    "score",
    "truth",
    "trace",
    "compare",
    "sigma",
    "permittivity",
)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="seaecho",
        description="Physics-based simulator of bistatic, polarimetric marine radar echoes.",
    )
    parser.add_argument("--version", action="version", version=f"seaecho {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for name in COMMANDS:
        module = importlib.import_module(f".{name}", __name__)
        module.register(sub)
    return parser


class UsageError(ValueError):
    """Bad command-line or scene input: reported in one line, exit status 2."""


def check_memory_option(value: float | None) -> None:
    """``--max-memory-gb`` must be a positive, finite number of GB."""
    if value is not None and not (0 < value < float("inf")):
        raise UsageError(f"--max-memory-gb {value}: must be a positive number of GB")


def _show_warning(message, category, filename, lineno, file=None, line=None):
    """One line per seaecho warning on stderr; others as Python shows them."""
    from ..warnings import SeaechoWarning

    if issubclass(category, SeaechoWarning):
        print(f"seaecho: {category.__name__}: {message}", file=file or sys.stderr)
    else:
        _python_showwarning(message, category, filename, lineno, file, line)


_python_showwarning = warnings.showwarning


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``seaecho`` console script."""
    from ..config import SceneError

    warnings.showwarning = _show_warning
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except (SceneError, UsageError) as exc:
        print(f"seaecho: error: {exc}", file=sys.stderr)
        return 2
    except RecursionError:
        print("seaecho: error: input nested too deeply to be read (a scene file needs at most "
              "a few levels of tables and arrays)", file=sys.stderr)
        return 2
    except MemoryError:
        print("seaecho: error: out of memory; `seaecho check SCENE` prints the estimated "
              "peak memory and the fields that drive it", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("seaecho: interrupted; no partial output was left", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
