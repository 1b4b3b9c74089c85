#!/usr/bin/env bash
# Install seaecho into ./.venv (fresh each time it is missing) with what it needs.
#   ./setup.sh        the package
#   ./setup.sh test   the package and its test tools
# On Debian/Ubuntu it also installs libLLVM 19, which Dr.Jit (Mitsuba's CPU back end) needs:
# the default libLLVM 15 aborts on some kernels (docs/install.md).
set -euo pipefail
cd "$(dirname "$0")"
extra=""
[ "${1:-}" = "test" ] && extra="[test]"

if ! ls /usr/lib/*/libLLVM-19.so* /usr/lib/llvm-19/lib/libLLVM*.so* >/dev/null 2>&1; then
  if command -v apt-get >/dev/null 2>&1; then
    SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    echo "setup: installing libllvm19 with apt-get" >&2
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq libllvm19 >/dev/null
  else
    echo "setup: warning: install LLVM >= 16 and set DRJIT_LIBLLVM_PATH (docs/install.md)" >&2
  fi
fi

[ -x .venv/bin/python ] || python3 -m venv .venv
.venv/bin/python -m pip install -q --upgrade pip
.venv/bin/python -m pip install -q ".${extra}"
