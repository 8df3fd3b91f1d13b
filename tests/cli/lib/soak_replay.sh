#!/usr/bin/env bash
# tests/cli/soak.cmake: the short soak's frames flown again offline
# (soak_report.py replay, then ig run): the replay's first frame is drawn
# at the soak's pose, and every frame lies near the segment between the two
# keys that bracket its time. The path's cubic may bulge past the segment's
# box when the soak's frame times were uneven (a loaded machine), so the
# margin is a quarter of the segment's length plus 1 m: a replay in the wrong
# frame or out of order misses by hundreds of metres.
set -uo pipefail
src=$1 build=$2
run=$build/test-out/soak out=$build/test-out/soak_replay
rm -rf "$out" && mkdir -p "$out"
python3 "$src/tools/bench/soak_report.py" replay "$run" "$out/replay.json" --first 120 --every 30 || exit 1
"$build/bin/ig" run "$out/replay.json" --out "$out/run" > "$out/run.log" 2>&1 || { cat "$out/run.log"; exit 1; }
python3 - "$run/serve/frames.csv" "$out/replay.json" "$out/run/frames.csv" <<'PY'
import csv, json, sys
soak = {int(r["frame"]): r for r in csv.DictReader(open(sys.argv[1]))}
keys = json.load(open(sys.argv[2]))["path"]["keys"]
frames = list(csv.DictReader(open(sys.argv[3])))
first = soak[120]
cols = ("x_m", "y_m", "z_m", "heading_deg", "pitch_deg", "roll_deg")
worst = max(abs(float(frames[0][c]) - float(first[c])) for c in cols)
# Every key is the pose of the soak's frame 120 + 30 i, at its time.
key_off = max(max(abs(k["position"][j] - float(soak[120 + 30 * i][c])) for j, c in enumerate(cols[:3])) +
              abs(k["t"] - (float(soak[120 + 30 * i]["sim_time_s"]) - float(first["sim_time_s"])))
              for i, k in enumerate(keys) if 120 + 30 * i in soak)
keys_found = all(120 + 30 * i in soak for i in range(len(keys)))
def bracket(t):
    i = max([j for j, k in enumerate(keys) if k["t"] <= t + 1e-9] or [0])
    return min(i, len(keys) - 2)
outside, worst_ratio = [], 0.0
for f in frames:
    i = bracket(float(f["sim_time_s"]))
    a, b = keys[i]["position"], keys[i + 1]["position"]
    length = sum((a[j] - b[j]) ** 2 for j in range(3)) ** 0.5
    p = [float(f[c]) for c in cols[:3]]
    out = max(max(min(a[j], b[j]) - p[j], p[j] - max(a[j], b[j]), 0.0) for j in range(3))
    worst_ratio = max(worst_ratio, out / max(length, 1e-6))
    if out > 1.0 + 0.25 * length:
        outside.append(f["frame"])
print("replay: %d keys, %d frames; keys off the soak's frames by %.4f at most%s; first frame off the soak's "
      "frame 120 by %.4f at most; worst bulge past a segment's box %.1f %% of its length; %d frames off their segment"
      % (len(keys), len(frames), key_off, "" if keys_found else " (some keys match no soak frame)", worst,
         100.0 * worst_ratio, len(outside)))
ok = (len(keys) >= 2 and len(frames) >= 2 and keys_found and key_off < 0.01 and worst < 0.01
      and not outside)
print("PASS soak replay" if ok else "FAIL soak replay")
sys.exit(0 if ok else 1)
PY
