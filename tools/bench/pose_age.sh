#!/usr/bin/env bash
# Benchmark: pose_age_ms (packet receive -> frame start) under a 60 Hz native
# stream while ig serve renders, and the frame time meanwhile. Prints figures.
#   tools/bench/pose_age.sh [BIN_DIR] [SECONDS] [SIZE]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/bin} seconds=${2:-10} size=${3:-640x480}
out=$(mktemp -d)
"$bin/ig" serve --udp 127.0.0.1:47990 --seconds $((seconds + 3)) --size "$size" --out "$out/serve" --quiet > /dev/null &
pid=$!
for _ in $(seq 1 100); do [ -f "$out/serve/frames.csv" ] && break; sleep 0.1; done
"$bin/ig-send" scenarios/default.json --to 127.0.0.1:47990 --rate 60 --duration "$seconds" --quiet
wait "$pid"
python3 - "$out/serve/frames.csv" "$size" <<'PY'
import csv, statistics, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["pose_mode"] == "interpolating"]
age = sorted(float(r["pose_age_ms"]) for r in rows)
ms = sorted(float(r["wall_ms"]) for r in rows)
p = lambda v, q: v[min(len(v) - 1, int(q * len(v)))]
print(f"60 Hz native stream, ig serve headless {sys.argv[2]}, {len(rows)} frames on received poses:")
print(f"  pose_age_ms median {statistics.median(age):.1f}, p99 {p(age, 0.99):.1f}, max {age[-1]:.1f}")
print(f"  frame wall_ms median {statistics.median(ms):.1f}, p99 {p(ms, 0.99):.1f}")
PY
rm -rf "$out"
