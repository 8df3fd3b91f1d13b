#!/usr/bin/env bash
# Benchmark: transport delay per latency mode. For each mode
# (smooth, latest, sync), host rate (30, 60 Hz) and stream (clean; 20 ms
# jitter + 5 % loss), ig serve renders a CIGI stream from ig send on
# loopback; tools/bench/latency_table.py then prints, per run, the transport
# delay (newest pose received -> frame complete, after glFinish), the motion
# lag (display instant - the host instant shown) and the pose error against
# where the host was when the frame completed. Prints a Markdown table.
#   tools/bench/latency.sh [BIN_DIR] [SECONDS] [SIZE]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/bin} seconds=${2:-6} size=${3:-320x240}
out=$(mktemp -d)
port=47950
runs=()
for rate in 30 60; do
  for impair in clean jitter; do
    for mode in smooth latest sync; do
      # A synchronous host waits for each Start Of Frame: network jitter and
      # loss are not what it is for (a lost datagram stalls it 2 s).
      [ "$mode" = sync ] && [ "$impair" = jitter ] && continue
      name="${mode}_${rate}hz_${impair}"
      port=$((port + 2))
      send_extra=() serve_extra=(--latency "$mode")
      [ "$impair" = jitter ] && send_extra+=(--jitter-ms 20 --loss 0.05 --seed 5)
      [ "$mode" = sync ] && send_extra+=(--cigi-sync)
      "$bin/ig" serve --cigi "127.0.0.1:$port" --cigi-reply "127.0.0.1:$((port + 1))" --seconds $((seconds + 2)) \
        --size "$size" --out "$out/$name" --quiet "${serve_extra[@]}" > "$out/$name.log" 2>&1 &
      pid=$!
      for _ in $(seq 1 100); do [ -f "$out/$name/frames.csv" ] && break; sleep 0.1; done
      "$bin/ig-send" scenarios/default.json --to "127.0.0.1:$port" --protocol cigi --rate "$rate" \
        --duration "$seconds" --cigi-listen "127.0.0.1:$((port + 1))" --log "$out/$name.send.csv" --quiet \
        "${send_extra[@]}"
      wait "$pid" || { cat "$out/$name.log"; exit 1; }
      runs+=("$name")
    done
  done
done
echo "ig serve $size headless on $(python3 -c "import json;print(json.load(open('$out/${runs[0]}/summary.json'))['gl_renderer'])" 2>/dev/null || echo '?'), CIGI from ig send, ${seconds} s per run"
python3 tools/bench/latency_table.py "$out" "${runs[@]}"
rm -rf "$out"
