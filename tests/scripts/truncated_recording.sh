#!/usr/bin/env bash
# truncated_recording.sh PLEXUS DOMAIN OUT: a recording cut by 1 % is refused on open
# ("truncated or corrupt recording", exit 2, one line); the whole one replays.
set -u
plexus=$1 domain=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$plexus" launch "$(dirname "$0")/../../deploy/scenarios/unicycle_circle.yaml" --set duration=2 --quiet \
  --domain "$domain" --record "$out/run.sqlite" --out "$out/run" > /dev/null 2>&1
[ -s "$out/run.sqlite" ] || { echo "no recording made"; exit 1; }
size=$(stat -c %s "$out/run.sqlite")
head -c $((size * 99 / 100)) "$out/run.sqlite" > "$out/cut.sqlite"
exec "$(dirname "$0")/expect_exit.sh" 2 "cut.sqlite: truncated or corrupt recording \(SQLite: " \
  "$plexus" replay "$out/cut.sqlite" --domain "$domain" --wait 1
