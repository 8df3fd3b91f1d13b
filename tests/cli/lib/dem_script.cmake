# Helpers for the cli tests that have two roles (dem_tiles.cmake,
# height_window.cmake, imagery_window.cmake): registered when included by
# tests/CMakeLists.txt, run as `cmake -P` on a real DEM per test case.
# In tests/cli/lib so the tests' glob of tests/cli/*.cmake does not register it.

# Script mode: skips the test when IG_DEM_DIR is not set (the message the
# tests' SKIP_REGULAR_EXPRESSION matches: cmake -P can exit 77 only from
# CMake 3.29 on, Debian 12 has 3.25), else starts from an empty OUT.
function(begin_dem_script what)
  if("$ENV{IG_DEM_DIR}" STREQUAL "")
    message(FATAL_ERROR "IG_DEM_DIR not set: ${what} test skipped")
  endif()
  file(REMOVE_RECURSE "${OUT}")
  file(MAKE_DIRECTORY "${OUT}")
endfunction()

# Script mode: stops the test with `failure` unless files a and b have the
# same bytes.
function(expect_same_file a b failure)
  file(SHA256 "${a}" hash_a)
  file(SHA256 "${b}" hash_b)
  if(NOT hash_a STREQUAL hash_b)
    message(FATAL_ERROR "${failure}")
  endif()
endfunction()

# Registration: a test <prefix>.<case> for each case after `defs`, running
# `script` in script mode with -DIG, the -D definitions in the list `defs`,
# -DOUT=test-out/<out_name>_<case> and -DCASE; begin_dem_script's message means skipped.
function(add_dem_script_tests prefix out_name script defs)
  foreach(case ${ARGN})
    add_test(NAME ${prefix}.${case}
      COMMAND ${CMAKE_COMMAND} -DIG=$<TARGET_FILE:ig> ${defs}
        -DOUT=${CMAKE_BINARY_DIR}/test-out/${out_name}_${case} -DCASE=${case} -P ${script})
    set_tests_properties(${prefix}.${case} PROPERTIES LABELS cli
      SKIP_REGULAR_EXPRESSION "IG_DEM_DIR not set: .* test skipped")
  endforeach()
endfunction()
