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
#    window's uploads show in upload_bytes; the picture's difference from the one-texture render
#    is printed (beyond the window and where minified, the overview is read
#    instead of the full image's mipmaps);
#  * top_down_paged / flight_paged: the same with terrain.imagery_budget_mb
#    1, so the imagery's tile cache is at the least the window needs (12 MB,
#    under the image's 17 MB);
#  * every windowed run: summary.json's paging.imagery within its budget, no
#    frame waited on an imagery tile (moves are held instead), frames.csv
#    has the imagery paging columns;
#  * every case whose DEM fits: a baseline method (roam) drapes the
#    imagery's overview instead of being refused;
#  * bad: imagery 20 degrees east of the DEM is refused with the clear error.
# Two roles, like height_window.cmake.

include(${CMAKE_CURRENT_LIST_DIR}/lib/dem_script.cmake)

if(CMAKE_SCRIPT_MODE_FILE)
  begin_dem_script(imagery-window)
  set(DEM "$ENV{IG_DEM_DIR}/mt_fuji_90m.tif")
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
  if(CASE STREQUAL "bad")
    file(WRITE "${OUT}/bad.json" "{\"name\": \"bad\", \"terrain\": {\"file\": \"${DEM}\", \"texture_limit\": ${limit}},
  \"render\": {\"width\": 160, \"height\": 120, \"imagery\": \"${OUT}/ortho.tif\"},
  \"path\": {\"frame\": \"geodetic\", \"altitude\": \"agl\", \"keys\": [${keys}]}, \"time\": {\"step_s\": 0.5, \"duration_s\": 2}}\n")
    execute_process(COMMAND "${IG}" run "${OUT}/bad.json" --out "${OUT}/run_bad" --headless --quiet
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("bad imagery: exit ${rc}: ${err}")
    if(rc EQUAL 0 OR NOT err MATCHES "ortho.tif: imagery does not overlap the DEM")
      message(FATAL_ERROR "imagery off the DEM must be refused naming the file and the reason")
    endif()
    return()
  endif()
  include(${CMAKE_CURRENT_LIST_DIR}/lib/window_runs.cmake)
  # paged: the imagery cache at its least (imagery_budget_mb 1 is raised to
  # what the 1201-pixel window needs with a tile of margin, 12 MB: less than
  # the 2402^2 image's 17 MB).
  set(budget "")
  if(CASE MATCHES "_paged$")
    set(budget ", \"imagery_budget_mb\": 1")
  endif()
  foreach(l 0 ${limit})
    set(extra "")
    if(l GREATER 0)
      set(extra ", \"texture_limit\": ${l}${budget}")
    endif()
    run_window_scenario(l${l} "\"file\": \"${DEM}\"${extra}" ", \"imagery\": \"${OUT}/ortho.tif\"" "${keys}")
  endforeach()
  # Paged imagery: summary.json's paging.imagery and frames.csv's imagery
  # columns; no frame waited on an imagery tile (moves are held instead).
  file(READ "${OUT}/run_l${limit}/summary.json" summary)
  string(JSON peak GET "${summary}" paging imagery peak_resident_mb)
  string(JSON budget_mb GET "${summary}" paging imagery budget_mb)
  string(JSON waited GET "${summary}" paging imagery frames_waited_on_io)
  string(JSON held GET "${summary}" paging imagery held_moves)
  message("${CASE}: imagery cache peak ${peak} of ${budget_mb} MB, held moves ${held}, frames waited ${waited}")
  if(NOT waited EQUAL 0)
    message(FATAL_ERROR "${waited} frames waited on an imagery tile")
  endif()
  if(peak GREATER budget_mb)
    message(FATAL_ERROR "the imagery cache held ${peak} MB, over its ${budget_mb} MB budget")
  endif()
  if(CASE MATCHES "_paged$" AND budget_mb GREATER 20)
    message(FATAL_ERROR "imagery_budget_mb 1 gave a ${budget_mb} MB cache, not the window's least")
  endif()
  include(${CMAKE_CURRENT_LIST_DIR}/lib/frames_csv.cmake)
  expect_frames_columns("${OUT}/run_l${limit}/frames.csv" "imagery_held,imagery_missing,imagery_page_ins,imagery_page_waits"
    "a paged-imagery run")
  execute_process(COMMAND "${TOOL}" diff "${OUT}/run_l0/final.png" "${OUT}/run_l${limit}/final.png" OUTPUT_VARIABLE d)
  string(STRIP "${d}" d)
  message("${CASE}: window render vs one texture: ${d}")
  # The other methods drape the overview (no window) where they can draw
  # the DEM (not beyond its own limit, top_down_overview): roam runs. Its
  # picture differs from roam's with the one-texture imagery by the
  # overview's blur (printed; the test image's stripes are about one
  # overview pixel wide, so most pixels differ: not asserted).
  if(CASE STREQUAL "top_down_overview")
    set(roam_limits "")
  else()
    set(roam_limits 0 ${limit})
  endif()
  foreach(l ${roam_limits})
    execute_process(COMMAND "${IG}" run "${OUT}/l${l}.json" --out "${OUT}/run_roam_l${l}" --headless --quiet
      --method roam RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "roam with imagery (texture limit ${l}) must drape it: exit ${rc}\n${out}\n${err}")
    endif()
  endforeach()
  if(roam_limits)
    execute_process(COMMAND "${TOOL}" diff "${OUT}/run_roam_l0/final.png" "${OUT}/run_roam_l${limit}/final.png"
      OUTPUT_VARIABLE droam)
    string(STRIP "${droam}" droam)
    message("${CASE}: roam, overview vs one texture: ${droam}")
  endif()
  if(CASE MATCHES "^top_down")
    if(NOT d MATCHES "^max [01] ")
      message(FATAL_ERROR "inside the window the picture must equal the one-texture render within 1 step: ${d}")
    endif()
    return()
  endif()
  # flight: the window moved: frames after the first upload more than
  # without it (the imagery window's new rows and columns).
  sum_frames_column("${OUT}/run_l0/frames.csv" upload_bytes 1 up0)
  sum_frames_column("${OUT}/run_l1201/frames.csv" upload_bytes 1 up1201)
  message("flight: upload_bytes after the first frame: ${up0} one texture, ${up1201} with the window")
  if(NOT up1201 GREATER up0)
    message(FATAL_ERROR "the imagery window did not move (no more uploads after the first frame)")
  endif()
  return()
endif()

add_dem_script_tests(cli.imagery_window imagery_window ${CMAKE_CURRENT_LIST_FILE} "-DTOOL=$<TARGET_FILE:imagery_tool>"
  top_down top_down_overview top_down_paged flight flight_paged bad)
