# Modbus TCP status/control (docs/modbus.md) against ig serve --headless with
# mbpoll and a libmodbus client (bench_modbus --poll). Ports 473xx.
if(IG_WITH_MODBUS)
  find_program(IG_MBPOLL mbpoll)
  if(NOT IG_MBPOLL)
    message(WARNING "mbpoll not found: the cli.modbus tests will fail (tools/setup.sh installs it)")
  endif()
  set(IG_MODBUS_OUT ${CMAKE_BINARY_DIR}/test-out/modbus)

  add_test(NAME cli.modbus.serve_status_and_controls COMMAND bash ${CMAKE_SOURCE_DIR}/tests/tools/modbus_serve.sh
    ${CMAKE_BINARY_DIR}/bin ${CMAKE_SOURCE_DIR} ${IG_MODBUS_OUT}/serve 47310 47311)
  set_tests_properties(cli.modbus.serve_status_and_controls PROPERTIES LABELS "cli;modbus" TIMEOUT 120
    RESOURCE_LOCK loopback_ig FAIL_REGULAR_EXPRESSION "FAIL"
    PASS_REGULAR_EXPRESSION "mbpoll frame counter: [0-9]+ then [0-9]+.*Illegal data value.*Illegal data address.*capture trigger -> capture_.*freeze=1: ig_state 3.*polling ok.*Level1 shrank after the threshold write; the IG kept rendering")

  # Bad --modbus endpoints are usage errors.
  ig_cli_failure_test(cli.modbus.bad_endpoint "--modbus.*expected ADDR:PORT.*exit=2"
    "'$<TARGET_FILE:ig>' serve --udp 127.0.0.1:47320 --modbus 127.0.0.1 --frames 1")
  set_tests_properties(cli.modbus.bad_endpoint PROPERTIES LABELS "cli;modbus")
  # A port already taken: one line, exit 1.
  add_test(NAME cli.modbus.port_in_use COMMAND bash -c "
    '$<TARGET_FILE:ig>' serve --headless --udp 127.0.0.1:47321 --modbus 127.0.0.1:47322 --seconds 4 --size 64x48 --quiet --out ${IG_MODBUS_OUT}/inuse1 >/dev/null 2>&1 &
    for _ in \$(seq 1 100); do (exec 3<>/dev/tcp/127.0.0.1/47322) 2>/dev/null && break; sleep 0.1; done
    '$<TARGET_FILE:ig>' serve --headless --udp 127.0.0.1:47323 --modbus 127.0.0.1:47322 --frames 1 --size 64x48 --quiet --out ${IG_MODBUS_OUT}/inuse2 2>&1; rc=$?
    wait; test $rc -eq 1 && echo exit-1")
  set_tests_properties(cli.modbus.port_in_use PROPERTIES LABELS "cli;modbus" RESOURCE_LOCK loopback_ig
    PASS_REGULAR_EXPRESSION "cannot listen on 127.0.0.1:47322.*exit-1")
endif()
