#!/usr/bin/env bash
# One ctest result per vcan case: prints the case's section of the VM log
# written by run_vm.sh and passes when the case said PASS.
# usage: check_case.sh LOG CASE
set -uo pipefail
log=${1:?LOG}; case=${2:?CASE}
[ -f "$log" ] || { echo "check_case: no log $log (did can.vm.run run?)"; exit 1; }
sed -n "/^case $case\$/,/^case $case: /p" "$log"
grep -q "^case $case: PASS" "$log"
