#!/usr/bin/env bash
# Renders the default and Table 2 scenarios with two ig binaries and checks
# that every capture PNG is byte-identical and that frames.csv agrees in every
# column that is not a time. For refactors that must not change the picture.
#   tools/check/same_captures.sh OLD_IG NEW_IG OUT_DIR [METHODS]
# METHODS: comma-separated (default: every method); Table 2 runs at 640x512.
set -euo pipefail
old=$1 new=$2 out=$3
methods=${4:-twolevel,reference,roam,geomipmap,chunked,quadtree,cdlod}
here=$(cd "$(dirname "$0")/../.." && pwd)
: "${IG_DEM_DIR:?set IG_DEM_DIR to the folder of the DEMs (../shared/data/dem)}"
status=0
compare() {  # name
  local a=$out/old/$1 b=$out/new/$1 n=0
  for png in "$a"/*.png; do
    [[ $(basename "$png") == frametime.png ]] && continue
    n=$((n + 1))
    if ! cmp -s "$png" "$b/$(basename "$png")"; then echo "DIFFERENT $1/$(basename "$png")"; status=1; fi
  done
  # frames.csv: drop the columns that are times (ms, s, fps, age)
  local keep
  keep=$(head -1 "$a/frames.csv" | tr ',' '\n' | grep -nvE '_ms$|_s$|ms_|fps|age|wall|cpu|time' | cut -d: -f1 | paste -sd,)
  if ! diff -q <(cut -d, -f"$keep" "$a/frames.csv") <(cut -d, -f"$keep" "$b/frames.csv") >/dev/null; then
    echo "DIFFERENT $1/frames.csv (non-time columns)"; status=1
  fi
  echo "$1: $n captures compared"
}
run_both() {  # name scenario args...
  local name=$1 scenario=$2; shift 2
  "$old" run "$scenario" --out "$out/old/$name" --quiet "$@" >/dev/null
  "$new" run "$scenario" --out "$out/new/$name" --quiet "$@" >/dev/null
  compare "$name"
}
run_both default "$here/scenarios/default.json"
IFS=, read -ra list <<< "$methods"
for m in "${list[@]}"; do
  run_both "table2_$m" "$here/scenarios/table2_sierra.json" --method "$m" --size 640x512
done
[[ $status == 0 ]] && echo "all captures byte-identical"
exit $status
