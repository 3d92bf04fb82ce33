#!/usr/bin/env bash
# waits.sh BIN_DIR WORK DOMAIN: every wait has a bound and a message (issue 19).
#  1. a service waiting for a launcher's start signal gives up after --timeout, saying why;
#  2. a lockstep service with no clock says that there was never a clock;
#  3. `plexus replay --lockstep` with no clock gives up after --timeout, saying so;
#  4. a realtime launch whose observer's input has no writer (its plant declared --external and
#     never started) waits for it half of --timeout, then starts and says which process was
#     still matching (and a launch with every producer present starts without that warning).
set -u
bin=$1 work=$2 domain=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
params=$(dirname "$bin")/../deploy/params
[ -d "$params" ] || params=$(cd "$(dirname "$0")/../../deploy/params" && pwd)
fail() { echo "FAIL: $*"; exit 1; }
check() {  # check WANT_RC MAX_S REGEX CMD...: exit code, a bound on the time, one stderr line matching
  local want=$1 max=$2 regex=$3; shift 3
  local t0=$(date +%s.%N)
  err=$(timeout 60 "$@" 2>&1 >/dev/null); rc=$?
  local took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  echo "exit $rc after ${took} s: $err"
  [ $rc -eq "$want" ] || fail "expected exit $want"
  awk -v t="$took" -v m="$max" 'BEGIN { exit !(t < m) }' || fail "took ${took} s, bound ${max} s"
  echo "$err" | grep -Eq -- "$regex" || fail "stderr does not match: $regex"
}
check 2 20 "no start signal from plexus launch within 2 s" \
  "$bin/localisation_observer" --params "$params/heading_observer.yaml" --start-signal --timeout 2 --domain "$domain"
check 1 30 "lockstep: no clock: no step on 'lockstep/clock'" \
  "$bin/localisation_observer" --params "$params/heading_observer.yaml" --mode lockstep --timeout 2 --domain "$domain"
# A 1 s run misses the scenario's 60 s expectation (exit 1); the recording is what counts.
"$bin/plexus" launch "$(dirname "$params")/scenarios/unicycle_circle.yaml" --quiet --domain "$domain" \
  --set duration=1 --record rec.mcap --out rec > /dev/null 2>&1
[ -s rec.mcap ] || fail "recording a short run failed"
check 1 40 "plexus replay: failed: no lockstep clock on 'lockstep/clock' within 2 s" \
  "$bin/plexus" replay rec.mcap --lockstep --timeout 2 --wait 1 --domain "$domain"
# 4. Realtime start on readiness (docs/distributed.md): --timeout 4, so the launcher waits 2 s.
scen=$(dirname "$params")/scenarios/wmr_output_feedback_rfid.yaml
t0=$(date +%s.%N)
short=(--set clock.mode=realtime --set duration=1 --set metrics.0.from=0 --set metrics.1.from=0)
"$bin/plexus" launch "$scen" "${short[@]}" --external plant_simulator --timeout 4 \
  --domain "$domain" --out unmatched > unmatched.out 2> unmatched.err
rc=$?
took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
line=$(grep "starting with inputs not yet matched" unmatched.err)
echo "exit $rc after $took s: $line"
[[ "$line" == *"after 2 s: localisation_observer observer"* ]] ||
  fail "no warning naming the observer, whose input r1/position had no writer (stderr: $(tail -3 unmatched.err))"
awk -v t="$took" 'BEGIN { exit !(t < 30) }' || fail "the launch took $took s (bound 30 s)"
"$bin/plexus" launch "$scen" "${short[@]}" --timeout 4 --domain "$domain" --out matched \
  > /dev/null 2> matched.err
! grep -q "starting with inputs not yet matched" matched.err || fail "warned with every producer running: $(grep matched matched.err)"
echo "all waits bounded"
