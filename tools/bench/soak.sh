#!/usr/bin/env bash
# Soak benchmark: `ig serve` for a long flight under full host load, its
# resident memory, open files and threads sampled from /proc as it goes
# (docs/results.md, "Soak: a long flight under full host load").
#
#   tools/bench/soak.sh BUILD_DIR OUT_DIR [options] [-- soak_report.py options]
#
# The rig, all on loopback:
#  * ig serve (headless, --cigi, --cigi-reply, --modbus) on the terrain:
#    big (default): a VRT of 5 x 5 copies of the Sierra DEM from $IG_DEM_DIR
#    (20481², made in OUT_DIR by make_copies_vrt.py, no data copied; delete
#    OUT_DIR after), paged within terrain.memory_budget_mb (--budget-mb);
#    default: scenarios/default.json (generated terrain, no DEM);
#    or any scenario FILE.json (its capture schedule is dropped).
#  * a CIGI host at --rate Hz in its own time (tests/tools/cigi_query_host
#    --soak): the ownship's Entity Control flying a circle (for big: 150 km
#    radius about the corner of four copies nearest the middle, crossing
#    copy boundaries, new terrain all the way round, so the height window
#    scrolls and tiles are paged in and evicted all the time), with --hot
#    HAT/HOT and --los LOS requests in every datagram, near the ownship.
#  * mbpoll reading the 37 status registers at --modbus-hz (one client,
#    one connection).
#  * every --sample-every seconds: VmRSS, RssAnon, RssFile, Threads from
#    /proc/PID/status and the /proc/PID/fd count of ig serve (soak_report.py sample).
# After the host's --duration seconds: mbpoll stopped, ig serve sent SIGTERM
# (it writes summary.json and exits 0), then soak_report.py reports:
# the samples, growth after --warmup, frame times, frames over twice the
# frame budget and why (soak_report.py report; options after -- go to it).
# Synchronisation by events only: the host starts on the IG's first Start
# Of Frame and tells this script so on its stdout, which starts mbpoll.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage() { awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; cat <<'EOF'
options:
  --duration S        seconds the host flies (default 3600)
  --terrain T         big | default | FILE.json (default big; big needs IG_DEM_DIR)
  --budget-mb MB      terrain.memory_budget_mb for big (default 64: the tile cache is full
                      before the first frame, so every page-in evicts a tile)
  --size WxH          image size (default 320x240)
  --hot N, --los N    HAT/HOT and LOS requests in each host datagram (default 100, 10)
  --spread M          requests within M metres of the ownship (default 5000)
  --rate HZ           host datagrams a second (default 60)
  --speed MPS         ownship speed (default 250)
  --radius M          circle radius (big: default 150000; else a quarter of the terrain's smaller side)
  --sample-every S    /proc sampling period (default 10)
  --modbus-hz HZ      mbpoll polling rate, 0 = no Modbus (default 10)
  --warmup S          seconds excluded from the growth figures (default 60)
  --port P            ports P (CIGI in), P+1 (CIGI replies), P+2 (Modbus) (default 47500)
EOF
}
[ $# -ge 2 ] || { usage; exit 2; }
build=$(cd "$1" && pwd); out=$2; shift 2
duration=3600 terrain=big budget=64 size=320x240 hot=100 los=10 spread=5000 rate=60 speed=250 radius=""
every=10 modbus_hz=10 warmup=60 port=47500
report_args=()
while [ $# -gt 0 ]; do
  case $1 in
    --duration) duration=$2; shift 2 ;;
    --terrain) terrain=$2; shift 2 ;;
    --budget-mb) budget=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --hot) hot=$2; shift 2 ;;
    --los) los=$2; shift 2 ;;
    --spread) spread=$2; shift 2 ;;
    --rate) rate=$2; shift 2 ;;
    --speed) speed=$2; shift 2 ;;
    --radius) radius=$2; shift 2 ;;
    --sample-every) every=$2; shift 2 ;;
    --modbus-hz) modbus_hz=$2; shift 2 ;;
    --warmup) warmup=$2; shift 2 ;;
    --port) port=$2; shift 2 ;;
    --) shift; report_args=("$@"); break ;;
    -h|--help) usage; exit 0 ;;
    *) echo "soak.sh: unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
