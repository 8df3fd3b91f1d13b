#!/usr/bin/env bash
# ig serve --headless --modbus against real clients: mbpoll (Debian's) and the
# libmodbus polling client (bench_modbus --poll). Prints every value it reads.
#   modbus_serve.sh BIN_DIR SRC_DIR OUT_DIR UDP_PORT MODBUS_PORT
# Steps: status registers change as frames are rendered (frame counter read
# twice); thresholds a1=0.05 / a2=0.10 written, Level1 shrinks in frames.csv;
# bad writes rejected and nothing changed; capture trigger -> PNG; 16
# clients at 100 Hz, half a request, garbage bytes; the IG renders throughout.
set -uo pipefail
bin=$1 src=$2 out=$3 udp=$4 port=$5
rm -rf "$out" && mkdir -p "$out"
fail() { echo "FAIL: $*"; kill "$pid" 2>/dev/null; wait "$pid"; echo "ig serve exit status $?"; cat "$out/serve.log" 2>/dev/null; exit 1; }
mb() { mbpoll -m tcp -p "$port" -a 1 -0 -o 2 "$@" 127.0.0.1; }
# A write: mbw OPTIONS... -- VALUES... (mbpoll wants the host before the values).
mbw() {
  local opts=()
  while [ "$1" != "--" ]; do opts+=("$1"); shift; done
  shift
  mbpoll -m tcp -p "$port" -a 1 -0 -o 2 "${opts[@]}" 127.0.0.1 -- "$@"
}
# A value read with -1: the line "[ADDR]: <tab>VALUE".
read_u32() { mb -t 3:int -B -r "$1" -c 1 -1 2>&1 | sed -n "s/^\[$1\]:[[:space:]]*\([-0-9.]*\).*/\1/p"; }
# Waits (polling the frame counter, bounded) until N more frames have been
# rendered: a control written before is then applied. No fixed sleeps.
wait_frames() {
  local start want now
  start=$(read_u32 2); want=$(( ${start:-0} + $1 ))
  for _ in $(seq 1 400); do
    now=$(read_u32 2)
    [ -n "$now" ] && [ "$now" -ge "$want" ] && return 0
    sleep 0.05
  done
  fail "the frame counter stopped at ${now:-?} (waited for $want)"
}
read_hold_f32() { mb -t 4:float -B -r "$1" -c 1 -1 2>&1 | sed -n "s/^\[$1\]:[[:space:]]*\([-0-9.e]*\).*/\1/p"; }

# The default scenario with the two-level eye guard off: the guard keeps
# Level1 over a low eye whatever a1/a2 say, and step 2 checks that the written
# thresholds reach the size controller. Level0 starts at 2048 triangles so
# step 4b's write of 8192 is a visible rebuild.
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); t=s["render"].setdefault("twolevel", {}); t["eye_guard"]=False; t["level0_budget"]=2048; json.dump(s, open(sys.argv[2], "w"))' \
  "$src/scenarios/default.json" "$out/config.json"
"$bin/ig" serve --config "$out/config.json" --headless --udp "127.0.0.1:$udp" \
  --modbus "127.0.0.1:$port" --seconds 16 --size 160x120 --out "$out/serve" > "$out/serve.log" 2>&1 &
pid=$!
for _ in $(seq 1 100); do
  mb -t 3 -r 0 -c 1 -1 > /dev/null 2>&1 && break
  sleep 0.1
done
"$bin/ig-send" "$src/scenarios/default.json" --to "127.0.0.1:$udp" --duration 10 --quiet > "$out/send.log" 2>&1 &
send=$!

# 1. The frame counter increases while frames are rendered. The server is up
# before the first frame (terrain build, first Level1 at full size can take a
# second on a loaded machine): wait for frame 1 first.
for _ in $(seq 1 100); do f1=$(read_u32 2); [ -n "$f1" ] && [ "$f1" -gt 0 ] && break; sleep 0.1; done
wait_frames 5; f2=$(read_u32 2)
echo "mbpoll frame counter: $f1 then $f2"
[ -n "$f1" ] && [ -n "$f2" ] && [ "$f2" -gt "$f1" ] || fail "frame counter did not increase ($f1 -> $f2)"
echo "mbpoll status block:"; mb -t 3 -r 0 -c 37 -1 2>&1 | grep '^\[' | tr '\n' ' '; echo
for _ in $(seq 1 50); do ok=$(read_u32 15); [ -n "$ok" ] && [ "$ok" -gt 0 ] && break; sleep 0.1; done
echo "mbpoll native packets accepted: $ok"
[ -n "$ok" ] && [ "$ok" -gt 0 ] || fail "native_ok not counting ($ok)"

