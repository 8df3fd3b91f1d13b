#!/usr/bin/env bash
# A host's stream without the wall clock: ig send --record writes the
# datagrams it would send, each received when sent (no socket, no pacing);
# ig run --recording replays them through the same decoders and pose
# filter as ig serve, on a simulated clock of STEP_S a frame. The logged
# poses are then checked against what was sent (check_pose_follow.py), as
# serve_and_send.sh does for a live run, but with the same answer every time.
#   send_and_replay.sh BIN_DIR SRC_DIR OUT_DIR PROTOCOL STEP_S FRAMES [--check ARGS...] [--send ARGS...]
set -euo pipefail
bin=$1 src=$2 out=$3 protocol=$4 step=$5 frames=$6
shift 6
check_args=() send_args=()
source "$(dirname "$0")/split_args.sh"
split_args "check send" "$@"
rm -rf "$out" && mkdir -p "$out"
# The default scenario with frames STEP_S apart (a live IG renders far more often than its 20 Hz).
python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))
s['time']['step_s'] = float(sys.argv[2])
s['capture']['times_s'] = []
json.dump(s, open(sys.argv[3], 'w'), indent=1)" "$src/scenarios/default.json" "$step" "$out/scenario.json"
"$bin/ig-send" "$out/scenario.json" --record "$out/stream.igrec" --protocol "$protocol" --duration 3 \
  --log "$out/send.csv" "${send_args[@]}" | tee "$out/send.log"
"$bin/ig" run "$out/scenario.json" --recording "$out/stream.igrec" --frames "$frames" --size 160x120 \
  --out "$out/run" --quiet > "$out/run.log" 2>&1 || { cat "$out/run.log"; exit 1; }
python3 "$src/tests/tools/check_pose_follow.py" "$out/run/frames.csv" "$out/send.csv" "${check_args[@]}"
