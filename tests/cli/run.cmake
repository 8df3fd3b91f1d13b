# ig run end to end: the outputs a user looks at, headless and windowed.
set(IG_TEST_OUT ${CMAKE_BINARY_DIR}/test-out)

add_test(NAME cli.run.default_outputs
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/run_default'
    '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --frames 6 --size 320x240 --out '${IG_TEST_OUT}/run_default' --quiet
    cd '${IG_TEST_OUT}/run_default'
    test -s frames.csv && test -s summary.json && test -s final.png && test -s frametime.png
    test \"$(ls capture_main_*.png | wc -l)\" -ge 1
    test \"$(wc -l < frames.csv)\" -eq 7
    head -1 frames.csv | grep -q '^frame,channel,sim_time_s,wall_ms,'
    grep -q '\"gl_renderer\"' summary.json && grep -q '\"median_ms\"' summary.json
    echo outputs ok")
set_tests_properties(cli.run.default_outputs PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "outputs ok")

# The windowed path (GLFW) under a virtual X server.
add_test(NAME cli.run.window_under_xvfb
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/run_window'
    xvfb-run -a -s '-screen 0 640x480x24' '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --window --vsync off --frames 3 --size 320x240 --out '${IG_TEST_OUT}/run_window' --quiet
    grep -q '\"headless\": false' '${IG_TEST_OUT}/run_window/summary.json'
    test -s '${IG_TEST_OUT}/run_window/final.png'
    echo window ok")
set_tests_properties(cli.run.window_under_xvfb PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "window ok")

ig_cli_failure_test(cli.run.missing_scenario "/nonexistent/scn.json.*exit=[1-9]"
  "'$<TARGET_FILE:ig>' run /nonexistent/scn.json")
ig_cli_failure_test(cli.run.unknown_method "unknown method 'nope'.*exit=[1-9]"
  "'$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --method nope --frames 1 --out '${IG_TEST_OUT}/run_nope'")

# The Sierra Nevada flight on the real 4097^2 DEM (skips without IG_DEM_DIR).
ig_real_dem_test(cli.run.sierra_real_dem "real-DEM run"
  "set -e; rm -rf '${IG_TEST_OUT}/run_sierra'
    '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/sierra_owens_valley.json' --frames 2 --size 320x240 --out '${IG_TEST_OUT}/run_sierra' --quiet
    grep -q '\"width\": 4097' '${IG_TEST_OUT}/run_sierra/summary.json'
    test -s '${IG_TEST_OUT}/run_sierra/final.png'
    echo sierra ok")

# --pass-times: every pass the frame ran gets its own wall time in frames.csv
# (<pass>_pass_ms), the passes lie within their stages, and summary.json and
# the closing line give the medians.
add_test(NAME cli.run.pass_times
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/run_pass_times'
    '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --frames 4 --size 320x240 --pass-times --quiet --out '${IG_TEST_OUT}/run_pass_times' > '${IG_TEST_OUT}/run_pass_times.log'
    grep -q 'median ms per pass, each finished before the next (--pass-times): level1 [0-9.]*, level0 ' '${IG_TEST_OUT}/run_pass_times.log'
    python3 - '${IG_TEST_OUT}/run_pass_times' <<'PY'
import csv, json, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(out + '/frames.csv')))
assert len(rows) == 4, len(rows)
timed = [c[:-len('_pass_ms')] for c in rows[0] if c.endswith('_pass_ms')]
drawn = set(p for r in rows for p in r['passes'].split('+'))
assert drawn <= set(timed) and 'sky' in timed and 'aa' in timed, (timed, drawn)
for r in rows:
    ms = {p: float(r[p + '_pass_ms']) for p in timed}
    assert all(v >= 0 for v in ms.values()), ms
    terrain = sum(v for p, v in ms.items() if p not in ('sky', 'aa'))
    assert 0 < terrain <= float(r['terrain_ms']), (terrain, r['terrain_ms'])
    assert ms['sky'] <= float(r['sky_ms']), (ms['sky'], r['sky_ms'])
    assert ms['aa'] <= float(r['resolve_ms']), (ms['aa'], r['resolve_ms'])
summary = json.load(open(out + '/summary.json'))
assert set(summary['pass_ms_median']) == set(timed), (summary['pass_ms_median'], timed)
print('pass times ok')
PY")
set_tests_properties(cli.run.pass_times PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "pass times ok")

# Scripted entities (docs/entities.md): 16 entities on the default flight;
# every frame has the entity pass, and two runs are pixel-identical.
add_test(NAME cli.run.scripted_entities
  COMMAND bash -c "set -e; out='${IG_TEST_OUT}/run_entities'; rm -rf \"$out\"; mkdir -p \"$out\"
    python3 '${CMAKE_SOURCE_DIR}/tools/bench/entity_traffic.py' '${CMAKE_SOURCE_DIR}/scenarios/default.json' 16 \"$out/traffic.json\"
    for k in 1 2; do '$<TARGET_FILE:ig>' run \"$out/traffic.json\" --frames 20 --size 320x240 --out \"$out/run$k\" --quiet; done
    cmp \"$out/run1/final.png\" \"$out/run2/final.png\"
    python3 -c \"import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); d=[int(x['entities_draws']) for x in r]; print('frames', len(r), 'entity draws per frame', min(d), '..', max(d)); sys.exit(0 if min(d) > 0 else 1)\" \"$out/run1/frames.csv\"
    echo scripted entities ok")
set_tests_properties(cli.run.scripted_entities PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "scripted entities ok")
