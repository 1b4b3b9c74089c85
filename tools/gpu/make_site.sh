#!/bin/bash
# A trimmed site-packages for a GPU machine without a package index (docs/performance.md,
# section 4), packed as one xz archive:  tools/gpu/make_site.sh WHEELS_DIR OUT.tar.xz
# WHEELS_DIR holds the cp312 manylinux wheels (pip download --no-deps --only-binary=:all:
# --python-version 3.12 ...) of: mitsuba 3.9.1, drjit 1.5.0, sionna-rt 2.2.0, pydantic,
# pydantic_core, annotated-types, typing-inspection, importlib_resources, h5netcdf,
# trimesh, finufft, cufinufft 2.5.1 and nvidia-cuda-runtime-cu12.
set -euo pipefail
W=$(cd "$1" && pwd); OUTFILE=$(realpath -m "$2"); HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d); S=$T/site; mkdir -p $S
for w in "$W"/*.whl; do
  case $(basename $w) in nvidia_cuda_runtime*) ;; *) unzip -q -o "$w" -d $S;; esac
done
cd $S
rm -rf lib64 share ./*.dist-info/RECORD
find . -name '*.pyi' -delete
find . -depth -type d \( -name __pycache__ -o -name tests -o -name test \) -exec rm -rf {} +
rm -rf mitsuba/include mitsuba/mitsuba_stubs mitsuba/cmake mitsuba/pkgconfig drjit/include \
       drjit/cmake mitsuba/data/srgb.coeff mitsuba/data/sunsky sionna/rt/scenes/*/
for f in mitsuba/*_ad_*.so mitsuba/scalar_*.so; do
  case $(basename $f) in cuda_ad_mono_polarized.*|llvm_ad_mono_polarized.*|scalar_rgb.*) ;;
                         *) rm -f $f;; esac
done
keep=" diffuse uniform ply obj serialized independent perspective hdrfilm box path direct \
gaussian tent rectangle disk sphere cube cylinder twosided conductor dielectric \
roughconductor constant area point directional spot "
for f in mitsuba/plugins/*.so; do
  [[ $keep == *" $(basename $f .so) "* ]] || rm -f $f
done
# cufinufft: only the H100's (sm_90) machine code; CUDA 12's runtime beside it, and
# libcufft.so.11 forwarding to CUDA 13's libcufft.so.12
python3 $HERE/fatbin.py cufinufft/libcufinufft.so $T/cf.so 90 elf
mv $T/cf.so cufinufft/libcufinufft.so
unzip -q -o -j "$W"/nvidia_cuda_runtime_cu12-*.whl 'nvidia/cuda_runtime/lib/libcudart.so.12' \
  -d cufinufft/
gcc -shared -fPIC -O2 -o cufinufft/libcufft.so.11 $HERE/cufft_forward.c \
  -Wl,--version-script=$HERE/cufft.map -Wl,-soname,libcufft.so.11 -ldl
tar -cf - . | xz -T2 -6 > "$OUTFILE"
rm -rf $T
ls -la "$OUTFILE"
