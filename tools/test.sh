#!/usr/bin/env bash
# Set up, build everything, run the whole test suite (ctest). Real-DEM tests
# run when IG_DEM_DIR names the DEM folder and skip with a message otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
