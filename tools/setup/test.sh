#!/usr/bin/env bash
# The README's second command: install dependencies, build once, run the whole test suite
# in parallel (slow tests carry the ctest label "slow"; every DDS test has its own domain),
# then the fuzz targets' smoke runs (tools/setup/fuzz_smoke.sh, a second build with clang).
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup/install_deps.sh
start=$(date +%s)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
echo "build: $(( $(date +%s) - start )) s"
start=$(date +%s)
ctest --test-dir build --output-on-failure -j2 --timeout 600
echo "tests: $(( $(date +%s) - start )) s"
tools/setup/fuzz_smoke.sh
