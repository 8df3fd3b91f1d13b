#!/usr/bin/env bash
# The cost of entities in view (docs/entities.md, "Cost"): ig run on a flight
# with 0, 16, 100 and 1000 scripted entities (tools/bench/entity_traffic.py:
# traffic on the ownship's path 2-12 s ahead), interleaved, REPEATS times
# each; per count the median frame time (wall_ms, frames 10 on) with the
# entity pass's work counters beside it (draw calls, vertex and fragment
# shader invocations, primitives) and the frame's uploaded bytes.
#   tools/bench/entity_cost.sh BIN_DIR SCENARIO.json [SIZE] [FRAMES] [REPEATS] [COUNTS...]
set -euo pipefail
bin=$1 scenario=$2 size=${3:-640x512} frames=${4:-200} repeats=${5:-3}
shift $(( $# < 5 ? $# : 5 ))
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(0 16 100 1000)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d /tmp/ig_entity_cost.XXXXXX)
trap 'rm -rf "$work"' EXIT
for n in "${counts[@]}"; do python3 "$here/entity_traffic.py" "$scenario" "$n" "$work/traffic_$n.json"; done
for r in $(seq 1 "$repeats"); do
  for n in "${counts[@]}"; do
    "$bin/ig" run "$work/traffic_$n.json" --frames "$frames" --size "$size" --out "$work/out_${n}_$r" > /dev/null 2>&1
  done
done
python3 - "$work" "$repeats" "${counts[@]}" <<'PY'
import csv, statistics, sys
work, repeats, counts = sys.argv[1], int(sys.argv[2]), [int(c) for c in sys.argv[3:]]
def col(rows, name):
    return statistics.median(float(r.get(name) or 0) for r in rows)
base = None
print("| entities | frame ms (median of runs) | vs none | entity draws | entity VS | entity FS | entity prims | upload bytes |")
print("|---|---|---|---|---|---|---|---|")
for n in counts:
    runs = [list(csv.DictReader(open(f"{work}/out_{n}_{r}/frames.csv")))[10:] for r in range(1, repeats + 1)]
    ms = statistics.median(col(rows, "wall_ms") for rows in runs)
    rows = runs[0]
    base = ms if base is None else base
    print(f"| {n} | {ms:.2f} | {ms / base:.3f} | {col(rows, 'entities_draws'):.0f} | {col(rows, 'entities_vs'):.0f} | "
          f"{col(rows, 'entities_fs'):.0f} | {col(rows, 'entities_prims'):.0f} | {col(rows, 'upload_bytes'):.0f} |")
PY
