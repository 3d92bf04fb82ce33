#!/usr/bin/env bash
# lockstep_stall.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# A lockstep run that stops on one process names that process's sample, whichever of the
# processes waiting on it times out first (docs/distributed.md, "Faults"; the launcher follows
# the chain of waits, tools/plexus/launch/failure_cause.hpp). The unicycle RFID loop
# (SCENARIO) on one host with --timeout 1; once the clock has run 200 steps, one service is
# frozen (SIGSTOP): the controller, then the observer. The plant waits for the controller's
# r1/cmd, the observer for the plant's r1/position, the controller for the observer's
# r1/heading, the clock for any of them: each of them can time out first. The run must fail
# (exit 1) with a line naming the frozen service's sample and the service
# (`no sample of 'r1/cmd' from 'controller'`, or the same reported by the process that waited
# for it: `(produced by 'controller')`), never a process that only waited in turn.
set -u
PLEXUS=$1 SCENARIO=$2 out=$3 domain=$4 vendor=$5
. "$(cd "$(dirname "$0")" && pwd)/clock_steps.sh"
rm -rf "$out" && mkdir -p "$out"
frozen=
listener=
cleanup() {
  [ -n "$frozen" ] && kill -CONT "$frozen" 2>/dev/null
  [ -n "$listener" ] && kill "$listener" 2>/dev/null
  return 0
}
trap cleanup EXIT
fail=0
echo "frozen | vendor | clock steps before | exit | failure line | result"
for c in "controller motion_controller r1/cmd" "observer localisation_observer r1/heading"; do
  read -r service program sample <<< "$c"
  run=$out/$service
  "$PLEXUS" launch "$SCENARIO" --dds "$vendor" --domain "$domain" --timeout 1 --quiet --set duration=600 \
    --out "$run" > "$run.out" 2> "$run.log" &
  launcher=$!
  steps=$out/$service.clock.csv
  "$PLEXUS" topic echo lockstep/clock --dds "$vendor" --domain "$domain" --csv --profile sensor --duration 60 \
    > "$steps" 2> /dev/null &
  listener=$!
  problems=()
  await_clock_steps "$steps" 200 "$launcher"
  seen=$SEEN
  kill "$listener" 2>/dev/null
  wait "$listener" 2>/dev/null
  listener=
  if [ "$seen" -lt 200 ]; then
    problems+=("the clock ran $seen steps within 60 s (nothing frozen)")
    kill "$launcher" 2>/dev/null
  else
    frozen=$(ps -o pid=,args= --ppid "$launcher" | awk -v p="$program" '{ n = $2; sub(".*/", "", n) } n == p { print $1 }')
    if [ -z "$frozen" ]; then
      problems+=("no $program child of the launcher")
      kill "$launcher" 2>/dev/null
    else
      kill -STOP "$frozen"
    fi
  fi
  wait "$launcher"
  rc=$?
  [ -n "$frozen" ] && kill -CONT "$frozen" 2>/dev/null
  frozen=
  msg=$(grep -m1 "^plexus launch: " "$run.log")
  [ "$rc" -eq 1 ] || problems+=("exit $rc (1 expected: the run fails)")
  re="no sample of '$sample' (from '$service'|\(produced by '$service'\)) for step [0-9]+ within 1 s"
  [[ "$msg" =~ $re ]] || problems+=("the failure does not name $service's $sample: '$msg'")
  verdict=PASS
  if [ ${#problems[@]} -gt 0 ]; then
    verdict=FAIL
    fail=1
    for p in "${problems[@]}"; do echo "FAIL $service ($vendor): $p"; done
    grep -v "gain condition" "$run.log" | tail -5
  fi
  echo "$service | $vendor | $seen | $rc | ${msg:-(none)} | $verdict"
done
exit $fail
