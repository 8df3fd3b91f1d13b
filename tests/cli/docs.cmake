# Every ```json example of docs/*.md works as written: complete scenarios run
# (ig run --frames 1 --size 160x120, after the example's own ```sh set-up),
# fragments run as members of a small scenario; examples on $IG_DEM_DIR are
# skipped, with a line saying so, when it is not set.
add_test(NAME cli.docs.json_examples_run COMMAND python3 ${CMAKE_SOURCE_DIR}/tests/tools/check_doc_examples.py
  $<TARGET_FILE:ig> ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/doc_examples)
set_tests_properties(cli.docs.json_examples_run PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "doc examples ok" FAIL_REGULAR_EXPRESSION "FAIL")

# The programs README.md and docs/live-ig.md run (build/bin/...) are the ones
# tools/demo.sh, the README's first command, builds.
add_test(NAME cli.docs.demo_builds_what_the_readme_runs COMMAND bash -c "set -e; cd '${CMAKE_SOURCE_DIR}'
  targets=\" $(sed -n 's/.*cmake --build .*--target //p' tools/demo.sh) \"
  for b in $(grep -ohE 'build/bin/[A-Za-z0-9_-]+' README.md docs/live-ig.md | sort -u | sed 's|build/bin/||'); do
    [ \"$b\" = shaders ] && continue
    case \"$targets\" in *\" $b \"*) echo \"demo.sh builds $b\" ;; *) echo \"FAIL: tools/demo.sh does not build $b\" ;; esac
  done")
set_tests_properties(cli.docs.demo_builds_what_the_readme_runs PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "demo.sh builds ig-send" FAIL_REGULAR_EXPRESSION "FAIL")
