#!/usr/bin/env bash
# Three IG channel processes (left, centre, right of scenarios/three_channels.json)
# join one loopback multicast group; one ig send stream feeds them all; each
# must follow the sent path.
#   multicast_channels.sh BIN_DIR SRC_DIR OUT_DIR
set -euo pipefail
bin=$1 src=$2 out=$3
group=239.255.71.80 port=47180
rm -rf "$out" && mkdir -p "$out"
pids=()
for ch in left centre right; do
  "$bin/ig" serve --config "$src/scenarios/three_channels.json" --channel "$ch" --multicast "$group" \
    --udp ":$port" --seconds 7 --size 160x120 --out "$out/$ch" --quiet > "$out/$ch.log" 2>&1 &
  pids+=($!)
done
for ch in left centre right; do
  for _ in $(seq 1 100); do [ -f "$out/$ch/frames.csv" ] && break; sleep 0.1; done
done
"$bin/ig-send" "$src/scenarios/three_channels.json" --to "$group:$port" --duration 3 --log "$out/send.csv"
for p in "${pids[@]}"; do wait "$p"; done
ok=0
for ch in left centre right; do
  echo "channel $ch:"
  grep -q "\"channels\": 1" "$out/$ch/summary.json"
  python3 "$src/tests/tools/check_pose_follow.py" "$out/$ch/frames.csv" "$out/send.csv" && ok=$((ok + 1))
done
[ "$ok" -eq 3 ] && echo "all 3 channels follow the sent path" || echo "FAIL: $ok of 3 channels followed"
