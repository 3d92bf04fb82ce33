#!/usr/bin/env bash
# quiet_runs.sh PLEXUS SCENARIOS WORK DOMAIN VENDOR: a normal end of a run is quiet, and a
# configuration warning is said once per run (issue 19). A short realtime launch of paper
# 000's RFID loop (its gain-condition warning is due) must print:
#  - the short gain-condition warning exactly once (the launcher's), its details in summary.md;
#  - no liveliness warning when the run ends (every writer leaves), no "0 samples" latency line.
set -u
plexus=$1 scenarios=$2 work=$3 domain=$4 vendor=$5
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# The scenario's metrics start at 100 s: a 4 s run scores from 1 s (it misses the bounds: exit 1).
"$plexus" launch "$scenarios/wmr_output_feedback_rfid.yaml" --dds "$vendor" --domain "$domain" --quiet \
  --set clock.mode=realtime --set duration=4 --set metrics.0.from=1 --set metrics.1.from=1 \
  --out "$work/run" > "$work/out.txt" 2> "$work/err.txt"
rc=$?
cat "$work/err.txt"
[ $rc -le 1 ] || fail "launch exited $rc"
[ "$(cat "$work/run/status")" = complete ] || fail "run status: $(cat "$work/run/status")"
n=$(grep -c 'gain condition' "$work/err.txt")
[ "$n" -eq 1 ] || fail "the gain-condition warning was printed $n times"
grep -q 'gain condition (15) of paper 000 violated: k1^2 + k2^2' "$work/run/summary.md" || fail "no details in summary.md"
if grep -qi 'liveliness' "$work/err.txt"; then fail "liveliness warnings at the end of a normal run"; fi
if grep -q '(0 samples)' "$work/out.txt"; then fail "a '0 samples' latency line"; fi
grep -q 'latency sensor -> r1/cmd: p50' "$work/out.txt" || fail "the sensor->command latency line is missing"
# An open-loop run (a constant command: no sensor sample reaches it) has no latency to show.
"$plexus" launch "$scenarios/unicycle_circle.yaml" --dds "$vendor" --domain "$domain" --quiet \
  --set clock.mode=realtime --set duration=2 --out "$work/open" > "$work/open.txt" 2> "$work/open_err.txt"
[ $? -le 1 ] || fail "open-loop launch failed: $(cat "$work/open_err.txt")"
if grep -q '(0 samples)' "$work/open.txt"; then fail "a '0 samples' latency line: $(grep '0 samples' "$work/open.txt")"; fi
if grep -qi 'liveliness' "$work/open_err.txt"; then fail "liveliness warnings at the end of the open-loop run"; fi
echo "quiet run on $vendor: one warning, no shutdown noise"
