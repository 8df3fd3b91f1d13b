#!/usr/bin/env bash
# Loopback end to end: ig serve (headless, small frames) receives what
# ig send plays from the default scenario; then the logged poses are checked
# against what was sent.
#   serve_and_send.sh BIN_DIR SRC_DIR OUT_DIR PROTOCOL PORT [--check ARGS...] [--send ARGS...] [--serve ARGS...]
set -euo pipefail
bin=$1 src=$2 out=$3 protocol=$4 port=$5
shift 5
check_args=() send_args=() serve_args=()
source "$(dirname "$0")/split_args.sh"
split_args "check send serve" "$@"
rm -rf "$out" && mkdir -p "$out"
case "$protocol" in
  native) flag=--udp ;;
  cigi) flag=--cigi; serve_args+=(--cigi-reply "127.0.0.1:$((port + 1))"); send_args+=(--cigi-listen "127.0.0.1:$((port + 1))") ;;
  fgfdm) flag=--fgfdm ;;
esac
"$bin/ig" serve --config "$src/scenarios/default.json" "$flag" "127.0.0.1:$port" --seconds 7 --size 160x120 \
  --out "$out/serve" --quiet "${serve_args[@]}" > "$out/serve.log" 2>&1 &
pid=$!
for _ in $(seq 1 100); do [ -f "$out/serve/frames.csv" ] && break; sleep 0.1; done
"$bin/ig-send" "$src/scenarios/default.json" --to "127.0.0.1:$port" --protocol "$protocol" --duration 3 \
  --log "$out/send.csv" "${send_args[@]}" | tee "$out/send.log"
wait "$pid" || { cat "$out/serve.log"; exit 1; }
cat "$out/serve.log"
# capture.times_s of the config: seconds since ig serve started (0 and 5 fall in a 7 s run).
echo "serve captures: $(ls "$out/serve"/capture_*.png 2>/dev/null | wc -l) (capture.times_s inside the run: $(python3 -c "
import json,sys; c=json.load(open(sys.argv[1])).get('capture',{}).get('times_s',[]); print(sum(1 for t in c if t < 7))" "$src/scenarios/default.json"))"
python3 "$src/tests/tools/check_pose_follow.py" "$out/serve/frames.csv" "$out/send.csv" "${check_args[@]}"
