#!/usr/bin/env bash
# Table 2 on a GPU machine (docs/results.md, "On a GPU"), from a folder that
# tools/bench/gpu_pack.py made, without installing anything but the GL
# dispatch libraries (glvnd: libegl1 libopengl0 libglvnd0, which hand EGL to
# the NVIDIA driver).
#
#   tools/bench/gpu_tables.sh PACK_DIR DEM_DIR OUT_DIR [RUN_REGEX]
#
# PACK_DIR: gpu_pack.py's output; DEM_DIR: holds the Sierra DEM (what
# IG_DEM_DIR names here); OUT_DIR gets one ig bench folder and log per run.
# RUN_REGEX picks runs by name (default: all): reduced15 reduced60 full15
# full60 reduced15_noculling. Each run has its own time limit, so one that
# runs over leaves the others' results. A 4-frame smoke run comes first and
# stops the script when EGL or the libraries fail. Every run is interleaved
# (--interleave): at frames of a few ms the GPU's clock drifts during a run,
# and so it reaches every method alike. On an H100 the runs took about 50,
# 60 and 210 s; full60 was cut off unfinished after 230 s. Where one
# command may run 10 minutes, run 'reduced.*' and 'full.*' as two.
set -uo pipefail
[ $# -ge 3 ] || { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
pack=$(cd "$1" && pwd) dem=$(cd "$2" && pwd) out=$3 only=${4:-.*}
mkdir -p "$out"; out=$(cd "$out" && pwd)
here=$(cd "$(dirname "$0")/../.." && pwd)
scenario=$here/scenarios/table2_sierra.json

nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$nv" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
export IG_DEM_DIR=$dem IG_SHADER_DIR=$pack/bin/shaders PROJ_DATA=$pack/proj GDAL_DATA=$pack/gdal
libs=$pack/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib:/usr/lib/x86_64-linux-gnu
glibc=$(ldd --version 2>/dev/null | head -1 | grep -o '[0-9]\.[0-9]*$')
# The packed libraries need glibc 2.36 (Debian 12's); an older machine runs
# them on the packed C library and loader.
if [ "$(printf '%s\n2.36\n' "$glibc" | sort -V | head -1)" = 2.36 ]; then
  ig=(env LD_LIBRARY_PATH="$libs" "$pack/bin/ig")
else
  ig=("$pack/glibc/ld-linux-x86-64.so.2" --library-path "$pack/glibc:$libs" "$pack/bin/ig")
fi
echo "machine glibc $glibc, $(nproc) CPUs; $(nvidia-smi -L 2>/dev/null || echo 'no nvidia-smi')"

"${ig[@]}" bench "$scenario" --methods twolevel --size 160x128 --frames 4 --error-samples 1 \
  --out "$out/smoke" > "$out/smoke.log" 2>&1
if [ ! -s "$out/smoke/results.csv" ]; then
  cat "$out/smoke.log"; echo "gpu_tables: the smoke run failed (log above)"; exit 1
fi
grep -m1 'on .* in ' "$out/smoke.log"

run() {
  local name=$1 limit=$2; shift 2
  [[ $name =~ ^($only)$ ]] || return 0
  echo "== $name $(date +%T)"
  timeout "$limit" "${ig[@]}" bench "$scenario" "$@" --out "$out/$name" > "$out/$name.log" 2>&1
  echo "exit $? $(date +%T) (1: no gnuplot for the plots; 124: over ${limit} s)"
}
reduced=(--methods all --sweep --interleave --size 640x512 --frames 40 --error-samples 6)
run reduced15 150 "${reduced[@]}" --fov 15
run reduced60 150 "${reduced[@]}" --fov 60
run full15 300 --methods all --sweep --interleave --fov 15
run full60 300 --methods all --sweep --interleave --fov 60
run reduced15_noculling 150 "${reduced[@]}" --fov 15 --horizon-culling off
