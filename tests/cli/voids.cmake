# The DEM void fill as it shows (docs/terrain-data.md "Nodata"): the Everest
# and Rainier summit views (scenarios/*_summit.json, reference method) from
# our loader against the same DEM filled beforehand by GDAL's own
# gdal_fillnodata.py -md 400 -si 2. Skips without IG_DEM_DIR.

find_program(IG_GDAL_FILLNODATA gdal_fillnodata.py)
# The picture check needs GDAL's Python bindings and NumPy: the interpreter
# GDAL's own script runs with (its #! line).
set(_ig_gdal_python "")
if(IG_GDAL_FILLNODATA)
  file(STRINGS "${IG_GDAL_FILLNODATA}" _shebang LIMIT_COUNT 1)
  if(_shebang MATCHES "^#! *([^ ]+)")
    set(_ig_gdal_python "${CMAKE_MATCH_1}")
  endif()
endif()

if(TARGET ig AND IG_GDAL_FILLNODATA AND _ig_gdal_python)
  set(IG_TEST_OUT ${CMAKE_BINARY_DIR}/test-out)
  foreach(_view everest:mt_everest_90m.tif rainier:mt_rainier_90m.tif)
    string(REPLACE ":" ";" _view "${_view}")
    list(GET _view 0 _name)
    list(GET _view 1 _dem)
    set(_out "${IG_TEST_OUT}/voids_${_name}")
    ig_real_dem_test(cli.voids.${_name}_summit_as_gdal_fills_it "void-fill picture test"
      "set -e; rm -rf '${_out}'; mkdir -p '${_out}/filled'
        '${IG_GDAL_FILLNODATA}' -q -md 400 -si 2 \"$IG_DEM_DIR/${_dem}\" '${_out}/filled/${_dem}'
        '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/${_name}_summit.json' --out '${_out}/ours' --quiet
        IG_DEM_DIR='${_out}/filled' '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/${_name}_summit.json' --out '${_out}/gdal' --quiet
        '${_ig_gdal_python}' '${CMAKE_SOURCE_DIR}/tests/tools/picture_agreement.py' '${_out}/ours/final.png' '${_out}/gdal/final.png' --min-psnr 27 --max-over16 0.05
        echo pictures agree"
      PASS_REGULAR_EXPRESSION "pictures agree" TIMEOUT 300)
  endforeach()
endif()
