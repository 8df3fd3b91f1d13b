# Every ```json example of docs/*.md works as written: complete scenarios run
# (ig run --frames 1 --size 160x120, after the example's own ```sh set-up),
# fragments run as members of a small scenario; examples on $IG_DEM_DIR are
# skipped, with a line saying so, when it is not set.
add_test(NAME cli.docs.json_examples_run COMMAND python3 ${CMAKE_SOURCE_DIR}/tests/tools/check_doc_examples.py
  $<TARGET_FILE:ig> ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/doc_examples)
set_tests_properties(cli.docs.json_examples_run PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "doc examples ok" FAIL_REGULAR_EXPRESSION "FAIL")
