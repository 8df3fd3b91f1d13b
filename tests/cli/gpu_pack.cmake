# The GPU machine's package (tools/bench/gpu_pack.py, docs/results.md "On a
# GPU"), tried here on llvmpipe (tests/cli/lib/gpu_pack_smoke.sh): packed
# with libxml2 kept (Mesa needs it), every library the packed ig loads
# resolves inside the package or is the C library, the stubbed OpenVDB is
# small, and gpu_tables.sh's smoke run of ig bench on the Sierra DEM (GDAL,
# PROJ, OpenImageIO and EGL through the packed libraries) reports its renderer.
ig_real_dem_test(cli.gpu_pack.smoke_bench "the smoke run of the GPU package"
  "bash ${CMAKE_CURRENT_LIST_DIR}/lib/gpu_pack_smoke.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR} \"\$IG_DEM_DIR\" ${CMAKE_BINARY_DIR}/test-out/gpu_pack")
set_tests_properties(cli.gpu_pack.smoke_bench PROPERTIES TIMEOUT 300
  PASS_REGULAR_EXPRESSION "table2_sierra, 1 method/knob rows x 4 frames at 160x128"
  FAIL_REGULAR_EXPRESSION "resolved outside|not stubbed|smoke run failed")
