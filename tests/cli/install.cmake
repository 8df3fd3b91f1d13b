# cmake --install puts ig, ig-send, the shaders and the default scenario under
# a prefix; the installed binary, run from another directory, finds its
# shaders (and ig serve its default config) relative to itself, and the
# installed binaries hold no source or build path.
set(IG_INSTALL_PREFIX ${CMAKE_BINARY_DIR}/test-out/install)
add_test(NAME cli.install.runs_from_the_prefix COMMAND bash -c "set -e
    rm -rf '${IG_INSTALL_PREFIX}'
    '${CMAKE_COMMAND}' --install '${CMAKE_BINARY_DIR}' --prefix '${IG_INSTALL_PREFIX}' > /dev/null
    cd /
    '${IG_INSTALL_PREFIX}/bin/ig' run '${IG_INSTALL_PREFIX}/share/ig/scenarios/default.json' --frames 3 --size 64x48 \
      --out '${IG_INSTALL_PREFIX}/run' --quiet
    grep -o '\"shader_dir\": *\"[^\"]*\"' '${IG_INSTALL_PREFIX}/run/summary.json'
    '${IG_INSTALL_PREFIX}/bin/ig' serve --udp 127.0.0.1:0 --frames 2 --size 64x48 --out '${IG_INSTALL_PREFIX}/serve' --quiet
    grep -o '\"scenario_file\": *\"[^\"]*\"' '${IG_INSTALL_PREFIX}/serve/summary.json'
    '${IG_INSTALL_PREFIX}/bin/ig-send' --help | head -1
    echo \"build paths in the binaries: $(strings '${IG_INSTALL_PREFIX}/bin/ig' '${IG_INSTALL_PREFIX}/bin/ig-send' |
      grep -c -F -e '${CMAKE_SOURCE_DIR}' -e '${CMAKE_BINARY_DIR}')\"")
set_tests_properties(cli.install.runs_from_the_prefix PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "\"shader_dir\": *\"${IG_INSTALL_PREFIX}/share/ig/shaders\".*\"scenario_file\": *\"${IG_INSTALL_PREFIX}/share/ig/scenarios/default.json\".*usage: ig send.*build paths in the binaries: 0\n")

# The exported package: a program outside the tree finds ig with
# find_package(ig CONFIG), links ig::ig_terrain and ig::ig_io, and runs.
add_test(NAME cli.install.package_links_a_consumer COMMAND bash -c "set -e
    rm -rf '${IG_INSTALL_PREFIX}-pkg' '${CMAKE_BINARY_DIR}/test-out/consumer'
    '${CMAKE_COMMAND}' --install '${CMAKE_BINARY_DIR}' --prefix '${IG_INSTALL_PREFIX}-pkg' > /dev/null
    '${CMAKE_COMMAND}' -S '${CMAKE_SOURCE_DIR}/tests/install_consumer' -B '${CMAKE_BINARY_DIR}/test-out/consumer' \
      -DCMAKE_PREFIX_PATH='${IG_INSTALL_PREFIX}-pkg' -DCMAKE_BUILD_TYPE=Release > /dev/null
    '${CMAKE_COMMAND}' --build '${CMAKE_BINARY_DIR}/test-out/consumer' > /dev/null
    grep -c '${CMAKE_SOURCE_DIR}' '${IG_INSTALL_PREFIX}-pkg/lib/cmake/ig/igTargets.cmake' || true
    '${CMAKE_BINARY_DIR}/test-out/consumer/ig_consumer'")
set_tests_properties(cli.install.package_links_a_consumer PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "^0\nterrain 129x129 level0 5[0-9][0-9] triangles ray hit native ok")
