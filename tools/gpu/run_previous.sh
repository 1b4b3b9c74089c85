#!/bin/bash
# The GPU measurements of docs/performance.md, section 4, on a machine with an NVIDIA GPU
# and no package index. From the root of a seaecho checkout there:
#   OUT=results/ bash tools/gpu/run.sh site.tar.xz
# site.tar.xz: tools/gpu/make_site.sh's archive (packages the machine lacks; it had
# numpy, scipy, xarray, h5py, matplotlib, pytest and hypothesis, and CUDA 13's cuFFT in
# PyTorch's environment). Each step has its own time limit; the log is $OUT/log.
# The previous session's measurements (kept to repeat them); run.sh is the current one.
# (Run in five calls there: steps 1-4 and 7; 3 with the CPU comparison, 5 and 8; 2 and 5
# with --sbr-profile; 6; 3 and 3b with 60 pulses.)
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
step 40 $PY tools/gpu/check_env.py                                          # 1
step 150 $PY $B --sbr --sbr-profile --variant cuda_ad_mono_polarized        # 2
step 180 $PY $B --save $OUT --pulses 30 --warmup 3                          # 3
step 60 $PY $B --no-cpu --pulses 60 --warmup 3 --freeze 1 --unbatched       # 3b
step 150 $PY -m pytest -q -p no:cacheprovider -m gpu tests/test_backend.py tests/radar/test_resident.py  # 4
step 90 $PY $B --sbr --sbr-profile --variant llvm_ad_mono_polarized --sbr-batch 262144  # 5
step 200 $PY $B --no-cpu --pulses 12 --warmup 2 --update 1                  # 6
step 200 $PY $B --no-cpu --pulses 12 --warmup 2 --update 1 --refresh 0
step 70 $PY $B --scan --stride 25 --variant cuda_ad_mono_polarized          # 7
step 70 $PY $B --scan --stride 25 --variant llvm_ad_mono_polarized          # 8
echo "done [$SECONDS s]" | tee -a $L
