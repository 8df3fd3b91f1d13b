# terrain.water end to end: what ig info reports, ig run with a water file
# (the default scenario's valley lake) and without water, and a bad water
# file named with its reason by ig run and ig info.
set(IG_WATER_OUT ${CMAKE_CURRENT_BINARY_DIR}/water-out)
set(IG_WATER_CHECK "python3 '${CMAKE_SOURCE_DIR}/tests/cli/lib/water_check.py'")

ig_real_dem_test(cli.water.info_sierra "the Sierra water check"
  "set -o pipefail; '$<TARGET_FILE:ig>' info \"$IG_DEM_DIR/sierra_nevada_3arcsec_4097.tif\" | ${IG_WATER_CHECK} info-sierra"
  PASS_REGULAR_EXPRESSION "water ok")
ig_real_dem_test(cli.water.info_fuji "Suruga Bay"
  "set -o pipefail; '$<TARGET_FILE:ig>' info \"$IG_DEM_DIR/mt_fuji_90m.tif\" | ${IG_WATER_CHECK} info-fuji"
  PASS_REGULAR_EXPRESSION "water ok")

# A water file replaces the auto detection: one lake at its attribute's level.
add_test(NAME cli.water.run_default_lake COMMAND bash -c "set -e; o='${IG_WATER_OUT}/default_lake'
  '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default_lake.json' --frames 2 --size 160x120 --out \"$o\" --quiet
  ${IG_WATER_CHECK} summary \"$o/summary.json\" 1 default_lake.geojson
  '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --frames 1 --size 160x120 --out \"$o-none\" --quiet
  ${IG_WATER_CHECK} no-water \"$o-none/summary.json\"")
set_tests_properties(cli.water.run_default_lake PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "water ok.*water ok")

# Bad water files: one line naming the file and why.
file(MAKE_DIRECTORY ${IG_WATER_OUT})
file(WRITE ${IG_WATER_OUT}/not_geojson.geojson "this is not GeoJSON\n")
file(WRITE ${IG_WATER_OUT}/empty.geojson "{\"type\":\"FeatureCollection\",\"features\":[]}\n")
file(WRITE ${IG_WATER_OUT}/far.geojson "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[10,10],[11,10],[11,11],[10,10]]]}}]}\n")
file(REMOVE ${IG_WATER_OUT}/missing.geojson)
foreach(bad "missing:no such file" "not_geojson:GDAL cannot open it" "empty:layer '[^']*' is empty"
            "far:its polygons do not cover a DEM sample")
  string(FIND "${bad}" ":" _colon)
  string(SUBSTRING "${bad}" 0 ${_colon} name)
  math(EXPR _colon "${_colon} + 1")
  string(SUBSTRING "${bad}" ${_colon} -1 reason)
  ig_cli_failure_test(cli.water.run_${name} "ig run: [^\n]*/${name}[.]geojson: ${reason}[^\n]*\nexit=1"
    "cd '${IG_WATER_OUT}' && python3 -c \"import json; s=json.load(open('${CMAKE_SOURCE_DIR}/scenarios/default.json')); s['terrain']['water']='${name}.geojson'; json.dump(s, open('${name}.json', 'w'))\" && '$<TARGET_FILE:ig>' run ${name}.json --frames 1 --size 64x48 --out '${IG_WATER_OUT}/run_${name}' --quiet")
endforeach()
ig_cli_failure_test(cli.water.info_no_such_file "ig info: /nowhere[.]shp: no such file\nexit=1"
  "'$<TARGET_FILE:ig>' info '${CMAKE_CURRENT_BINARY_DIR}/info-data/tiny.asc' --water /nowhere.shp")
ig_cli_failure_test(cli.water.info_no_georeference "ig info: [^\n]*/far[.]geojson: the DEM [^\n]* has no georeferencing[^\n]*\nexit=1"
  "'$<TARGET_FILE:ig>' info '${CMAKE_CURRENT_BINARY_DIR}/info-data/tiny.asc' --water '${IG_WATER_OUT}/far.geojson'")
