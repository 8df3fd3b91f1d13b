# cmake --install puts ig, ig-send, the shaders and the default scenario under
# a prefix; the installed binary, run from another directory, finds its
# shaders (and ig serve its default config) relative to itself.
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
    '${IG_INSTALL_PREFIX}/bin/ig-send' --help | head -1")
set_tests_properties(cli.install.runs_from_the_prefix PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "\"shader_dir\": *\"${IG_INSTALL_PREFIX}/share/ig/shaders\".*\"scenario_file\": *\"${IG_INSTALL_PREFIX}/share/ig/scenarios/default.json\".*usage: ig send")