# 2. Thresholds a1=0.05, a2=0.10 in one FC 16 write: Level1 must shrink.
wait_frames 10
fw=$(read_u32 2)
mbw -t 4:float -B -r 2 -- 0.05 0.10 > "$out/write.log" 2>&1 || { cat "$out/write.log"; fail "threshold write"; }
echo "mbpoll wrote a1=0.05 a2=0.10 at frame $fw: $(grep -o 'Written.*' "$out/write.log")"
echo "mbpoll reads back a1=$(read_hold_f32 2) a2=$(read_hold_f32 4)"

# 3. Bad writes are rejected (exit status and message) and change nothing.
bad() {  # expected-message mbpoll-args...
  local want=$1; shift
  if "$@" > "$out/bad.log" 2>&1; then fail "accepted: $*"; fi
  grep -q "$want" "$out/bad.log" || { cat "$out/bad.log"; fail "no '$want' for $*"; }
  local what="$*"; what=${what/#mbw /mbpoll write }; what=${what/#mb /mbpoll read }
  echo "$what -> rejected (exit status non-zero): $want"
}
bad "Illegal data value" mbw -t 4:float -B -r 2 -- 1.5
bad "Illegal data value" mbw -t 4:float -B -r 2 -- 0.2 0.1
bad "Illegal data value" mbw -t 4 -r 0 -- 2
bad "Illegal data value" mbw -t 4:float -B -r 10 -- -5
bad "Illegal data value" mbw -t 4 -r 13 -- 3
bad "Illegal data address" mbw -t 4 -r 14 -- 1
bad "Illegal data address" mb -t 3 -r 36 -c 2 -1
a1=$(read_hold_f32 2); a2=$(read_hold_f32 4)
echo "after bad writes a1=$a1 a2=$a2"
python3 -c "import sys; sys.exit(0 if abs($a1-0.05)<1e-6 and abs($a2-0.10)<1e-6 else 1)" || fail "a bad write changed the thresholds"

# 4. Capture trigger -> the next frame as PNG; the register reads 0 again.
mbw -t 4 -r 12 -- 1 > /dev/null 2>&1 || fail "capture write"
for _ in $(seq 1 30); do ls "$out/serve"/capture_*.png > /dev/null 2>&1 && break; sleep 0.1; done
png=$(ls "$out/serve"/capture_*.png 2>/dev/null | head -1)
[ -n "$png" ] || fail "no capture PNG"
echo "capture trigger -> $(basename "$png")"
cap=$(mb -t 4 -r 12 -c 1 -1 2>&1 | sed -n 's/^\[12\]:[[:space:]]*\([0-9]*\).*/\1/p')
[ "$cap" = "0" ] || fail "capture register reads '$cap', not 0"

# 4b. Level0 budget 8192: the method is rebuilt at the next frame boundary.
fb=$(read_u32 2)
mbw -t 4:int -B -r 8 -- 8192 > /dev/null 2>&1 || fail "level0_budget write"
wait_frames 3
echo "mbpoll wrote level0_budget=8192 at frame $fb"

# 4c. Latency mode 1 (latest): applied at a frame boundary, the frame log says so.
mbw -t 4 -r 13 -- 1 > /dev/null 2>&1 || fail "latency_mode write"
for _ in $(seq 1 50); do tail -1 "$out/serve/frames.csv" | grep -q ",latest," && break; sleep 0.1; done
tail -1 "$out/serve/frames.csv" | grep -q ",latest," || fail "latency_mode 1 not applied"
echo "mbpoll wrote latency_mode=1: frames logged with latency_mode latest"
mbw -t 4 -r 13 -- 0 > /dev/null 2>&1 || fail "latency_mode write back"

# 5. Freeze: the pose stays while ig send keeps streaming; wireframe: flag set.
mbw -t 4 -r 0 -- 1 > /dev/null 2>&1 || fail "freeze write"
wait_frames 2
state=$(mb -t 3 -r 0 -c 1 -1 2>&1 | sed -n 's/^\[0\]:[[:space:]]*\([0-9]*\).*/\1/p')
fz1=$(read_u32 2); wait_frames 30; fz2=$(read_u32 2)
mbw -t 4 -r 0 -- 0 > /dev/null 2>&1 || fail "unfreeze write"
echo "freeze=1: ig_state $state, frames $fz1..$fz2 frozen"
[ "$state" = "3" ] || fail "ig_state is '$state' while frozen, not 3"
mbw -t 4 -r 1 -- 1 > /dev/null 2>&1 || fail "wireframe write"
wait_frames 2
flags=$(mb -t 3 -r 1 -c 1 -1 2>&1 | sed -n 's/^\[1\]:[[:space:]]*\([0-9]*\).*/\1/p')
mbw -t 4 -r 1 -- 0 > /dev/null 2>&1 || fail "wireframe off"
echo "wireframe=1: status_flags $flags"
[ $((flags & 2)) -eq 2 ] || fail "wireframe flag not set ($flags)"

# 6. 16 libmodbus clients at 100 Hz for 2 s, plus half a request that stays,
# one that vanishes, and garbage bytes, all at once.
exec 7<>"/dev/tcp/127.0.0.1/$port" && printf '\x00\x01\x00\x00\x00\x06\x01\x04' >&7
exec 8<>"/dev/tcp/127.0.0.1/$port" && printf '\x00\x01\x00\x00\x00\x06' >&8 && exec 8>&-
exec 9<>"/dev/tcp/127.0.0.1/$port" && head -c 4096 /dev/urandom >&9 2>/dev/null; exec 9>&-
fp1=$(read_u32 2)
"$bin/bench_modbus" --connect "127.0.0.1:$port" --poll 16 --rate 100 --seconds 2 || fail "16 polling clients"
fp2=$(read_u32 2)
exec 7>&-
echo "frame counter during polling: $fp1 -> $fp2"
[ "$fp2" -gt "$fp1" ] || fail "the IG stopped rendering while polled"
clients=$(mb -t 3 -r 29 -c 1 -1 2>&1 | sed -n 's/^\[29\]:[[:space:]]*\([0-9]*\).*/\1/p')
echo "modbus_clients now: $clients"

wait "$send"
wait "$pid" || fail "ig serve exited with an error"
cat "$out/serve.log"
python3 - "$out/serve" "$fw" "$fp1" "$fp2" "$fz1" "$fz2" "$fb" <<'PY' || exit 1
import csv, json, statistics, sys
d, fw, fp1, fp2, fz1, fz2, fb = sys.argv[1], *map(int, sys.argv[2:8])
rows = list(csv.DictReader(open(d + "/frames.csv")))
frames = [int(r["frame"]) for r in rows]
if frames != list(range(len(frames))): print("FAIL: frames.csv rows not continuous"); sys.exit(1)
n = lambda lo, hi: [int(float(r["level1_n"])) for r in rows if lo <= int(r["frame"]) < hi]
before = n(max(0, fw - 30), fw)
after = n(fw + 30, fw + 1000000)
print(f"level1_n before the write (frames {max(0, fw-30)}..{fw-1}): median {statistics.median(before)}; "
      f"30+ frames after: median {statistics.median(after)}, max {max(after)}")
if not statistics.median(after) < statistics.median(before):
    print("FAIL: Level1 did not shrink after a1/a2 = 0.05/0.10"); sys.exit(1)
l0 = lambda lo, hi: [int(float(r["level0_tris"])) for r in rows if lo <= int(r["frame"]) < hi]
l0_before, l0_after = max(l0(0, fb)), max(l0(fb + 1, fz1))
print(f"level0_tris drawn: at most {l0_before} before the budget write, up to {l0_after} after")
if not l0_after > 2048 >= l0_before: print("FAIL: Level0 was not rebuilt with 8192 triangles"); sys.exit(1)
pos = lambda lo, hi: {(r["x_m"], r["y_m"], r["z_m"], r["heading_deg"]) for r in rows if lo <= int(r["frame"]) < hi}
frozen, moving = pos(fz1, fz2), pos(fz1 - 60, fz1 - 30)
print(f"frozen frames {fz1}..{fz2 - 1}: {len(frozen)} distinct pose(s); 30 frames before: {len(moving)}")
if len(frozen) != 1 or len(moving) < 2: print("FAIL: freeze did not hold the pose"); sys.exit(1)
print(f"frames.csv: {len(rows)} rows, {sum(1 for f in frames if fp1 <= f < fp2)} rendered while 16 clients polled")
s = json.load(open(d + "/summary.json"))
print("summary modbus:", json.dumps(s["modbus"]))
if s["modbus"]["clients_dropped"] < 2: print("FAIL: half request / garbage client not dropped"); sys.exit(1)
print("Level1 shrank after the threshold write; the IG kept rendering")
PY
