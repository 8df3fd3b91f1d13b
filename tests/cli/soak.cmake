# A short soak of ig serve: the soak benchmark's rig (tools/bench/soak.sh,
# docs/results.md "Soak: a long flight under full host load") for 45 s on the
# generated default terrain (no DEM): a CIGI host at 60 Hz in its own time,
# each datagram its ownship (a slow circle, 20 m/s, so the view and the
# IG's working set stay steady) and 100 HOT requests, mbpoll reading the
# status block at 10 Hz (when built with Modbus). It samples ig serve's
# VmRSS, threads and open files from /proc every second and asserts on those
# samples: over the 30 s after the flight's first 12 s resident memory grown
# by at most 2 MB (medians of the last and first thirds), open files and
# threads constant; ig serve exits 0 (on SIGTERM after the
# host's last datagram) and writes summary.json. Ports 47500-47502.
set(IG_SOAK_MODBUS_HZ 0)
if(IG_WITH_MODBUS)
  find_program(IG_MBPOLL mbpoll)
  if(IG_MBPOLL)
    set(IG_SOAK_MODBUS_HZ 10)
  endif()
endif()
add_test(NAME cli.soak.steady_hot_load COMMAND bash ${CMAKE_SOURCE_DIR}/tools/bench/soak.sh ${CMAKE_BINARY_DIR}
  ${CMAKE_BINARY_DIR}/test-out/soak --terrain default --duration 45 --hot 100 --los 0 --speed 20 --sample-every 1
  --warmup 12 --modbus-hz ${IG_SOAK_MODBUS_HZ} --port 47500 -- --check-flat-mb 2 --check-for 30 --table-every 5)
set_tests_properties(cli.soak.steady_hot_load PROPERTIES LABELS "cli;net;soak" TIMEOUT 300
  RESOURCE_LOCK loopback_ig PASS_REGULAR_EXPRESSION "PASS soak" FAIL_REGULAR_EXPRESSION "FAIL")

# The short soak's frames flown again offline (soak_report.py replay): the
# hour's largest frames are traced this way (docs/results.md).
set_tests_properties(cli.soak.steady_hot_load PROPERTIES FIXTURES_SETUP soak_run)
add_test(NAME cli.soak.replay COMMAND bash ${CMAKE_SOURCE_DIR}/tests/cli/lib/soak_replay.sh ${CMAKE_SOURCE_DIR}
  ${CMAKE_BINARY_DIR})
set_tests_properties(cli.soak.replay PROPERTIES LABELS "cli;soak" TIMEOUT 300 FIXTURES_REQUIRED soak_run
  PASS_REGULAR_EXPRESSION "PASS soak replay" FAIL_REGULAR_EXPRESSION "FAIL")

# The soak's memory check tells a dip from a leak, on that short soak's own
# samples edited (tests/cli/lib/soak_check.sh).
add_test(NAME cli.soak.check_tells_a_dip_from_a_leak COMMAND bash ${CMAKE_SOURCE_DIR}/tests/cli/lib/soak_check.sh
  ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR})
set_tests_properties(cli.soak.check_tells_a_dip_from_a_leak PROPERTIES LABELS "cli;soak" TIMEOUT 120
  FIXTURES_REQUIRED soak_run PASS_REGULAR_EXPRESSION "PASS soak check" FAIL_REGULAR_EXPRESSION "FAIL soak check")
