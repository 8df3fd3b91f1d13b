#!/usr/bin/env bash
# tests/cli/soak.cmake: the short soak's frames flown again offline
# (soak_report.py replay, then ig run): the replay's first frame is drawn
# at the soak's pose, and every frame within the stretch's extent (1 m:
# the path's curve between keys may bulge out a little).
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
lo = [min(k["position"][i] for k in keys) - 1.0 for i in range(3)]
hi = [max(k["position"][i] for k in keys) + 1.0 for i in range(3)]
outside = [f["frame"] for f in frames
           if any(not lo[i] <= float(f[c]) <= hi[i] for i, c in enumerate(("x_m", "y_m", "z_m")))]
print("replay: %d keys, %d frames; first frame off the soak's frame 120 by %.4f at most; %d outside the stretch"
      % (len(keys), len(frames), worst, len(outside)))
ok = len(keys) >= 2 and len(frames) >= 2 and worst < 0.01 and not outside
print("PASS soak replay" if ok else "FAIL soak replay")
sys.exit(0 if ok else 1)
PY
