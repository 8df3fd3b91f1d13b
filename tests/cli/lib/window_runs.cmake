# Helpers shared by the window tests (tests/cli/height_window.cmake,
# imagery_window.cmake; script mode, ${IG} set): scenarios that fly the
# two-level method over a DEM at 160 x 120 for 2 s in 0.5 s steps.
# In tests/cli/lib so the tests' glob of tests/cli/*.cmake does not register it.

# Writes OUT/<name>.json with `terrain` (the terrain block's members),
# `render` (extra render members, "" or starting with ", ") and `keys` (the
# geodetic path keys, AGL), runs `ig run` on it into OUT/run_<name> and
# stops the test with ig's output if it fails or leaves no final.png.
function(run_window_scenario name terrain render keys)
  file(WRITE "${OUT}/${name}.json" "{\"name\": \"${name}\",
  \"terrain\": {${terrain}},
  \"render\": {\"width\": 160, \"height\": 120, \"fov_y_deg\": 45, \"antialiasing\": \"off\", \"ground_detail\": false${render}},
  \"path\": {\"frame\": \"geodetic\", \"altitude\": \"agl\", \"keys\": [
    ${keys}]},
  \"time\": {\"step_s\": 0.5, \"duration_s\": 2}}\n")
  execute_process(COMMAND "${IG}" run "${OUT}/${name}.json" --out "${OUT}/run_${name}" --headless --quiet
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/run_${name}/final.png")
    message(FATAL_ERROR "ig run ${name}: exit ${rc}\n${out}\n${err}")
  endif()
endfunction()

# `ig run --method roam` on OUT/<name>.json must fail with a message
# matching `regex` (a method that cannot draw the scene is refused, saying
# why); `what` names the case in the failure.
function(expect_roam_refused name regex what)
  execute_process(COMMAND "${IG}" run "${OUT}/${name}.json" --out "${OUT}/run_roam" --headless --quiet --method roam
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("ig run --method roam (${what}): exit ${rc}: ${err}")
  if(rc EQUAL 0 OR NOT err MATCHES "${regex}")
    message(FATAL_ERROR "roam ${what} must be refused naming the method and why")
  endif()
endfunction()
