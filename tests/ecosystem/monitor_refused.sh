#!/usr/bin/env bash
# monitor_refused.sh PLEXUS SCENARIO PORT OUT: `plexus launch --monitor PORT` refuses, with one
# line and exit 2 before any process starts (no run folder), a port that is taken and a
# lockstep run (the monitor is for realtime runs).
set -u
plexus=$1 scenario=$2 port=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
expect=$(dirname "$0")/../scripts/expect_exit.sh
python3 -c "import socket, time; s = socket.socket(); s.bind(('127.0.0.1', $port)); s.listen(); time.sleep(30)" &
holder=$!
trap 'kill $holder 2> /dev/null' EXIT
for _ in $(seq 50); do ss -ltn | grep -q "127.0.0.1:$port " && break; sleep 0.1; done
"$expect" 2 "^plexus launch: error: --monitor $port: cannot listen on 127.0.0.1:$port: " \
  "$plexus" launch "$scenario" --set clock.mode=realtime --monitor "$port" --domain 214 --out "$out/busy" --quiet || exit 1
[ ! -e "$out/busy" ] || { echo "FAIL: a run folder was made: something started"; exit 1; }
"$expect" 2 "^plexus launch: error: --monitor: realtime runs only" \
  "$plexus" launch "$scenario" --monitor "$((port + 1))" --domain 214 --out "$out/lockstep" --quiet || exit 1
[ ! -e "$out/lockstep" ] || { echo "FAIL: a run folder was made: something started"; exit 1; }
