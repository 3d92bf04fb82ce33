#!/usr/bin/env bash
# The README's second command: install dependencies, build once, run the whole test suite
# in parallel (slow tests carry the ctest label "slow"; every DDS test has its own domain),
# and the fuzz targets' smoke runs (tools/setup/fuzz_smoke.sh: a second build, with clang).
#
# Three phases, so that nothing runs beside a test that needs the machine to itself:
#  1. the exclusive tests: RUN_SERIAL and labelled realtime (wall-clock loops whose figures
#     are checked), and those labelled light (they mostly wait on the wall clock), with
#     nothing CPU-bound on the machine: six at a time (each takes 1-25 % of the machine), one
#     at a time among those labelled `heavy` or `alone` and among the netns ones
#     (PLEXUS_REALTIME_LANES; cmake/PlexusTesting.cmake, plexus_realtime_lanes); ctest's log
#     of the phase, with every test's output, is kept as build/LastTest_exclusive.log;
#  2. every other test (ctest -j2; the other RUN_SERIAL tests, netns and multi-host ones, one
#     at a time among them), with the fuzz build beside under SCHED_IDLE (chrt --idle: only
#     the CPU time the tests leave idle; one compile at a time);
#  3. the rest of the fuzz build (-j2), then the fuzz smoke runs.
# Why: two clean-clone CI runs (2026-11-27) ran the fuzz build beside the exclusive tests and
# failed the 1 kHz arm loop across two processes (Table 4's band); on this 2-vCPU machine
# even a SCHED_IDLE compile slows a realtime loop's processes (measured: 274-479 late reads
# instead of 20-80, the serial bridge's device watchdog tripping; docs/testing.md, "CI").
set -euo pipefail
cd "$(dirname "$0")/../.."
tools/setup/install_deps.sh
tools/setup/install_npm.sh  # third-party readers the ecosystem tests check plexus's files with
start=$(date +%s)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
echo "build: $(($(date +%s) - start)) s"

# The test numbers of each phase, from ctest's own listing (RUN_SERIAL and LABELS per test).
ctest --test-dir build --show-only=json-v1 > build/tests.json
phase_tests() {  # phase_tests exclusive|shared: comma-separated ctest test numbers
  jq -r --arg want "$1" '[.tests | to_entries[]
      | (.value.properties // []) as $p
      | ((any($p[]; .name == "RUN_SERIAL" and .value == true)
          and any($p[]; .name == "LABELS" and (.value | index("realtime"))))
         or any($p[]; .name == "LABELS" and (.value | index("light")))) as $exclusive
      | select(($want == "exclusive") == $exclusive) | .key + 1] | join(",")' build/tests.json
}
exclusive=$(phase_tests exclusive)
shared=$(phase_tests shared)

# Each phase's failed tests, kept so that the last lines of this script's output name them
# (a CI log is often read from its tail, and the shared phase's output pushes the exclusive
# phase's failures far up).
failed_log=build/Testing/Temporary/LastTestsFailed.log
keep_failures() {  # keep_failures PHASE: copy ctest's list of the phase's failed tests
  if [ -s "$failed_log" ]; then cp "$failed_log" "build/failed_$1.log"; else : > "build/failed_$1.log"; fi
}

# The test domains' participant ports (0-31) out of the kernel's ephemeral port range while the
# suite runs, so that no socket bound to "any port" can take one. plexus's own Cyclone DDS
# participants move off such a port by themselves; third-party Cyclone DDS programs the tests
# run (ddsperf, the native interop programs) cannot, and a Fast DDS participant of another
# test's domain would be seen by them (docs/runtime.md, "Domains on one host"). As root only;
# the previous setting comes back at the end. Also the fixed UDP ports the bridge tests bind
# (40000 + 10 * domain + {0,1}; udp_bind_busy's 47991): inside the ephemeral range, another
# test's socket bound to "any port" took 40311 once (2026-11-30, closed_loop_balancing_udp_fast:
# "cannot bind: Address already in use" for the whole run, the emulator obeyed no command).
reserved_before=""
if [ "$(id -u)" -eq 0 ] && reserved_before=$(sysctl -n net.ipv4.ip_local_reserved_ports 2> /dev/null); then
  sysctl -qw net.ipv4.ip_local_reserved_ports="$(for d in $(seq 0 232); do
    printf '%d-%d,' $((7410 + 250 * d)) $((7473 + 250 * d)); done)40000-42339,47991" ||
    echo "test.sh: could not reserve the DDS participant ports (sysctl); tests run without"
  trap 'sysctl -qw net.ipv4.ip_local_reserved_ports="$reserved_before"' EXIT
fi

suite_rc=0
start=$(date +%s)
rm -f "$failed_log"
lanes=6  # docs/testing.md, "Realtime lanes": 4 until 2026-11-29 (a 31-minute CI), 5 until 2026-11-30
[ -z "$exclusive" ] || PLEXUS_REALTIME_LANES=$lanes ctest --test-dir build --output-on-failure -j$lanes --timeout 600 \
  -I "0,0,0,$exclusive" || suite_rc=$?
keep_failures exclusive
cp build/Testing/Temporary/LastTest.log build/LastTest_exclusive.log 2> /dev/null || true
echo "exclusive tests: $(($(date +%s) - start)) s"

start=$(date +%s)
mkdir -p build-fuzz
FUZZ_BUILD_ONLY=1 FUZZ_JOBS=1 setsid chrt --idle 0 tools/setup/fuzz_smoke.sh > build-fuzz/build_beside.log 2>&1 &
fuzz_build=$!
rm -f "$failed_log"
ctest --test-dir build --output-on-failure -j2 --timeout 600 -I "0,0,0,$shared" || suite_rc=$?
keep_failures shared
echo "shared tests (fuzz build beside): $(($(date +%s) - start)) s"

# The fuzz build continues in the foreground with both cores (make resumes where the idle
# one stopped), then the smoke runs.
kill -- -"$fuzz_build" 2> /dev/null || true
wait "$fuzz_build" 2> /dev/null || true
fuzz_rc=0
FUZZ_JOBS=2 tools/setup/fuzz_smoke.sh || fuzz_rc=$?
for phase in exclusive shared; do
  while IFS=: read -r number name; do
    echo "FAILED in the $phase phase: test $number, $name (its output is above)"
  done < "build/failed_$phase.log"
done
echo "suite exit $suite_rc, fuzz smoke exit $fuzz_rc"
[ "$suite_rc" -eq 0 ] && [ "$fuzz_rc" -eq 0 ]
