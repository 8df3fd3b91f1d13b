#!/usr/bin/env bash
# Benchmark: the pose rate a 1 kHz CANaerospace stream (ig-send --can
# --rate 1000) sustains through a real kernel's SocketCAN (vcan0 in the test
# VM, or this host's vcan0 when it has one). Prints figures; asserts nothing.
# usage: tools/bench/can_vm_bench.sh [BUILD_DIR]   (after building the tests)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
"$here/tests/can/prepare_vm.sh" "$build/can-vm"
"$here/tests/can/run_vm.sh" "$build/can-vm" "$build/bin/can_vm_cases" "$build/can-vm/bench.log" bench_1khz
