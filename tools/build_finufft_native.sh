#!/bin/bash
# finufft compiled for this machine's CPU, in place of the PyPI wheel (docs/install.md,
# "A faster NUFFT"; docs/performance.md, section 1):
#
#   tools/build_finufft_native.sh [PYTHON]        (default: .venv/bin/python)
#
# The PyPI wheels are built for the x86-64 baseline (FINUFFT_ARCH_FLAGS=-march=x86-64:
# SSE2, no FMA); built from the same version's source with -march=native, the spreader
# that sums a pulse's facets uses the CPU's wider vectors. Same tolerance, numbers within
# rounding of the wheel's (vector width and fused multiply-adds differ: the bytes of a
# run change at the rounding level).
#
# Needs a C++17 compiler, cmake >= 3.19 and FFTW 3 (Debian: apt-get install libfftw3-dev).
# finufft's CMake fetches xsimd, findFFTW and CPM.cmake from GitHub; on a machine without
# that access, give local copies (xsimd at the commit finufft pins, see its CMakeLists.txt):
#   XSIMD_SRC=/path/xsimd FINDFFTW_SRC=/path/findFFTW CPM_CACHE=/dir/with/cpm/CPM_<v>.cmake
# Undo with: PYTHON -m pip install --force-reinstall --no-deps --only-binary=:all: finufft
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${1:-.venv/bin/python}
VER=$("$PY" -c "import importlib.metadata as m; print(m.version('finufft'))")
args=(-C cmake.define.FINUFFT_ARCH_FLAGS=-march=native)
[ -n "${XSIMD_SRC:-}" ] && args+=(-C "cmake.define.CPM_xsimd_SOURCE=$XSIMD_SRC")
[ -n "${FINDFFTW_SRC:-}" ] && args+=(-C "cmake.define.CPM_findfftw_SOURCE=$FINDFFTW_SRC")
[ -n "${CPM_CACHE:-}" ] && args+=(-C "cmake.define.CPM_SOURCE_CACHE=$CPM_CACHE")
echo "building finufft $VER for this CPU (a few minutes) ..." >&2
"$PY" -m pip install --no-deps --force-reinstall --no-binary finufft "${args[@]}" \
    "finufft==$VER"
"$PY" - <<'EOF'
import time

import numpy as np

import finufft

rng = np.random.default_rng(0)
x = rng.uniform(-np.pi, np.pi, 500_000)
c = rng.standard_normal(x.size) + 1j * rng.standard_normal(x.size)
plan = finufft.Plan(1, (210,), eps=1e-9, isign=-1, nthreads=1, spread_sort=0)
plan.setpts(x)
plan.execute(c)
t = time.process_time()
for _ in range(10):
    plan.execute(c)
print(f"finufft {finufft.__version__} from {finufft.__file__}: "
      f"{(time.process_time() - t) / 10 * 1e3:.1f} ms of CPU per 500 000-point type 1 "
      "transform (N = 210, eps = 1e-9)")
EOF
