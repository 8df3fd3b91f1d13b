# Terrain beyond one texture (issue 16) on the Sierra DEM, made small:
#  * same_picture: the two-level method reading heights through a small
#    wrap-around height window (terrain.height_window,
#    render/height_window_texture.h) renders the same picture as with the
#    whole-DEM texture alone, on a flight that moves the window;
#  * overview: with the texture limit lowered below the DEM
#    (terrain.texture_limit 2049: an overview every 2nd sample, Level0 built
#    on it, full resolution in a 512-sample window) ig run renders, and a
#    baseline method is refused with a message naming it and the limit;
#  * paged / paged_overview: with terrain.memory_budget_mb 16 the heights
#    (64 MB) are paged from the file by the tile cache (terrain/paged_heights.h)
#    and the picture is byte-identical to the whole-array run's (with
#    terrain.wait_for_pages: frames wait for tiles, as a replay for
#    comparison must; live, Level1 would keep its square meanwhile), with a
#    256-sample window (paged) and beyond a texture limit of 2049
#    (paged_overview); frames.csv has page_waits / page_ins and
#    summary.json a "paging" block.
# Two roles, like dem_tiles.cmake:
#  * included by tests/CMakeLists.txt: registers cli.height_window.* (skip without IG_DEM_DIR);
#  * run as `cmake -P height_window.cmake -DIG=... -DOUT=... -DCASE=...`.

include(${CMAKE_CURRENT_LIST_DIR}/lib/dem_script.cmake)

if(CMAKE_SCRIPT_MODE_FILE)
  begin_dem_script(height-window)
  set(DEM "$ENV{IG_DEM_DIR}/sierra_nevada_3arcsec_4097.tif")
  include(${CMAKE_CURRENT_LIST_DIR}/lib/window_runs.cmake)
  set(keys "{\"t\": 0, \"position\": [36.700, -118.060, 200], \"hpr\": [250, -4, 0]},
    {\"t\": 2, \"position\": [36.680, -118.110, 150], \"hpr\": [255, -2, -8]}")
  if(CASE STREQUAL "overview")
    run_window_scenario(overview "\"file\": \"${DEM}\", \"texture_limit\": 2049, \"height_window\": 512" "" "${keys}")
    expect_roam_refused(overview "method 'roam' cannot draw .*4097x4097.*texture limit is 2049" "beyond the texture limit")
    return()
  endif()
  if(CASE MATCHES "^paged")
    set(extra "")
    if(CASE STREQUAL "paged_overview")
      set(extra "\"texture_limit\": 2049, ")
    endif()
    foreach(budget 2048 16 16live)
      string(REGEX REPLACE "live" "" mb "${budget}")
      set(wait "true")
      if(budget MATCHES "live")
        set(wait "false")
      endif()
      run_window_scenario(${budget}
        "\"file\": \"${DEM}\", ${extra}\"height_window\": 256, \"memory_budget_mb\": ${mb}, \"wait_for_pages\": ${wait}"
        "" "${keys}")
    endforeach()
    expect_roam_refused(16 "method 'roam' cannot draw .*(paged|texture limit)" "on paged heights")
    file(READ "${OUT}/run_16/summary.json" summary)
    string(JSON waited GET "${summary}" paging frames_waited_on_io)
    string(JSON peak GET "${summary}" paging peak_resident_mb)
    message("paged: frames waited on I/O ${waited}, peak resident ${peak} MB")
    if(peak GREATER 16)
      message(FATAL_ERROR "the tile cache held ${peak} MB, over its 16 MB budget")
    endif()
    include(${CMAKE_CURRENT_LIST_DIR}/lib/frames_csv.cmake)
    expect_frames_columns("${OUT}/run_16/frames.csv" "page_waits,page_ins" "a paged run")
    # Live: the same flight without waiting for tiles (Level1 keeps its
    # square meanwhile; which frames do depends on the disk, so only the
    # bookkeeping is checked here; visual/render/test/paged_level1_hold_test.cpp
    # checks the hold itself with gated reads).
    file(READ "${OUT}/run_16live/summary.json" summary)
    string(JSON live_wait GET "${summary}" paging wait_for_pages)
    string(JSON deferred GET "${summary}" paging deferred_reads)
    message("paged, live: deferred reads ${deferred}")
    if(live_wait OR NOT deferred GREATER_EQUAL 0)
      message(FATAL_ERROR "summary.json of a live paged run: wait_for_pages ${live_wait}, deferred_reads '${deferred}'")
    endif()
    expect_frames_columns("${OUT}/run_16live/frames.csv" "level1_held" "a live paged run")
    file(STRINGS "${OUT}/run_2048/frames.csv" header LIMIT_COUNT 1)
    if(header MATCHES "page_waits")
      message(FATAL_ERROR "frames.csv of a DEM within the budget has paging columns")
    endif()
    expect_same_file("${OUT}/run_2048/final.png" "${OUT}/run_16/final.png"
      "final.png with paged heights differs from the whole-array run's")
    return()
  endif()
  foreach(window 0 256)
    run_window_scenario(${window} "\"file\": \"${DEM}\", \"height_window\": ${window}" "" "${keys}")
  endforeach()
  # The window was used: its first fill (256 x 256 floats) and its updates
  # show in the frames' upload_bytes on top of what the run without it uploads.
  include(${CMAKE_CURRENT_LIST_DIR}/lib/frames_csv.cmake)
  sum_frames_column("${OUT}/run_0/frames.csv" upload_bytes 0 up0)
  sum_frames_column("${OUT}/run_256/frames.csv" upload_bytes 0 up256)
  message("upload_bytes over the flight: ${up0} without the window, ${up256} with it")
  math(EXPR extra "${up256} - ${up0}")
  if(extra LESS 262144)
    message(FATAL_ERROR "the height window uploaded ${extra} bytes, less than its first fill (262144)")
  endif()
  expect_same_file("${OUT}/run_0/final.png" "${OUT}/run_256/final.png"
    "final.png with a 256-sample height window differs from the whole-DEM texture's")
  return()
endif()

add_dem_script_tests(cli.height_window height_window ${CMAKE_CURRENT_LIST_FILE} ""
  same_picture overview paged paged_overview)
