#!/usr/bin/env bash
# The README's second command: install dependencies, build once, run the whole test suite
# in parallel (slow tests carry the ctest label "slow"; every DDS test has its own domain),
# and the fuzz targets' smoke runs (tools/setup/fuzz_smoke.sh: a second build, with clang).
#
# The fuzz build and smoke run beside the suite under SCHED_IDLE (chrt --idle): they get only
# the CPU time the suite leaves idle, which is most of a core while its RUN_SERIAL realtime
# tests run one at a time, and they never take CPU from a test's loops. One job at a time
# (-j1): a second SCHED_IDLE job would fill the core a serial realtime test's processes wake
# on (a CI run beside -j2 saw pty stalls and a 1 kHz arm loop outside Table 4's band).
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup/install_deps.sh
start=$(date +%s)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
echo "build: $(( $(date +%s) - start )) s"
start=$(date +%s)
chrt --idle 0 tools/setup/fuzz_smoke.sh > build/fuzz_smoke.log 2>&1 &
fuzz=$!
suite_rc=0
ctest --test-dir build --output-on-failure -j2 --timeout 600 || suite_rc=$?
echo "tests: $(( $(date +%s) - start )) s"
fuzz_rc=0
wait "$fuzz" || fuzz_rc=$?
cat build/fuzz_smoke.log
echo "tests and fuzz smoke: $(( $(date +%s) - start )) s (fuzz smoke exit $fuzz_rc)"
[ "$suite_rc" -eq 0 ] && [ "$fuzz_rc" -eq 0 ]
