#!/usr/bin/env bash
# A flood of host requests (issue 15): ig serve in its own time (not
# synchronous) on the Sierra DEM, a test host sends 3000 HOT requests after
# each of 10 IG frames against a budget of 2000 a frame; every request must
# be answered once, no frame may carry more than the budget, the backlog is
# answered over the next frames and counted as deferred, rendering goes on.
# Exit 77 without IG_DEM_DIR.
#   host_flood.sh IG QUERY_HOST SRC_DIR OUT_DIR PORT
set -euo pipefail
ig=$1 host=$2 src=$3 out=$4 port=$5
if [ -z "${IG_DEM_DIR:-}" ]; then echo "IG_DEM_DIR not set: host flood test skipped"; exit 77; fi
rm -rf "$out" && mkdir -p "$out"
"$ig" serve --config "$src/scenarios/sierra_owens_valley.json" --cigi "127.0.0.1:$port" \
  --cigi-reply "127.0.0.1:$((port + 1))" --size 64x48 --out "$out/serve" --quiet > "$out/serve.log" 2>&1 &
pid=$!
status=0
"$host" "$IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif" "127.0.0.1:$port" "127.0.0.1:$((port + 1))" 10 \
  --flood 3000 2000 || status=$?
kill -TERM "$pid"  # ig serve ends its frame and writes its summary
wait "$pid" || { cat "$out/serve.log"; echo "FAIL ig serve exited with an error"; exit 1; }
python3 -c "
import json, sys
h = json.load(open(sys.argv[1]))['host_services']
print('ig host_services:', json.dumps(h))
ok = h['requests'] == 30000 and h['answered'] == 30000 and h['deferred'] > 0 and h['pending'] == 0 and not h['dropped']
print('PASS flood summary' if ok else 'FAIL flood summary: expected 30000 requests answered, some deferred, none pending or dropped')
" "$out/serve/summary.json"
exit $status
