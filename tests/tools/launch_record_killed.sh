#!/usr/bin/env bash
# launch_record_killed.sh PLEXUS SCENARIO VENDOR DOMAIN WORK_DIR: `plexus launch --record`
# SIGKILLed mid-run (a lockstep run of SCENARIO) leaves its MCAP recording cut short but
# readable: `plexus record info` says so and counts samples of every signal topic, and
# `plexus replay --summary` reads up to the cut with one warning line.
set -u
plexus=$1 scenario=$2 vendor=$3 domain=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
rec=$work/run.mcap
launcher=
cleanup() { [ -n "$launcher" ] && kill -9 "$launcher" 2> /dev/null; return 0; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
# Long enough never to end before it is killed: 600 s of unicycle_circle took 1.7 s on Cyclone
# DDS in lockstep once the steps ran on the receive thread (2026-11-30); 6000 s take about 17 s.
"$plexus" launch "$scenario" --set duration=6000 --dds "$vendor" --domain "$domain" --record "$rec" --out "$work/run" \
  --quiet > "$work/launch.log" 2>&1 &
launcher=$!
chunks=0
for _ in $(seq 1 600); do
  chunks=$("$plexus" record info "$rec" --json 2> /dev/null | jq -r '.chunks // 0' 2> /dev/null)
  [ "${chunks:-0}" -ge 3 ] && break
  kill -0 "$launcher" 2> /dev/null || { cat "$work/launch.log"; fail "the launch ended before it recorded"; }
  sleep 0.1
done
[ "${chunks:-0}" -ge 3 ] || fail "the recording has $chunks chunks after 60 s"
kill -KILL "$launcher"
wait "$launcher" 2> /dev/null
launcher=
info=$("$plexus" record info "$rec" --json) || fail "record info refused the cut recording"
echo "$info" | jq -c '{complete, cut_short, messages, topics, chunks}'
# Every signal's topic has samples (param/reply holds the answers to plexus param: none here).
echo "$info" | jq -e '.complete == false and .messages > 0
    and ([.channels[] | select(.topic != "param/reply") | .messages] | min) > 0' > /dev/null ||
  fail "expected a cut-short recording with samples of every signal's topic"
"$plexus" replay --summary "$rec" > "$work/summary.out" 2> "$work/summary.err" || fail "replay --summary exited $?"
cat "$work/summary.err"
[ "$(grep -c . "$work/summary.err")" -eq 1 ] && grep -q "no footer" "$work/summary.err" || fail "expected one warning line"
[ "$(grep -c . "$work/summary.out")" -eq "$(echo "$info" | jq -r .topics)" ] || fail "replay --summary lists another number of topics"
echo "killed launcher: $(echo "$info" | jq -r .messages) samples up to the cut, readable"
