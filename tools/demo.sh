#!/usr/bin/env bash
# Set up, build, and run the default scenario (generated terrain, headless
# when there is no display). Outputs: out/default/. Builds build/bin/ig and
# build/bin/ig-send (the pose sender the README and docs/live-ig.md use with
# ig serve).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target ig ig-send ig_entity_models
build/bin/ig run scenarios/default.json --out out/default "$@"
