#!/usr/bin/env bash
# The cost of clouds (docs/rendering.md, "Clouds"): ig run on the default
# flight without clouds, under scattered cumulus and under an overcast
# (scenarios/default.json, clouds_cumulus.json, clouds_overcast.json),
# interleaved, REPEATS times each; per scene the median frame time
# (wall_ms, frames 10 on), the cloud pass's own time (clouds_ms) and work
# counters beside them: fragment shader invocations of the cloud pass and
# of the whole frame, and draw calls.
#   tools/bench/cloud_cost.sh BIN_DIR [SIZE] [FRAMES] [REPEATS]
set -euo pipefail
bin=$1 size=${2:-640x512} frames=${3:-200} repeats=${4:-3}
root=$(cd "$(dirname "$0")/../.." && pwd)
scenes=(default clouds_cumulus clouds_overcast)
work=$(mktemp -d /tmp/ig_cloud_cost.XXXXXX)
trap 'rm -rf "$work"' EXIT
for r in $(seq 1 "$repeats"); do
  for s in "${scenes[@]}"; do
    "$bin/ig" run "$root/scenarios/$s.json" --frames "$frames" --size "$size" --out "$work/out_${s}_$r" > /dev/null 2>&1
  done
done
python3 - "$work" "$repeats" "$size" "${scenes[@]}" <<'PY'
import csv, statistics, sys
work, repeats, size, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
def col(rows, name):
    return statistics.median(float(r.get(name) or 0) for r in rows)
base = None
print("| scene | size | frame ms (median of runs) | vs none | clouds ms | cloud pass FS | frame FS | draws |")
print("|---|---|---|---|---|---|---|---|")
for s in scenes:
    runs = [list(csv.DictReader(open(f"{work}/out_{s}_{r}/frames.csv")))[10:] for r in range(1, repeats + 1)]
    ms = statistics.median(col(rows, "wall_ms") for rows in runs)
    clouds = statistics.median(col(rows, "clouds_ms") for rows in runs)
    rows = runs[0]
    base = ms if base is None else base
    print(f"| {s} | {size} | {ms:.1f} | {ms / base:.2f} | {clouds:.1f} | {col(rows, 'clouds_fs') / 1e3:.0f} k | "
          f"{col(rows, 'fs_invocations') / 1e3:.0f} k | {col(rows, 'draw_calls'):.0f} |")
PY
