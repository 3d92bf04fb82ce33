#!/usr/bin/env bash
# truncated_recording.sh PLEXUS DOMAIN OUT: a recording cut by 1 %: SQLite is refused on open
# ("truncated or corrupt recording", exit 2, one line); MCAP is read up to the cut, with one
# warning line (`plexus replay --summary` exit 0). The whole ones replay.
set -u
plexus=$1 domain=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
scenario="$(dirname "$0")/../../deploy/scenarios/unicycle_circle.yaml"
for ext in sqlite mcap; do
  "$plexus" launch "$scenario" --set duration=2 --quiet --domain "$domain" --record "$out/run.$ext" --out "$out/run_$ext" \
    > /dev/null 2>&1
  [ -s "$out/run.$ext" ] || { echo "no $ext recording made"; exit 1; }
  size=$(stat -c %s "$out/run.$ext")
  head -c $((size * 99 / 100)) "$out/run.$ext" > "$out/cut.$ext"
done
"$plexus" replay --summary "$out/cut.mcap" > "$out/mcap.out" 2> "$out/mcap.err" || { cat "$out/mcap.err"; echo "cut MCAP refused"; exit 1; }
cat "$out/mcap.err"
[ "$(grep -c . "$out/mcap.err")" -eq 1 ] && grep -q "cut.mcap: .*replaying the [0-9]* samples before the cut" "$out/mcap.err" ||
  { echo "expected one warning line for the cut MCAP recording"; exit 1; }
exec "$(dirname "$0")/expect_exit.sh" 2 "cut.sqlite: truncated or corrupt recording \(SQLite: " \
  "$plexus" replay "$out/cut.sqlite" --domain "$domain" --wait 1
