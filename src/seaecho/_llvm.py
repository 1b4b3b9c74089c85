"""Point Dr.Jit at a libLLVM that works, before drjit is first imported.

Mitsuba's CPU variants JIT through the system's libLLVM. libLLVM 15 (Debian 12's default)
aborts the process on ``dr.maximum``/``dr.minimum``/``dr.atan2`` ("Cannot select:
fmaximum"); libLLVM >= 16 works (docs/install.md). The project's
set-up installs Debian's ``libllvm19``. Call :func:`configure_llvm` before importing drjit;
it leaves a user's own ``DRJIT_LIBLLVM_PATH`` alone.
"""

from __future__ import annotations

import glob
import os
import sys

#: Versions tried, newest first; 15 and older are known to abort (see module docstring).
_GOOD_VERSIONS = (21, 20, 19, 18, 17, 16)
_SEARCH_DIRS = (
    "/usr/lib/x86_64-linux-gnu",
    "/usr/lib/aarch64-linux-gnu",
    "/usr/lib64",
    "/usr/lib",
    "/usr/local/lib",
    "/opt/homebrew/opt/llvm/lib",
    "/usr/local/opt/llvm/lib",
)


def find_libllvm() -> str | None:
    """Path of the newest usable libLLVM (version >= 16) on this machine, or None."""
    for version in _GOOD_VERSIONS:
        candidates = []
        for directory in _SEARCH_DIRS:
            candidates += glob.glob(os.path.join(directory, f"libLLVM-{version}.so*"))
            candidates += glob.glob(os.path.join(directory, f"libLLVM.so.{version}*"))
            candidates += glob.glob(
                os.path.join(directory, f"llvm-{version}", "lib", "libLLVM*.so*")
            )
            candidates += glob.glob(os.path.join(directory, f"libLLVM-{version}.dylib"))
        candidates += glob.glob(f"/usr/lib/llvm-{version}/lib/libLLVM*.so*")
        if candidates:
            return sorted(candidates, key=len)[0]
    return None


def configure_llvm() -> str | None:
    """Set ``DRJIT_LIBLLVM_PATH`` to a working libLLVM unless the user set it.

    Returns the path in use (or None if none was found; Dr.Jit then falls back to its
    own search, which may pick a libLLVM that aborts on some kernels).
    """
    if "DRJIT_LIBLLVM_PATH" in os.environ:
        return os.environ["DRJIT_LIBLLVM_PATH"]
    if "drjit" in sys.modules:  # too late to choose; say what is in use
        return None
    path = find_libllvm()
    if path is not None:
        os.environ["DRJIT_LIBLLVM_PATH"] = path
    return path


__all__ = ["configure_llvm", "find_libllvm"]
