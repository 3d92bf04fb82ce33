#!/usr/bin/env bash
# run_folders.sh PLEXUS SCENARIO WORK DOMAIN: what a run folder promises (issue 19).
#  1. two runs started at once without --out get two folders (names unique within a second);
#  2. --out on an earlier run's folder empties it first (nothing of that run stays), and
#     --out on a non-empty folder that is not a run folder is refused (exit 2), untouched;
#  3. Ctrl-C on `plexus launch` says "interrupted", exits 130 and marks the folder incomplete.
set -u
plexus=$1 scenario=$2 work=$3 domain=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
# Short runs miss the scenario's 60 s expectation: exit 1 is a run that completed.
sim() { "$plexus" sim "$scenario" --quiet "$@" > /dev/null 2>&1; [ $? -le 1 ]; }

sim --set duration=1 &
sim --set duration=1 &
wait
n=$(ls runs | wc -l)
echo "two runs at once: $n folders: $(ls runs | tr '\n' ' ')"
[ "$n" -eq 2 ] || fail "expected 2 run folders"
for d in runs/*; do [ "$(cat "$d/status")" = complete ] || fail "$d/status is not complete"; done

sim --set duration=1 --out again || fail "first run into again/"
touch again/left_over_from_the_first_run
sim --set duration=2 --out again || fail "second run into again/"
[ ! -e again/left_over_from_the_first_run ] || fail "--out kept a file of the earlier run"
grep -q 'duration 2 s' again/summary.md || fail "again/summary.md is not the second run's"

mkdir -p mine; echo precious > mine/notes.txt
err=$("$plexus" sim "$scenario" --quiet --set duration=1 --out mine 2>&1 >/dev/null); rc=$?
echo "--out mine: exit $rc: $err"
[ $rc -eq 2 ] || fail "--out on a foreign folder: expected exit 2"
echo "$err" | grep -q 'is not a plexus run folder' || fail "the refusal does not say why"
[ "$(cat mine/notes.txt)" = precious ] || fail "the foreign folder was touched"

# Long enough never to end before the Ctrl-C: 600 s of this open-loop scenario took 1.7-3.3 s
# in lockstep once the steps ran on the receive thread (2026-11-30); 6000 s take 17-33 s.
"$plexus" launch "$scenario" --quiet --domain "$domain" --set duration=6000 --out interrupted > launch.out 2> launch.err &
pid=$!
for _ in $(seq 1 300); do  # up to 30 s for the run to start (the status line needs processes up)
  grep -q 'started pid' interrupted/logs/*.log 2>/dev/null && break
  sleep 0.1
done
sleep 2
kill -INT $pid
wait $pid; rc=$?
echo "launch after SIGINT: exit $rc; $(tail -1 launch.err)"
[ $rc -eq 130 ] || fail "expected exit 130 after Ctrl-C"
tail -1 launch.err | grep -q '^plexus launch: interrupted (SIGINT)' || fail "no 'interrupted' line"
[ "$(cat interrupted/status)" = "interrupted (SIGINT)" ] || fail "status: $(cat interrupted/status)"
[ ! -e interrupted/metrics.json ] || fail "an interrupted run was scored"
err=$("$plexus" report interrupted 2>&1 >/dev/null); rc=$?
echo "report of the interrupted run: exit $rc: $err"
[ $rc -eq 2 ] && echo "$err" | grep -q 'the run did not complete (interrupted (SIGINT))' || fail "report of an interrupted run"
echo "all run-folder checks passed"
