#!/usr/bin/env bash
# Cost breakdown of the two-level method's passes: times the Table 2
# flight with every pass, then without each one in turn (ig bench
# --skip-pass), side by side in one run; prints median frame ms, CPU ms and the work
# counters per variant. Images without a pass are wrong on purpose: only
# the time and work matter here.
#   IG_DEM_DIR=... tools/bench/twolevel_passes.sh [BIN_DIR] [SIZE] [FRAMES] [FOV]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/bin} size=${2:-640x512} frames=${3:-40} fov=${4:-15}
: "${IG_DEM_DIR:?set IG_DEM_DIR to the folder with the shared DEMs}"
out=$(mktemp -d)
echo "| variant | frame ms median | p95 | CPU ms | LOD ms | fragment invocations | vertex invocations | draw calls | bytes uploaded |"
echo "|---|---|---|---|---|---|---|---|---|"
for skip in none level1 band level0 count; do
  args=()
  [ "$skip" != none ] && args=(--skip-pass "$skip")
  "$bin/ig" bench scenarios/table2_sierra.json --methods twolevel --size "$size" --frames "$frames" --fov "$fov" \
    --error-samples 1 --out "$out/$skip" "${args[@]}" > /dev/null 2>&1
  python3 - "$out/$skip/results.csv" "$skip" <<'PY'
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
name = "all passes" if sys.argv[2] == "none" else "without " + sys.argv[2]
print(f"| {name} | {float(r['frame_ms_median']):.2f} | {float(r['frame_ms_p95']):.2f} | {float(r['cpu_ms_median']):.2f} | {float(r['lod_ms_median']):.3f} | "
      f"{float(r['fs_invocations_median']):.0f} | {float(r['vs_invocations_median']):.0f} | "
      f"{float(r['draw_calls_median']):.0f} | {float(r['upload_bytes_median']):.0f} |")
PY
done
rm -rf "$out"
