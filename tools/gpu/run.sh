#!/bin/bash
# The GPU measurements of docs/performance.md, section 4, on a machine with an NVIDIA GPU
# and no package index. From the root of a seaecho checkout there:
#   OUT=results/ bash tools/gpu/run.sh site.tar.xz
# site.tar.xz: tools/gpu/make_site.sh's archive (packages the machine lacks; it had
# numpy, scipy, xarray, h5py, matplotlib, pytest and hypothesis, and CUDA 13's cuFFT in
# PyTorch's environment). Each step has its own time limit; the log is $OUT/log.
# About 3 minutes on an H100 (each limit below is the most a step may take): the
# environment, the gpu-marked tests, the held Simulation 2 pulse traced and then frozen
# (the sea's kernel and the scatterers' radar equation replayed, the hull's echo kept on
# the device, one transform per pulse; then the frozen one with each stage waiting for
# the GPU, so that it holds its own GPU work), the coastal revolution's stages over all its
# pulses on CUDA. The earlier measurements (SBR, new sea every pulse) are
# tools/gpu/run_previous.sh's steps; the revolution's stride-25 stages on CUDA and on the
# LLVM back end were this script's steps 4 and 6 before (its history).
set -u
export PYTHONUNBUFFERED=1
R=$(pwd); L=$OUT/log; mkdir -p "$OUT"
SITE=${SITE:-/tmp/site}; mkdir -p $SITE && tar -xJf "$1" -C $SITE || exit 3
CUFFT=$(dirname "$(find /opt /usr -name 'libcufft.so.12*' 2>/dev/null | head -1)")
export LD_LIBRARY_PATH=$SITE/cufinufft:$CUFFT:${LD_LIBRARY_PATH:-}
export PYTHONPATH=$SITE:$R/src:$R/benchmarks:$R/tests:$R/tests/radar
export SEAECHO_CACHE_DIR=/tmp/seaecho-cache; PY=${PY:-python3}
step() { local t=$1; shift; echo "=== $(date +%T) [$SECONDS s] $*" | tee -a $L
         timeout $t "$@" 2>&1 | tee -a $L; echo "=== rc ${PIPESTATUS[0]} [$SECONDS s]" | tee -a $L; }
B=benchmarks/bench_gpu.py
C=cuda_ad_mono_polarized
step 40 $PY tools/gpu/check_env.py                                          # 1
step 120 $PY -m pytest -q -p no:cacheprovider -m gpu tests/test_backend.py \
    tests/radar/test_resident.py tests/radar/test_replay.py                 # 2
step 100 $PY $B --no-cpu --pulses 40 --warmup 3                             # 3
step 60 $PY $B --no-cpu --pulses 20 --warmup 3 --freeze 1 --sync-stages      # 3b
step 100 $PY $B --scan --stride 1 --stages --variant $C                     # 4
echo "done [$SECONDS s]" | tee -a $L
