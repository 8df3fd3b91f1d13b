#!/usr/bin/env bash
# tests/cli/gpu_pack.cmake: packs BUILD_DIR's ig into OUT/pack, checks what
# the packed ig resolves, then gpu_tables.sh's smoke run on DEM_DIR.
set -uo pipefail
src=$1 build=$2 dem=$3 out=$4
python3 "$src/tools/bench/gpu_pack.py" "$build" "$out/pack" --keep xml2 || exit 1
outside=$(LD_LIBRARY_PATH="$out/pack/lib" ldd "$out/pack/bin/ig" | grep -v "$out/pack/lib" |
  grep -v -E 'linux-vdso|lib(c|m|dl|pthread|rt)\.so|ld-linux' || true)
[ -z "$outside" ] || { echo "resolved outside the package: $outside"; exit 1; }
size=$(stat -c %s "$out/pack/lib/libopenvdb.so.10.0")
[ "$size" -lt 1000000 ] || { echo "libopenvdb not stubbed: $size bytes"; exit 1; }
bash "$src/tools/bench/gpu_tables.sh" "$out/pack" "$dem" "$out/tables" none
