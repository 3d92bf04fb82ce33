#!/usr/bin/env bash
# The fuzz smoke CI runs after the test suite (tools/setup/test.sh; docs/testing.md, "Fuzzing"):
# the fuzz build in build-fuzz/ (clang, ASan + UBSan: -DPLEXUS_FUZZ=ON, a build of its own so
# that the canonical build is unchanged; FUZZ_JOBS parallel compiles, default 2), then every
# target's smoke test (ctest label fuzz): the committed corpus replayed, then 10 s of fuzzing
# from it. FUZZ_BUILD_ONLY=1: the build alone (what CI runs beside the shared tests).
set -euo pipefail
cd "$(dirname "$0")/../.."
start=$(date +%s)
cmake -S . -B build-fuzz -DPLEXUS_FUZZ=ON -DPLEXUS_FUZZ_OPT=-O0  # a smoke: half the build of -O1 (cmake/PlexusFuzz.cmake)
cmake --build build-fuzz -j"${FUZZ_JOBS:-2}" --target fuzz  # the fuzz targets and what they link, nothing else
echo "fuzz build: $(( $(date +%s) - start )) s"
[ "${FUZZ_BUILD_ONLY:-0}" = 1 ] && exit 0
start=$(date +%s)
# Two at a time: each target fuzzes in one process, one core each.
ctest --test-dir build-fuzz --output-on-failure -j"${FUZZ_JOBS:-2}" -L fuzz
echo "fuzz smoke: $(( $(date +%s) - start )) s"
