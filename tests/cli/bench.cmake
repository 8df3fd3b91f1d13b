# ig bench end to end (docs/bench.md) on a tiny generated terrain: the
# outputs are well formed (tests/tools/check_bench_output.py), bad arguments
# exit 2 with a clear message. The checker runs last: its "ok" line is what
# passes the test (set -e stops before it on any earlier failure).
set(IG_TEST_OUT ${CMAKE_BINARY_DIR}/test-out)
set(IG_BENCH_TINY ${CMAKE_SOURCE_DIR}/tests/tools/bench_tiny_scenario.json)
set(IG_BENCH_CHECK ${CMAKE_SOURCE_DIR}/tests/tools/check_bench_output.py)

# Default knobs: one row per method, 8 frames (the whole tiny flight), 5 sampled
# (positions 0, 2, 4, 5, 7: four of them have a frame before them, the
# temporal error's pairs).
add_test(NAME cli.bench.default_knobs
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/bench_default'
    '$<TARGET_FILE:ig>' bench '${IG_BENCH_TINY}' --methods twolevel,reference --error-samples 5 --out '${IG_TEST_OUT}/bench_default'
    python3 '${IG_BENCH_CHECK}' '${IG_TEST_OUT}/bench_default' --rows 2 --frames 8 --samples 5 --pairs 4 --methods twolevel,reference")
set_tests_properties(cli.bench.default_knobs PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "check_bench_output: ok"
  FIXTURES_SETUP bench_default_run)

# --sweep: one row per knob value of each method's knob_sweep (plus its
# default when the sweep lacks it); --frames subsamples, --size / --fov override.
# Every one of the 6 frames is sampled: 5 have a frame before them.
add_test(NAME cli.bench.sweep
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/bench_sweep'
    '$<TARGET_FILE:ig>' bench '${IG_BENCH_TINY}' --methods twolevel,reference --sweep --frames 6 --size 128x96 --fov 30 --out '${IG_TEST_OUT}/bench_sweep'
    rows=$(( $(wc -l < '${IG_TEST_OUT}/bench_sweep/results.csv') - 1 ))
    test $rows -ge 3
    grep -q 'image: 128x96, vertical FOV 30 deg' '${IG_TEST_OUT}/bench_sweep/results.md'
    grep -q '^twolevel,level0_budget,.*,1,' '${IG_TEST_OUT}/bench_sweep/results.csv'
    python3 '${IG_BENCH_CHECK}' '${IG_TEST_OUT}/bench_sweep' --rows $rows --frames 6 --samples 6 --pairs 5 --methods twolevel,reference --order sequential")
set_tests_properties(cli.bench.sweep PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "check_bench_output: ok"
  FIXTURES_SETUP bench_sweep_run)

# --interleave: the same sweep flown frame by frame in turn (frames.csv in
# that order) gives the same rows and, frame for frame, the same image and
# temporal errors (only the timing may differ); results.md says how the
# frames were flown.
add_test(NAME cli.bench.interleave
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/bench_interleave'
    '$<TARGET_FILE:ig>' bench '${IG_BENCH_TINY}' --methods twolevel,reference --sweep --frames 6 --size 128x96 --fov 30 --interleave --out '${IG_TEST_OUT}/bench_interleave'
    grep -q 'interleaved (each frame flown by every method and knob in turn' '${IG_TEST_OUT}/bench_interleave/results.md'
    grep -q 'one method and knob after the other' '${IG_TEST_OUT}/bench_sweep/results.md'
    rows=$(( $(wc -l < '${IG_TEST_OUT}/bench_sweep/results.csv') - 1 ))
    python3 '${IG_BENCH_CHECK}' '${IG_TEST_OUT}/bench_interleave' --rows $rows --frames 6 --samples 6 --pairs 5 --methods twolevel,reference --order interleaved --same-errors-as '${IG_TEST_OUT}/bench_sweep'")
set_tests_properties(cli.bench.interleave PROPERTIES LABELS cli FIXTURES_REQUIRED bench_sweep_run
  PASS_REGULAR_EXPRESSION "check_bench_output: ok")

# --pipelined: every frame flown again with frames in flight, in stretches
# of 10 taken in turn (frames_pipelined.csv, the pipelined tables); the
# finished frames' images and errors are those of a run without it.
add_test(NAME cli.bench.pipelined
  COMMAND bash -c "set -e; rm -rf '${IG_TEST_OUT}/bench_pipelined'
    '$<TARGET_FILE:ig>' bench '${IG_BENCH_TINY}' --methods twolevel,reference --error-samples 5 --interleave --pipelined --out '${IG_TEST_OUT}/bench_pipelined'
    python3 '${IG_BENCH_CHECK}' '${IG_TEST_OUT}/bench_pipelined' --rows 2 --frames 8 --samples 5 --pairs 4 --methods twolevel,reference --pipelined --same-errors-as '${IG_TEST_OUT}/bench_default'")
set_tests_properties(cli.bench.pipelined PROPERTIES LABELS cli FIXTURES_REQUIRED bench_default_run
  PASS_REGULAR_EXPRESSION "check_bench_output: ok")

# Every registered method on a real DEM (skips without IG_DEM_DIR): a short
# flight over Mt Rainier, 6 frames 0.2 s apart, 3 sampled (positions 1, 3, 5,
# each with a frame before it). Every row's temporal error is finite and
# non-negative, the reference's 0, and results.csv agrees with samples.csv.
ig_real_dem_test(cli.bench.all_methods_real_dem "real-DEM bench"
  "set -e; rm -rf '${IG_TEST_OUT}/bench_rainier'
    '$<TARGET_FILE:ig>' bench '${CMAKE_SOURCE_DIR}/tests/tools/bench_rainier_scenario.json' --methods all --error-samples 3 --out '${IG_TEST_OUT}/bench_rainier'
    rows=$(( $(wc -l < '${IG_TEST_OUT}/bench_rainier/results.csv') - 1 ))
    test $rows -ge 2
    python3 '${IG_BENCH_CHECK}' '${IG_TEST_OUT}/bench_rainier' --rows $rows --frames 6 --samples 3 --pairs 3 --methods all")

set(_bench "'$<TARGET_FILE:ig>' bench")
ig_cli_failure_test(cli.bench.unknown_method "unknown method 'nope' \\(available: .*exit=2"
  "${_bench} '${IG_BENCH_TINY}' --methods twolevel,nope --out '${IG_TEST_OUT}/bench_nope'")
ig_cli_failure_test(cli.bench.bad_size "--size: expected WxH, got '640by480'.*exit=2"
  "${_bench} '${IG_BENCH_TINY}' --size 640by480 --out '${IG_TEST_OUT}/bench_badsize'")
ig_cli_failure_test(cli.bench.bad_fov "--fov: must be in \\(0, 179\\] degrees.*exit=2"
  "${_bench} '${IG_BENCH_TINY}' --fov 200 --out '${IG_TEST_OUT}/bench_badfov'")
ig_cli_failure_test(cli.bench.missing_scenario "/nonexistent/scn.json.*exit=1"
  "${_bench} /nonexistent/scn.json --out '${IG_TEST_OUT}/bench_missing'")
