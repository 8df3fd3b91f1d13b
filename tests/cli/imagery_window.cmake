# Imagery beyond one texture (issue 16) on the Fuji DEM (1201²), made small:
# imagery 2x finer than the DEM (2402², made at test time by imagery_tool)
# with terrain.texture_limit 1201, so the heights still fit one texture and
# the imagery does not: an overview (every 2 x 2 pixels' mean) everywhere
# and full resolution in a 1201-pixel wrap-around window on Level1
# (render/imagery_window_texture.h).
#  * top_down: looking down from 1500 m, every imagery pixel magnified and
#    inside the window: final.png within 1 colour step of the one-texture
#    render (the same image without the limit) - the window is read at
#    level 0 where the whole texture is too (shaders/terrain_shading.frag
#    imagery_at), but at texel coordinate p / 1201 instead of p / 2402, whose
#    float rounding moves llvmpipe's 8-bit bilinear weights by one step on
#    some pixels (104 of 19200 when written); the overview, a 2 x 2 mean of a
#    pixel-level pattern, would differ by far more;
#  * top_down_overview: the same with texture_limit 601, so the heights are
#    an overview too (step 2, height window 601) and the imagery's step is 4
#    with a partial last block: still within 1 step;
#  * flight: an oblique low flight that moves the window renders, the
#    window's uploads show in upload_bytes, a baseline method is refused
#    naming the limit; the picture's difference from the one-texture render
#    is printed (beyond the window and where minified, the overview is read
#    instead of the full image's mipmaps);
#  * bad: imagery 20 degrees east of the DEM is refused with the clear error.
# Two roles, like height_window.cmake.

if(CMAKE_SCRIPT_MODE_FILE)
  if("$ENV{IG_DEM_DIR}" STREQUAL "")
    message("IG_DEM_DIR not set: imagery-window test skipped")
    cmake_language(EXIT 77)
  endif()
  set(DEM "$ENV{IG_DEM_DIR}/mt_fuji_90m.tif")
  file(REMOVE_RECURSE "${OUT}")
  file(MAKE_DIRECTORY "${OUT}")
  set(offset 0)
  if(CASE STREQUAL "bad")
    set(offset 20)
  endif()
  execute_process(COMMAND "${TOOL}" make "${DEM}" "${OUT}/ortho.tif" 2 ${offset} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "imagery_tool make: ${err}")
  endif()
  set(limit 1201)
  if(CASE STREQUAL "top_down_overview")
    set(limit 601)
  endif()
  if(CASE MATCHES "^top_down")
    set(keys "{\"t\": 0, \"position\": [35.40, 138.65, 1500], \"hpr\": [20, -80, 0]},
    {\"t\": 1, \"position\": [35.401, 138.652, 1500], \"hpr\": [20, -80, 0]}")
  else()
    set(keys "{\"t\": 0, \"position\": [35.30, 138.60, 200], \"hpr\": [60, -6, 0]},
    {\"t\": 2, \"position\": [35.32, 138.66, 150], \"hpr\": [65, -4, -8]}")
  endif()
  foreach(l 0 ${limit})
    set(extra "")
    if(l GREATER 0)
      set(extra ", \"texture_limit\": ${l}")
    endif()
    file(WRITE "${OUT}/l${l}.json" "{\"name\": \"imagery_${l}\",
  \"terrain\": {\"file\": \"${DEM}\"${extra}},
  \"render\": {\"width\": 160, \"height\": 120, \"fov_y_deg\": 45, \"imagery\": \"${OUT}/ortho.tif\"},
  \"path\": {\"frame\": \"geodetic\", \"altitude\": \"agl\", \"keys\": [
    ${keys}]},
  \"time\": {\"step_s\": 0.5, \"duration_s\": 2}}\n")
    execute_process(COMMAND "${IG}" run "${OUT}/l${l}.json" --out "${OUT}/run_${l}" --headless --quiet
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(CASE STREQUAL "bad")
      message("bad imagery: exit ${rc}: ${err}")
      if(rc EQUAL 0 OR NOT err MATCHES "ortho.tif: imagery does not overlap the DEM")
        message(FATAL_ERROR "imagery off the DEM must be refused naming the file and the reason")
      endif()
      continue()
    endif()
    if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/run_${l}/final.png")
      message(FATAL_ERROR "ig run with texture_limit ${l}: exit ${rc}\n${out}\n${err}")
    endif()
  endforeach()
  if(CASE STREQUAL "bad")
    return()
  endif()
  execute_process(COMMAND "${TOOL}" diff "${OUT}/run_0/final.png" "${OUT}/run_${limit}/final.png" OUTPUT_VARIABLE d)
  string(STRIP "${d}" d)
  message("${CASE}: window render vs one texture: ${d}")
  if(CASE MATCHES "^top_down")
    if(NOT d MATCHES "^max [01] ")
      message(FATAL_ERROR "inside the window the picture must equal the one-texture render within 1 step: ${d}")
    endif()
    return()
  endif()
  # flight: the window moved: frames after the first upload more than
  # without it (the imagery window's new rows and columns).
  include(${CMAKE_CURRENT_LIST_DIR}/lib/frames_csv.cmake)
  sum_frames_column("${OUT}/run_0/frames.csv" upload_bytes 1 up0)
  sum_frames_column("${OUT}/run_1201/frames.csv" upload_bytes 1 up1201)
  message("flight: upload_bytes after the first frame: ${up0} one texture, ${up1201} with the window")
  if(NOT up1201 GREATER up0)
    message(FATAL_ERROR "the imagery window did not move (no more uploads after the first frame)")
  endif()
  execute_process(COMMAND "${IG}" run "${OUT}/l1201.json" --out "${OUT}/run_roam" --headless --quiet --method roam
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  message("ig run --method roam: exit ${rc}: ${err}")
  if(rc EQUAL 0 OR NOT err MATCHES "method 'roam' cannot drape the imagery .*texture limit 1201")
    message(FATAL_ERROR "roam with imagery beyond the limit must be refused naming the method and the limit")
  endif()
  return()
endif()

foreach(case top_down top_down_overview flight bad)
  add_test(NAME cli.imagery_window.${case}
    COMMAND ${CMAKE_COMMAND} -DIG=$<TARGET_FILE:ig> -DTOOL=$<TARGET_FILE:imagery_tool>
      -DOUT=${CMAKE_BINARY_DIR}/test-out/imagery_window_${case} -DCASE=${case} -P ${CMAKE_CURRENT_LIST_FILE})
  set_tests_properties(cli.imagery_window.${case} PROPERTIES LABELS cli SKIP_RETURN_CODE 77)
endforeach()
