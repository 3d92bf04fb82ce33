#!/usr/bin/env bash
# waits.sh BIN_DIR WORK DOMAIN: every wait has a bound and a message (issue 19).
#  1. a service waiting for a launcher's start signal gives up after --timeout, saying why;
#  2. a lockstep service with no clock says that there was never a clock;
#  3. `plexus replay --lockstep` with no clock gives up after --timeout, saying so.
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
  --set duration=1 --record rec.sqlite --out rec > /dev/null 2>&1
[ -s rec.sqlite ] || fail "recording a short run failed"
check 1 40 "plexus replay: failed: no lockstep clock on 'lockstep/clock' within 2 s" \
  "$bin/plexus" replay rec.sqlite --lockstep --timeout 2 --wait 1 --domain "$domain"
echo "all waits bounded"
