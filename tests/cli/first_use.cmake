# What a new user meets first: a picture with no terrain says why, capture
# schedules, --frames and its captures, a missing file named as missing, and
# --help describing every option. Scenarios: tests/cli/scenarios/.
set(IG_FIRST_OUT ${CMAKE_BINARY_DIR}/test-out/first_use)
set(IG_FIRST_SCN ${CMAKE_SOURCE_DIR}/tests/cli/scenarios)
# summary.json's value at a dotted key path, for the tests' bash lines.
set(IG_JSON_GET "python3 -c \"import functools,json,sys; print(functools.reduce(lambda v, k: v[k], sys.argv[2].split('.'), json.load(open(sys.argv[1]))))\"")

# Runs `ig run` on tests/cli/scenarios/<name>.json into OUT/<test> (stderr in
# OUT/<test>.err; one folder per test, as tests sharing a scenario may run at
# once) and then the bash `checks`; passes on "<name> ok".
function(ig_first_use_run_test test name args checks)
  add_test(NAME ${test} COMMAND bash -c "set -e; o='${IG_FIRST_OUT}/${test}'; mkdir -p '${IG_FIRST_OUT}'; rm -rf \"$o\" \"$o.err\"
    '$<TARGET_FILE:ig>' run '${IG_FIRST_SCN}/${name}.json' --out \"$o\" --quiet ${args} 2> \"$o.err\" || { cat \"$o.err\"; exit 1; }
    cat \"$o.err\"; get() { ${IG_JSON_GET} \"$o/summary.json\" \"$1\"; }
    ${checks}
    echo '${name} ok'")
  set_tests_properties(${test} PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "${name} ok")
endfunction()

# A geodetic path with the longitude's sign wrong (7.9 W for 7.9 E) lands
# 1213 km west of the terrain: every frame counted, one warning naming the
# frame, the local position and the latitude / longitude.
ig_first_use_run_test(cli.run.pose_off_terrain_is_counted_and_named off_terrain ""
  "test \"$(get frames_outside_terrain)\" = 4; test \"$(get frames_below_terrain)\" = 0
    test \"$(grep -c warning \"$o.err\")\" = 1
    grep -q 'ig run: warning: frame 0 (t 0.000 s): the eye at local x -1212[0-9]* m, y [0-9]* m, z 1500 m (lat 46.51000, lon -7.90000) is 1213 km outside the terrain' \"$o.err\"")

# Over the terrain, looking 50..90 degrees up: no terrain in any view.
ig_first_use_run_test(cli.run.sky_only_view_is_counted sky_only ""
  "test \"$(get frames_outside_terrain)\" = 4
    grep -q 'frame 0 (t 0.000 s): the eye at local x 3840 m, y 3840 m, z 3000 m looks where there is no terrain' \"$o.err\"")

# An AGL altitude of -20 m: the eye is under the ground in every frame.
ig_first_use_run_test(cli.run.eye_below_terrain_is_counted under_terrain ""
  "test \"$(get frames_below_terrain)\" = 4; test \"$(get frames_outside_terrain)\" = 0
    test \"$(grep -c warning \"$o.err\")\" = 1
    grep -q 'frame 0 (t 0.000 s): the eye at local x 3840 m, y 3840 m, z [0-9]* m is 20.0 m below the terrain surface' \"$o.err\"")

# capture.every_s 0.5 and times_s [0.7] over 2 s at 0.1 s steps: frames 0,
# 5, 7, 10, 15 and 20, nothing else, and no warning.
ig_first_use_run_test(cli.run.capture_every_s capture_every ""
  "test \"$(cd \"$o\" && ls capture_*.png | tr '\\n' ' ')\" = 'capture_main_t000.000s_f000000.png capture_main_t000.500s_f000005.png capture_main_t000.700s_f000007.png capture_main_t001.000s_f000010.png capture_main_t001.500s_f000015.png capture_main_t002.000s_f000020.png '
    test \"$(get frames_outside_terrain)\" = 0; ! grep -q warning \"$o.err\"")

# --frames 6 renders frames 0..5: the captures at 0 and 0.5 s are saved, the
# four later ones are named in one warning.
ig_first_use_run_test(cli.run.frames_names_the_captures_it_skips capture_every "--frames 6"
  "test \"$(ls \"$o\"/capture_*.png | wc -l)\" = 2; test \"$(get frames_rendered)\" = 6
    grep -q 'ig run: warning: --frames 6 renders frames 0..5 (sim time up to 0.5 s of the scenario.s 2 s): capture times 0.7, 1, 1.5, 2 s fall after the last rendered frame and are not saved' \"$o.err\"")

# ig serve honours capture.every_s (seconds since it started): frame 0, and
# at least one later frame in 8 frames paced at 10 a second (0.7 s or more).
# It counts frames outside the terrain as ig run does, also where it always
# reported them (pose_intake).
add_test(NAME cli.serve.capture_every_s_and_outside_terrain COMMAND bash -c "set -e; o='${IG_FIRST_OUT}/serve'; rm -rf \"$o\"; mkdir -p \"$o\"
  '$<TARGET_FILE:ig>' serve --config '${IG_FIRST_SCN}/capture_every.json' --udp 127.0.0.1:0 --frames 8 --rate 10 --out \"$o/every\" --quiet
  test -f \"$o/every/capture_main_t000.0\"*_f000000.png
  test \"$(ls \"$o/every\"/capture_*.png | wc -l)\" -ge 2
  '$<TARGET_FILE:ig>' serve --config '${IG_FIRST_SCN}/off_terrain.json' --udp 127.0.0.1:0 --frames 3 --out \"$o/off\" --quiet 2> \"$o/off.err\"
  cat \"$o/off.err\"; grep -q 'ig serve: warning: frame 0 (t [0-9.]* s): the eye at local x -1212' \"$o/off.err\"
  test \"$(${IG_JSON_GET} \"$o/off/summary.json\" frames_outside_terrain)\" = 3
  test \"$(${IG_JSON_GET} \"$o/off/summary.json\" pose_intake.frames_outside_terrain)\" = 3
  echo 'serve ok'")
set_tests_properties(cli.serve.capture_every_s_and_outside_terrain PROPERTIES LABELS "cli;net" PASS_REGULAR_EXPRESSION "serve ok")

# A file a scenario or the command line names but that is not there.
ig_cli_failure_test(cli.run.missing_imagery_says_no_such_file
  "ig run: [^\n]*/tests/cli/scenarios/textures/no_such_ortho.png: no such file\nexit=1"
  "'$<TARGET_FILE:ig>' run '${IG_FIRST_SCN}/missing_imagery.json' --out '${IG_FIRST_OUT}/missing_imagery' --quiet")
ig_cli_failure_test(cli.run.missing_recording_says_no_such_file "ig run: /nonexistent/flight.igrec: no such file\nexit=1"
  "'$<TARGET_FILE:ig>' run '${IG_FIRST_SCN}/capture_every.json' --recording /nonexistent/flight.igrec --out '${IG_FIRST_OUT}/missing_recording' --quiet")
ig_cli_failure_test(cli.run.missing_dem_says_no_such_file "/nonexistent/dem.tif: no such file\nexit=1"
  "mkdir -p '${IG_FIRST_OUT}' && cd '${IG_FIRST_OUT}' && echo '{\"terrain\": {\"file\": \"/nonexistent/dem.tif\"}, \"path\": {\"keys\": [{\"t\": 0, \"position\": [0, 0, 0]}]}}' > missing_dem.json
   '$<TARGET_FILE:ig>' run missing_dem.json --out '${IG_FIRST_OUT}/missing_dem' --quiet")
ig_cli_failure_test(cli.run.bad_capture_every "capture.every_s: must be >= time.step_s \\(0.1\\)[^\n]*got 0.01\\).*exit=1"
  "mkdir -p '${IG_FIRST_OUT}' && cd '${IG_FIRST_OUT}' && echo '{\"terrain\": {\"generator\": {}}, \"path\": {\"keys\": [{\"t\": 0, \"position\": [0, 0, 0]}]}, \"time\": {\"step_s\": 0.1}, \"capture\": {\"every_s\": 0.01}}' > bad_every.json
   '$<TARGET_FILE:ig>' run bad_every.json --out '${IG_FIRST_OUT}/bad_every' --quiet")

# --help: the synopsis, then every option it names described with a sentence.
foreach(cmd run serve send bench info)
  add_test(NAME cli.help.${cmd}_describes_every_option COMMAND bash -c
    "set -o pipefail; '$<TARGET_FILE:ig>' ${cmd} --help | python3 '${CMAKE_SOURCE_DIR}/tests/tools/check_help.py' 'ig ${cmd}'")
  set_tests_properties(cli.help.${cmd}_describes_every_option PROPERTIES LABELS cli
    PASS_REGULAR_EXPRESSION "help ok" FAIL_REGULAR_EXPRESSION "FAIL")
endforeach()
