# ig serve --can / ig-send --can on this host. The host kernel has no
# SocketCAN (the vcan cases run in a VM: tests/can), so these check the
# failure path a user sees: a clear error, and `ig serve` keeps rendering.
if(IG_WITH_CAN)
  add_test(NAME cli.serve_can_missing_interface
    COMMAND ${CMAKE_BINARY_DIR}/bin/ig serve --can igtest_none0 --frames 10 --size 96x64 --out ${CMAKE_BINARY_DIR}/cli_serve_can)
  set_tests_properties(cli.serve_can_missing_interface PROPERTIES LABELS cli
    ENVIRONMENT "LIBGL_ALWAYS_SOFTWARE=1;GALLIUM_DRIVER=llvmpipe"
    PASS_REGULAR_EXPRESSION "CAN igtest_none0: .*retrying every 0.5 s, rendering the last good pose")
  add_test(NAME cli.send_can_missing_interface
    COMMAND ${CMAKE_BINARY_DIR}/bin/ig-send ${CMAKE_SOURCE_DIR}/tests/can/can_path.json --can igtest_none0)
  set_tests_properties(cli.send_can_missing_interface PROPERTIES LABELS cli WILL_FAIL FALSE
    PASS_REGULAR_EXPRESSION "ig send: CAN igtest_none0: ")
endif()