done
ig="$build/bin/ig" host="$build/bin/cigi_query_host"
src=$(cd "$here/../.." && pwd)
rm -rf "$out" && mkdir -p "$out"
out=$(cd "$out" && pwd)

# The scenario: terrain and render settings; its path's one key is what the
# IG shows until the host's first datagram. Circle: LAT,LON,RADIUS for the host.
circle=""
case $terrain in
  big)
    [ -n "${IG_DEM_DIR:-}" ] || { echo "soak.sh: --terrain big needs IG_DEM_DIR (the shared DEMs)" >&2; exit 2; }
    sierra="$IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif"
    python3 "$here/make_copies_vrt.py" "$ig" "$sierra" 5 "$out/sierra_5x5.vrt"
    circle=$(python3 - "$ig" "$sierra" "$out/scenario.json" "$out/sierra_5x5.vrt" "$budget" "${radius:-150000}" <<'PY'
import json, math, subprocess, sys
ig, sierra, scenario, vrt, budget, radius = sys.argv[1:5] + [int(sys.argv[5]), float(sys.argv[6])]
b = json.loads(subprocess.run([ig, "info", sierra], check=True, capture_output=True, text=True).stdout)["bounds"]
# make_copies_vrt.py: the mosaic's north-west corner is the file's, copies
# step one sample less than the file east and south. The corner where
# copies (1,1), (2,1), (1,2), (2,2) meet, nearest the middle of the 5 x 5:
w = 4097
lat = b["north"] - 2 * (b["north"] - b["south"]) * (w - 1) / w
lon = b["west"] + 2 * (b["east"] - b["west"]) * (w - 1) / w
# The IG's first pose (until the host's first datagram) is the circle's
# centre: the tiles it loads before its first frame are not those of the
# flight, so the host's flight pages from its start.
start = [lat, lon, 300]
json.dump({"name": "soak_sierra_5x5",
           "terrain": {"file": vrt, "memory_budget_mb": budget},
           "render": {"width": 640, "height": 480, "fov_y_deg": 60},
           "path": {"frame": "geodetic", "altitude": "agl",
                    "keys": [{"t": 0, "position": start, "hpr": [90, -3, 0]},
                             {"t": 1, "position": start, "hpr": [90, -3, 0]}]},
           "time": {"step_s": 0.1, "duration_s": 1}}, open(scenario, "w"), indent=1)
print("%.6f,%.6f,%.0f" % (lat, lon, radius))
PY
)
    ;;
  *)
    file=$terrain
    [ "$terrain" = default ] && file="$src/scenarios/default.json"
    python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s.pop("capture", None); json.dump(s, open(sys.argv[2], "w"), indent=1)' \
      "$file" "$out/scenario.json"
    ;;
esac

host_args=(--soak "$hot" "$los" --duration "$duration" --rate "$rate" --spread "$spread" --speed "$speed")
if [ -n "$circle" ]; then host_args+=(--circle "$circle"); elif [ -n "$radius" ]; then host_args+=(--radius "$radius"); fi
serve_args=(serve --config "$out/scenario.json" --headless --cigi "127.0.0.1:$port" --cigi-reply "127.0.0.1:$((port + 1))"
  --size "$size" --out "$out/serve" --quiet)
