# ig serve's CIGI host services (issue 15): a test host on loopback drives
# HAT/HOT, LOS segment and LOS vector requests (basic and extended, geodetic
# and ownship-relative, big- and little-endian, one periodic request then its
# cancellation) in synchronous operation, and checks every answer against
# the Sierra DEM. Ports 472xx. Skips without IG_DEM_DIR.
add_test(NAME cli.serve.cigi_host_services
  COMMAND bash ${CMAKE_SOURCE_DIR}/tests/tools/host_services.sh $<TARGET_FILE:ig> $<TARGET_FILE:cigi_query_host>
          ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/host_services 47200 10)
set_tests_properties(cli.serve.cigi_host_services PROPERTIES LABELS "cli;net" SKIP_RETURN_CODE 77
  PASS_REGULAR_EXPRESSION "PASS host services" FAIL_REGULAR_EXPRESSION "FAIL" RESOURCE_LOCK loopback_ig)

# A flood beyond the per-frame budget: answered over later frames, none lost.
add_test(NAME cli.serve.cigi_request_flood
  COMMAND bash ${CMAKE_SOURCE_DIR}/tests/tools/host_flood.sh $<TARGET_FILE:ig> $<TARGET_FILE:cigi_query_host>
          ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR}/test-out/host_flood 47220)
set_tests_properties(cli.serve.cigi_request_flood PROPERTIES LABELS "cli;net" SKIP_RETURN_CODE 77
  PASS_REGULAR_EXPRESSION "PASS flood summary" FAIL_REGULAR_EXPRESSION "FAIL" RESOURCE_LOCK loopback_ig)

# The rest of a CIGI host's packets, from an independent encoder of the ICD
# layouts (Python struct): time of day, visibility, position and collision
# requests, environmental conditions, packets counted as unsupported.
add_test(NAME cli.serve.cigi_environment
  COMMAND python3 ${CMAKE_SOURCE_DIR}/tests/tools/cigi_environment_host.py $<TARGET_FILE:ig> ${CMAKE_SOURCE_DIR}
          ${CMAKE_BINARY_DIR}/test-out/cigi_environment 47240)
set_tests_properties(cli.serve.cigi_environment PROPERTIES LABELS "cli;net" SKIP_RETURN_CODE 77
  PASS_REGULAR_EXPRESSION "PASS environment" FAIL_REGULAR_EXPRESSION "FAIL" RESOURCE_LOCK loopback_ig)

# Entities placed by a host (Entity Control for ids beyond the ownship): a
# clamped entity's Position Response altitude is the IG's own HOT under it,
# an attached one follows its parent, a destroyed one is gone. Skips without
# IG_DEM_DIR.
add_test(NAME cli.serve.cigi_entities
  COMMAND python3 ${CMAKE_SOURCE_DIR}/tests/tools/cigi_entity_host.py $<TARGET_FILE:ig> ${CMAKE_SOURCE_DIR}
          ${CMAKE_BINARY_DIR}/test-out/cigi_entities 47280)
set_tests_properties(cli.serve.cigi_entities PROPERTIES LABELS "cli;net" SKIP_RETURN_CODE 77
  PASS_REGULAR_EXPRESSION "PASS entities" FAIL_REGULAR_EXPRESSION "FAIL" RESOURCE_LOCK loopback_ig)
