#!/usr/bin/env bash
# Runs the vcan cases (can_vm_cases all): directly when this host has a
# vcan0 (and AF_CAN), otherwise inside the test VM (prepare_vm.sh), booted
# once: the host's root is shared read-only over 9p and the cases run
# chrooted into it, so the same ig-send, cansend and test binary run on the
# VM's kernel. The output goes to LOG too, where check_case.sh reads each
# case's result (one ctest test per case).
#
# usage: run_vm.sh VM_DIR CASE_BINARY LOG [CASE (default all)]
set -uo pipefail
vm=${1:?VM_DIR}; bin=${2:?CASE_BINARY}; out=${3:?LOG}; case=${4:-all}
rm -f "$out"

if [ -e /sys/class/net/vcan0 ]; then
  echo "run_vm: this host has vcan0: running the cases here"
  "$bin" "$case" | tee "$out"
  exit 0
fi

log=$(mktemp)
trap 'rm -f "$log"' EXIT
start=$(date +%s.%N)
# TCG only: a /dev/kvm node may exist but KVM hangs here (docs/platform.md).
timeout 100 qemu-system-x86_64 -accel tcg -m 512 -smp 1 -nodefaults -no-user-config -display none \
  -serial stdio -monitor none -no-reboot \
  -kernel "$vm/vmlinux" -initrd "$vm/initrd.gz" \
  -virtfs local,path=/,mount_tag=host,security_model=none,readonly=on,multidevs=remap \
  -append "console=ttyS0 quiet panic=-1 IG_CASE=$case IG_CMD=$bin IG_WORKDIR=$(pwd)" > "$log" 2>&1
qrc=$?
grep -v -e "^\[ *[0-9.]*\] reboot" -e "9p: Multiple devices" "$log" | tr -d '\r' | tee "$out"
end=$(date +%s.%N)
echo "run_vm: the VM ran for $(awk "BEGIN {printf \"%.1f\", $end - $start}") s (qemu exit $qrc)"
if ! grep -q -a "IG_VM_RESULT case=$case" "$log"; then
  echo "run_vm: no result marker from the VM (boot failed or timed out)"
  exit 1
fi
# The cases' own verdicts are the per-case tests (check_case.sh); this test
# fails when no case reported at all (the program never ran in the VM).
if ! grep -q -a -E "^case [a-z_]+: (PASS|FAIL)" "$out"; then
  echo "run_vm: no case reported a result (the test program did not run in the VM)"
  exit 1
fi
exit 0
