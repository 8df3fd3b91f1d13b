#!/usr/bin/env bash
# Two hosts on the IG's CIGI port: ig serve, told --host the first one's
# socket, follows that host's path; the second host (another aircraft 2 km
# east, flying 90 degrees off) moves nothing and every datagram it sent is
# counted as foreign.
#   two_hosts.sh BIN_DIR SRC_DIR OUT_DIR PORT
set -euo pipefail
bin=$1 src=$2 out=$3 port=$4
rm -rf "$out" && mkdir -p "$out"
python3 - "$src/scenarios/default.json" "$out/other.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
for k in s["path"]["keys"]:
    k["position"][0] += 2000.0
    k["hpr"][0] = (k["hpr"][0] + 90) % 360
json.dump(s, open(sys.argv[2], "w"))
EOF
host="127.0.0.1:$((port + 2))" other="127.0.0.1:$((port + 3))"
"$bin/ig" serve --config "$src/scenarios/default.json" --cigi "127.0.0.1:$port" --host "$host" --seconds 7 \
  --size 160x120 --out "$out/serve" > "$out/serve.log" 2>&1 &
pid=$!
for _ in $(seq 1 100); do [ -f "$out/serve/frames.csv" ] && break; sleep 0.1; done
"$bin/ig-send" "$out/other.json" --to "127.0.0.1:$port" --protocol cigi --from "$other" --duration 3 \
  > "$out/other.log" 2>&1 &
other_pid=$!
"$bin/ig-send" "$src/scenarios/default.json" --to "127.0.0.1:$port" --protocol cigi --from "$host" --duration 3 \
  --log "$out/send.csv" | tee "$out/send.log"
wait "$other_pid" || { cat "$out/other.log"; exit 1; }
cat "$out/other.log"
wait "$pid" || { cat "$out/serve.log"; exit 1; }
cat "$out/serve.log"
python3 - "$out/serve/summary.json" "$out/other.log" <<'EOF'
import json, re, sys
s = json.load(open(sys.argv[1]))
sent = int(re.search(r": (\d+) datagrams sent", open(sys.argv[2]).read()).group(1))
foreign = s["foreign_datagrams"]
print(f"second host sent {sent}, foreign_datagrams {foreign}, cigi source {s['senders']['sources']['cigi']}")
if sent == 0 or foreign != sent:
    print("FAIL: every datagram of the second host must be counted as foreign")
EOF
python3 "$src/tests/tools/check_pose_follow.py" "$out/serve/frames.csv" "$out/send.csv"
