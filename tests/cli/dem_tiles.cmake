# A folder of DEM tiles read as one DEM (visual/terrain/dem_mosaic.h): the
# Sierra DEM cut into tiles at test time. Two roles, like info.cmake:
#  * included by tests/CMakeLists.txt: registers cli.tiles.* (skip without IG_DEM_DIR);
#  * run as `cmake -P dem_tiles.cmake -DIG=... -DCUT=... -DOUT=... -DCASE=...`.

include(${CMAKE_CURRENT_LIST_DIR}/lib/dem_script.cmake)

if(CMAKE_SCRIPT_MODE_FILE)
  begin_dem_script(tiled-DEM)
  set(DEM "$ENV{IG_DEM_DIR}/sierra_nevada_3arcsec_4097.tif")

  function(run_ok)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${ARGN}\n  exit ${rc}\n  ${out}\n  ${err}")
    endif()
    set(run_out "${out}" PARENT_SCOPE)
  endfunction()
  function(info_of path prefix)
    run_ok("${IG}" info "${path}")
    message("ig info ${path}: ${run_out}")
    foreach(k width height min_m max_m mean_m nodata_count)
      string(JSON v GET "${run_out}" ${k})
      set(${prefix}_${k} "${v}" PARENT_SCOPE)
    endforeach()
    string(JSON v ERROR_VARIABLE none GET "${run_out}" tiles)
    set(${prefix}_tiles "${v}" PARENT_SCOPE)
    string(JSON v ERROR_VARIABLE none GET "${run_out}" reprojected_tiles)
    set(${prefix}_reprojected "${v}" PARENT_SCOPE)
  endfunction()
  function(expect what got want)
    if(NOT "${got}" STREQUAL "${want}")
      message(FATAL_ERROR "${what}: got ${got}, expected ${want}")
    endif()
  endfunction()

  if(CASE STREQUAL "four")
    # 2 x 2 tiles: the same grid and heights as the file, and the same picture.
    run_ok("${CUT}" "${DEM}" "${OUT}/tiles" 2 2)
    info_of("${DEM}" file)
    info_of("${OUT}/tiles" tiles)
    foreach(k width height min_m max_m mean_m nodata_count)
      expect("${k}" "${tiles_${k}}" "${file_${k}}")
    endforeach()
    expect("tiles" "${tiles_tiles}" 4)
    # tiles_paged: the folder with its heights paged (a 48 MB budget, under
    # the 4097^2 floats): read through the mosaic's in-memory VRTs after the load.
    foreach(src file tiles tiles_paged)
      set(terrain "${DEM}\"")
      if(src STREQUAL "tiles")
        set(terrain "${OUT}/tiles\"")
      elseif(src STREQUAL "tiles_paged")
        set(terrain "${OUT}/tiles\", \"memory_budget_mb\": 48, \"wait_for_pages\": true")
      endif()
      file(WRITE "${OUT}/${src}.json" "{\"name\": \"tiles_${src}\", \"terrain\": {\"file\": \"${terrain}},
  \"render\": {\"width\": 160, \"height\": 120, \"fov_y_deg\": 45},
  \"path\": {\"frame\": \"geodetic\", \"altitude\": \"agl\", \"keys\": [
    {\"t\": 0, \"position\": [36.700, -118.060, 200], \"hpr\": [250, -4, 0]},
    {\"t\": 2, \"position\": [36.680, -118.110, 150], \"hpr\": [255, -2, -8]}]},
  \"time\": {\"step_s\": 0.5, \"duration_s\": 2}}\n")
      run_ok("${IG}" run "${OUT}/${src}.json" --out "${OUT}/run_${src}" --headless --quiet)
    endforeach()
    file(SHA256 "${OUT}/run_file/final.png" a)
    file(SHA256 "${OUT}/run_tiles/final.png" b)
    expect("final.png of the tiles against the file" "${b}" "${a}")
    file(SHA256 "${OUT}/run_tiles_paged/final.png" c)
    expect("final.png of the tiles, paged, against the file" "${c}" "${a}")
  elseif(CASE STREQUAL "missing")
    # Tile 1 (north-east, 2049 x 2048 samples) left out: nodata, filled and counted.
    run_ok("${CUT}" "${DEM}" "${OUT}/tiles" 2 2 --skip 1)
    info_of("${OUT}/tiles" tiles)
    expect("width" "${tiles_width}" 4097)
    expect("height" "${tiles_height}" 4097)
    expect("nodata_count" "${tiles_nodata_count}" 4196352)
    expect("tiles" "${tiles_tiles}" 3)
  elseif(CASE STREQUAL "reprojected")
    # The last tile in UTM 11N: warped back onto the first tile's grid.
    run_ok("${CUT}" "${DEM}" "${OUT}/tiles" 2 2 --epsg-of-last 32611)
    info_of("${OUT}/tiles" tiles)
    expect("reprojected_tiles" "${tiles_reprojected}" 1)
    expect("width" "${tiles_width}" 4097)
    if(tiles_height LESS 4097 OR tiles_nodata_count LESS 1)
      message(FATAL_ERROR "the warped tile's footprint should add rows and nodata (height ${tiles_height}, "
                          "nodata ${tiles_nodata_count})")
    endif()
  elseif(CASE STREQUAL "bad")
    # A folder with no DEM tile, and one with a tile that is not a raster: one clear error each.
    file(WRITE "${OUT}/empty/README.txt" "not a DEM\n")
    file(WRITE "${OUT}/broken/bad.tif" "garbage")
    foreach(dir empty broken)
      execute_process(COMMAND "${IG}" info "${OUT}/${dir}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
      message("ig info ${dir}: exit ${rc}: ${err}")
      if(rc EQUAL 0 OR NOT out STREQUAL "")
        message(FATAL_ERROR "ig info on the ${dir} folder must fail with no output")
      endif()
    endforeach()
    execute_process(COMMAND "${IG}" info "${OUT}/empty" ERROR_VARIABLE err)
    if(NOT err MATCHES "empty: no DEM tiles in the folder")
      message(FATAL_ERROR "unexpected error for the empty folder: ${err}")
    endif()
    execute_process(COMMAND "${IG}" info "${OUT}/broken" ERROR_VARIABLE err)
    if(NOT err MATCHES "broken/bad.tif: tile cannot be read: not a recognised raster format")
      message(FATAL_ERROR "unexpected error for the broken tile: ${err}")
    endif()
  else()
    message(FATAL_ERROR "unknown CASE ${CASE}")
  endif()
  return()
endif()

add_dem_script_tests(cli.tiles tiles ${CMAKE_CURRENT_LIST_FILE} "-DCUT=$<TARGET_FILE:cut_dem_tiles>"
  four missing reprojected bad)
