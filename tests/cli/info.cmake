# `ig info` end to end. This file has two roles:
#  * included by tests/CMakeLists.txt: registers the cli.info.* tests;
#  * run as `cmake -P info.cmake -DIG=... -DARGS=...`: runs one `ig info`
#    and checks its exit code, its stdout (one JSON object, parsed with
#    string(JSON)) and its stderr (exactly one "ig info: ..." line on error).
#
# Check-mode variables:
#   IG           path of the ig executable
#   ARGS         arguments after `ig info`, separated by "|"
#   EXPECT_RC    expected exit code
#   EXPECT_JSON  "|"-separated checks on members: key=value (exact text;
#                booleans read ON/OFF), key=null, key=LO..HI (numeric); a
#                nested member is named by its path, outer.inner=value
#   EXPECT_ERR   regex the single stderr line must match (error cases)
#   EXPECT_OUT   regex stdout must match (non-JSON output, e.g. --help)

if(CMAKE_SCRIPT_MODE_FILE)
  string(REPLACE "|" ";" _args "${ARGS}")
  execute_process(COMMAND "${IG}" info ${_args}
    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  message("ig info ${_args}\n  exit: ${_rc}\n  stdout: ${_out}\n  stderr: ${_err}")
  if(NOT "${_rc}" STREQUAL "${EXPECT_RC}")
    message(FATAL_ERROR "exit code ${_rc}, expected ${EXPECT_RC}")
  endif()
  if(DEFINED EXPECT_OUT AND NOT _out MATCHES "${EXPECT_OUT}")
    message(FATAL_ERROR "stdout does not match '${EXPECT_OUT}'")
  endif()
  if(DEFINED EXPECT_ERR)
    if(NOT _out STREQUAL "")
      message(FATAL_ERROR "stdout must be empty on error")
    endif()
    string(REGEX MATCHALL "\n" _newlines "${_err}")
    list(LENGTH _newlines _nlines)
    if(NOT _nlines EQUAL 1 OR NOT _err MATCHES "^ig info: [^\n]+\n$")
      message(FATAL_ERROR "stderr must be exactly one 'ig info: ...' line")
    endif()
    if(NOT _err MATCHES "${EXPECT_ERR}")
      message(FATAL_ERROR "stderr does not match '${EXPECT_ERR}'")
    endif()
  endif()
  if(DEFINED EXPECT_JSON)
    string(STRIP "${_out}" _json)
    string(JSON _type ERROR_VARIABLE _jerr TYPE "${_json}")
    if(_jerr OR NOT _type STREQUAL "OBJECT")
      message(FATAL_ERROR "stdout is not one JSON object: ${_jerr}")
    endif()
    string(REPLACE "|" ";" _checks "${EXPECT_JSON}")
    foreach(_check IN LISTS _checks)
      if(NOT _check MATCHES "^([a-z_.]+)=(.*)$")
        message(FATAL_ERROR "bad check '${_check}'")
      endif()
      set(_key "${CMAKE_MATCH_1}")
      set(_want "${CMAKE_MATCH_2}")
      string(REPLACE "." ";" _member_path "${_key}")
      string(JSON _t ERROR_VARIABLE _jerr TYPE "${_json}" ${_member_path})
      if(_jerr)
        message(FATAL_ERROR "JSON has no member '${_key}'")
      endif()
      string(JSON _v GET "${_json}" ${_member_path})
      if(_want STREQUAL "null")
        if(NOT _t STREQUAL "NULL")
          message(FATAL_ERROR "${_key} is ${_t} '${_v}', expected null")
        endif()
      elseif(_want MATCHES "^(-?[0-9.]+)\\.\\.(-?[0-9.]+)$")
        if(NOT _t STREQUAL "NUMBER" OR _v LESS CMAKE_MATCH_1 OR _v GREATER CMAKE_MATCH_2)
          message(FATAL_ERROR "${_key} = ${_v}, expected ${_want}")
        endif()
      elseif(NOT _v STREQUAL _want)
        message(FATAL_ERROR "${_key} = '${_v}', expected '${_want}'")
      endif()
    endforeach()
  endif()
  message("ok")
  return()
endif()

if(NOT TARGET ig)
  return()
endif()

set(_ig_info_script ${CMAKE_CURRENT_LIST_FILE})
set(_ig_info_dir ${CMAKE_CURRENT_BINARY_DIR}/info-data)
file(MAKE_DIRECTORY ${_ig_info_dir})

# Small inputs written at configure time.
file(WRITE ${_ig_info_dir}/tiny.asc
  "ncols 4\nnrows 3\nxllcorner 1000\nyllcorner 2000\ncellsize 10\nNODATA_value -9999\n"
  "1 2 3 4\n5 -9999 7 8\n9 10 11 12\n")
file(WRITE ${_ig_info_dir}/empty.tif "")
file(WRITE ${_ig_info_dir}/notes.tif "this is a text file, not a GeoTIFF\n")
file(WRITE ${_ig_info_dir}/notes.png "this is a text file, not a PNG\n")
file(WRITE ${_ig_info_dir}/N44W072.hgt "abc")
file(WRITE ${_ig_info_dir}/huge.asc
  "ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n")
file(REMOVE ${_ig_info_dir}/missing.tif)

# ig_info_test(NAME args rc [JSON checks] [ERR regex] [OUT regex])
function(ig_info_test name args rc)
  cmake_parse_arguments(T "" "JSON;ERR;OUT" "" ${ARGN})
  set(defs -DIG=$<TARGET_FILE:ig> "-DARGS=${args}" -DEXPECT_RC=${rc})
  if(DEFINED T_JSON)
    list(APPEND defs "-DEXPECT_JSON=${T_JSON}")
  endif()
  if(DEFINED T_ERR)
    list(APPEND defs "-DEXPECT_ERR=${T_ERR}")
  endif()
  if(DEFINED T_OUT)
    list(APPEND defs "-DEXPECT_OUT=${T_OUT}")
  endif()
  add_test(NAME cli.info.${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${_ig_info_script})
  set_tests_properties(cli.info.${name} PROPERTIES LABELS cli TIMEOUT 120)
endfunction()

set(D ${_ig_info_dir})
ig_info_test(ascii_grid "${D}/tiny.asc" 0
  JSON "width=4|height=3|nodata_count=1|min_m=1|max_m=12|spacing_x_m=10|spacing_y_m=10|crs=null|geographic=OFF|source=${D}/tiny.asc")
ig_info_test(spacing_override "${D}/tiny.asc|--spacing|2.5" 0
  JSON "spacing_x_m=2.5|spacing_y_m=2.5")
# How voids are filled: GDAL's GDALFillNodata with its settings (terrain/void_fill.h).
ig_info_test(void_fill_defaults "${D}/tiny.asc" 0
  JSON "nodata_count=1|void_fill.algorithm=GDALFillNodata|void_fill.max_distance=400|void_fill.smoothing_iterations=2|void_fill.deep_count=0|void_fill.deep_fill=layers")
ig_info_test(void_fill_options "${D}/tiny.asc|--fill-max-distance|3|--fill-smoothing|0" 0
  JSON "void_fill.max_distance=3|void_fill.smoothing_iterations=0|void_fill.deep_count=0")
ig_info_test(usage_bad_fill_distance "${D}/tiny.asc|--fill-max-distance|0" 2
  ERR "--fill-max-distance must be an integer in 1\\.\\.1024, got '0'")
ig_info_test(usage_bad_fill_smoothing "${D}/tiny.asc|--fill-smoothing|2.5" 2
  ERR "--fill-smoothing must be an integer in 0\\.\\.32")
ig_info_test(help "--help" 0 OUT "usage: ig info FILE")
ig_info_test(missing_file "${D}/missing.tif" 1 ERR "missing\\.tif: no such file")
ig_info_test(empty_file "${D}/empty.tif" 1 ERR "empty\\.tif: empty file \\(0 bytes\\)")
# A folder is a mosaic of its tiles (cli.tiles.*): here the first tile that cannot be read is named.
ig_info_test(directory_of_bad_tiles "${D}" 1 ERR "info-data/N44W072\\.hgt: tile cannot be read")
ig_info_test(text_as_tif "${D}/notes.tif" 1 ERR "notes\\.tif: not a recognised raster format")
ig_info_test(text_as_png "${D}/notes.png" 1 ERR "notes\\.png: not a recognised raster format")
ig_info_test(truncated_hgt "${D}/N44W072.hgt" 1
  ERR "N44W072\\.hgt: truncated or wrong-size SRTM \\.hgt: 3 bytes, expected 2884802")
ig_info_test(absurd_size "${D}/huge.asc" 1 ERR "huge\\.asc: raster size 100000x100000 is too large")
ig_info_test(usage_no_file "" 2 ERR "missing FILE")
ig_info_test(usage_two_files "${D}/tiny.asc|${D}/tiny.asc" 2 ERR "more than one FILE")
ig_info_test(usage_bad_option "${D}/tiny.asc|--frobnicate" 2 ERR "unknown option --frobnicate")
ig_info_test(usage_bad_encoding "${D}/tiny.asc|--encoding|jpeg" 2 ERR "--encoding must be")
ig_info_test(usage_bad_number "${D}/tiny.asc|--scale|abc" 2 ERR "--scale needs a number")

# The real DEMs (shared/data/dem/README.md), when IG_DEM_DIR is set at configure time.
if(DEFINED ENV{IG_DEM_DIR} AND NOT "$ENV{IG_DEM_DIR}" STREQUAL "")
  set(R $ENV{IG_DEM_DIR})
  ig_info_test(real_sierra_tif "${R}/sierra_nevada_3arcsec_4097.tif" 0
    JSON "width=4097|height=4097|min_m=-80|max_m=4404|spacing_y_m=92.3..92.8|spacing_x_m=72.5..74.5|crs=EPSG:4326|geographic=ON|nodata_count=0")
  ig_info_test(real_sierra_png16
    "${R}/sierra_nevada_3arcsec_4097_u16_plus1000.png|--encoding|png16|--scale|1|--offset|-1000" 0
    JSON "width=4097|height=4097|min_m=-80|max_m=4404|crs=null")
  ig_info_test(real_hgt "${R}/N44W072.hgt" 0
    JSON "width=1201|height=1201|min_m=115|max_m=1908|spacing_y_m=92.3..92.8|spacing_x_m=65.5..66.8|crs=EPSG:4326|nodata_count=0")
  ig_info_test(real_rainier "${R}/mt_rainier_90m.tif" 0
    JSON "width=1201|height=1201|min_m=263|max_m=4371|spacing_x_m=63..64.7|crs=EPSG:4326")
  ig_info_test(real_everest "${R}/mt_everest_90m.tif" 0
    JSON "width=1201|height=1201|min_m=192|max_m=8642|spacing_x_m=81.5..83|crs=EPSG:4326|nodata_count=130953|void_fill.deep_count=0")
  # A short search leaves the summit void's middle deep (filled by layers, counted).
  ig_info_test(real_everest_deep_voids "${R}/mt_everest_90m.tif|--fill-max-distance|4" 0
    JSON "nodata_count=130953|void_fill.max_distance=4|void_fill.deep_count=1..130952|max_m=8642")
  ig_info_test(real_fuji_tif "${R}/mt_fuji_90m.tif" 0
    JSON "width=1201|height=1201|min_m=-16|max_m=3742|spacing_x_m=75..76.2|crs=EPSG:4326")
  ig_info_test(real_qgis_dem25 "${R}/qgis_dem25_bejar_spain.tif" 0
    JSON "width=601|height=410|min_m=513..515|max_m=2409..2411|spacing_x_m=25|spacing_y_m=25|crs=EPSG:23030|geographic=OFF")
  ig_info_test(real_fuji_terrain_rgb "${R}/fuji.png|--encoding|terrain-rgb" 0
    JSON "width=512|height=512|min_m=13.65..13.75|max_m=3750.95..3751.05|crs=null")
  ig_info_test(real_readme_is_not_a_dem "${R}/README.md" 1
    ERR "README\\.md: not a recognised raster format")
endif()
