#!/usr/bin/env bash
# ig serve on the Sierra DEM in CIGI synchronous operation, driven by the
# test host tests/tools/cigi_query_host.cpp over loopback: every request type,
# both byte orders, answers checked against the DEM. Exit 77 without IG_DEM_DIR.
# Native queries go to the --udp port (PORT + 2).
#   host_services.sh IG QUERY_HOST SRC_DIR OUT_DIR PORT FRAMES
set -euo pipefail
ig=$1 host=$2 src=$3 out=$4 port=$5 frames=$6
if [ -z "${IG_DEM_DIR:-}" ]; then echo "IG_DEM_DIR not set: host services test skipped"; exit 77; fi
rm -rf "$out" && mkdir -p "$out"
"$ig" serve --config "$src/scenarios/sierra_owens_valley.json" --cigi "127.0.0.1:$port" \
  --cigi-reply "127.0.0.1:$((port + 1))" --udp "127.0.0.1:$((port + 2))" --latency sync --frames "$frames" --size 160x120 \
  --out "$out/serve" --quiet > "$out/serve.log" 2>&1 &
pid=$!
# The host waits for the IG's first Start Of Frame (repeated until a host frame comes).
status=0
"$host" "$IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif" "127.0.0.1:$port" "127.0.0.1:$((port + 1))" "$frames" \
  --native "127.0.0.1:$((port + 2))" || status=$?
wait "$pid" || { cat "$out/serve.log"; echo "FAIL ig serve exited with an error"; exit 1; }
python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))
print('ig host_services:', json.dumps(s['host_services']))
print('ig view_control:', json.dumps(s['view_control']))
if s['view_control']['applied'] != 2 or s['view_control']['notes']:
    print('FAIL view control packets not applied as sent')
" "$out/serve/summary.json"
exit $status