[ "$modbus_hz" != 0 ] && serve_args+=(--modbus "127.0.0.1:$((port + 2))")
commit=$(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git -C "$src" status --porcelain --untracked-files=no 2>/dev/null | head -1)
python3 - "$out/run.json" "$commit${dirty:+ (uncommitted changes)}" "$duration" "$terrain" "$budget" "$size" "$hot" "$los" \
  "$spread" "$rate" "$speed" "$circle" "$every" "$modbus_hz" "$warmup" "$(cut -d' ' -f1-3 /proc/loadavg)" \
  "$ig ${serve_args[*]}" "$host $out/scenario.json 127.0.0.1:$port 127.0.0.1:$((port + 1)) ${host_args[*]}" <<'PY'
import json, sys
keys = ["commit", "duration_s", "terrain", "budget_mb", "size", "hot", "los", "spread_m", "rate_hz", "speed_mps",
        "circle", "sample_every_s", "modbus_hz", "warmup_s", "loadavg_start", "serve_command", "host_command"]
json.dump(dict(zip(keys, sys.argv[2:])), open(sys.argv[1], "w"), indent=1)
PY

cleanup() {  # on any early exit: stop what was started (by process id)
  for p in ${mbpoll_pid:-} ${host_pid:-} ${guard_pid:-} ${serve_pid:-} ${sampler_pid:-}; do kill "$p" 2>/dev/null || true; done
}
trap cleanup EXIT

"$ig" "${serve_args[@]}" > "$out/serve.log" 2>&1 &
serve_pid=$!
python3 "$here/soak_report.py" sample "$serve_pid" "$out/samples.csv" --every "$every" &
sampler_pid=$!
mkfifo "$out/host.fifo"
"$host" "$out/scenario.json" "127.0.0.1:$port" "127.0.0.1:$((port + 1))" "${host_args[@]}" > "$out/host.fifo" 2>&1 &
host_pid=$!
# The host waits for the IG's first Start Of Frame; if ig serve dies first, stop the host.
( tail --pid="$serve_pid" -f /dev/null; kill "$host_pid" 2>/dev/null ) &
guard_pid=$!
exec 3< "$out/host.fifo"
if ! IFS= read -r first <&3; then
  wait "$serve_pid" && rc=0 || rc=$?
  echo "FAIL: ig serve or the host stopped before the first frame (ig serve exit status $rc)"; cat "$out/serve.log"
  exit 1
fi
echo "$first" | tee "$out/host.log"
# The IG has rendered a frame, so its Modbus server is listening: one client from now on.
if [ "$modbus_hz" != 0 ]; then
  stdbuf -oL mbpoll -m tcp -p "$((port + 2))" -a 1 -0 -t 3 -r 0 -c 37 -l "$((1000 / modbus_hz))" -o 1 127.0.0.1 \
    > "$out/mbpoll.log" 2>&1 &
  mbpoll_pid=$!
fi
tee -a "$out/host.log" <&3
exec 3<&-
wait "$host_pid" && host_rc=0 || host_rc=$?
host_pid=""
if [ -n "${mbpoll_pid:-}" ]; then
  kill -INT "$mbpoll_pid" 2>/dev/null || echo "FAIL: mbpoll had stopped before the end of the flight"
  wait "$mbpoll_pid" || true  # mbpoll exits 1 on SIGINT, after its poll statistics
  mbpoll_pid=""
fi
kill -TERM "$serve_pid" 2>/dev/null || true
wait "$serve_pid" && serve_rc=0 || serve_rc=$?
serve_pid=""
kill "$sampler_pid" 2>/dev/null || true
wait "$sampler_pid" 2>/dev/null || true
sampler_pid=""
wait "$guard_pid" 2>/dev/null || true
guard_pid=""
python3 - "$out/run.json" "$serve_rc" "$host_rc" "$(cut -d' ' -f1-3 /proc/loadavg)" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
r.update(serve_rc=int(sys.argv[2]), host_rc=int(sys.argv[3]), loadavg_end=sys.argv[4])
json.dump(r, open(sys.argv[1], "w"), indent=1)
PY
cat "$out/serve.log"
python3 "$here/soak_report.py" report "$out" --warmup "$warmup" "${report_args[@]}"
