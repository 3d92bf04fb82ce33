#!/usr/bin/env bash
# ros2_names.sh PLEXUS VENDOR DOMAIN OUT ROS2_PACKAGE_DIR: the main job
# (deploy/scenarios/four_robots.yaml, every robot and service) in realtime under
# `plexus launch --naming ros2`, for 16 s. Beside it, on the same domain:
#  - `plexus topic list --json` in the default naming lists the names as they are on the
#    wire (no mapping back): wire.json. It lists what it discovered in 4 s, and must end
#    well before the run does: in a working-tree suite of 4d21bc2 (a 10 s run, a 2 s
#    listing, a loaded machine) it listed nothing; it had started 6.5 s into the run and
#    ended 5.7 s later, 1.8 s after the run. So the run lasts 16 s;
#  - `plexus record --naming ros2` records every topic, the CDR exactly as it arrived:
#    run.mcap (a recorder that did not speak ROS 2's names would find nothing to record).
# Then ros2_check.mjs parses the generated ROS 2 interface package with @foxglove/rosmsg,
# checks the wire names against ROS 2's mapping, and decodes the first samples of every topic
# with @foxglove/rosmsg2-serialization against the generated definitions; they must equal
# `plexus topic echo --recording --json`. Needs the npm packages of tests/ecosystem
# (tools/setup/install_npm.sh).
set -euo pipefail
plexus=$1 vendor=$2 domain=$3 out=$4 ros2=$5
here=$(cd "$(dirname "$0")" && pwd)
[ -d "$here/node_modules/@foxglove/rosmsg2-serialization" ] || { echo "npm packages missing: run tools/setup/install_npm.sh"; exit 1; }
[ -f "$ros2/package.xml" ] || { echo "$ros2: no generated ROS 2 package"; exit 1; }
rm -rf "$out" && mkdir -p "$out/echo"
"$plexus" launch "$here/../../deploy/scenarios/four_robots.yaml" --naming ros2 --set clock.mode=realtime \
  --set duration=16 --set metrics.0.from=15 --set metrics.1.from=15 --dds "$vendor" --domain "$domain" \
  --out "$out/run" --quiet > "$out/launch.log" 2>&1 &
launch=$!
# The services start within the first seconds; the recorder adds topics as their writers appear.
"$plexus" record --naming ros2 --dds "$vendor" --domain "$domain" -o "$out/run.mcap" --duration 8 \
  > "$out/record.log" 2>&1 &
record=$!
sleep 4
rc=0
# plexus param under ROS 2's names too; its reply on param/reply is one more recorded sample.
"$plexus" param list "localisation_observer wmr_observer" --naming ros2 --dds "$vendor" --domain "$domain" \
  > "$out/param.txt" 2>&1 || { echo "plexus param list under naming ros2:"; cat "$out/param.txt"; rc=1; }
grep -q "^wmr_observer.L " "$out/param.txt" || { echo "plexus param list: no wmr_observer.L"; rc=1; }
"$plexus" topic list --dds "$vendor" --domain "$domain" --json --wait 4 > "$out/wire.json"
wait "$record" || { echo "plexus record failed:"; cat "$out/record.log"; rc=1; }
wait "$launch" || {
  r=$?
  # A shortened main job misses its paper expectations (exit 1): the names and the samples are what is checked.
  [ $r -eq 1 ] || { tail -20 "$out/launch.log"; echo "plexus launch exit $r"; rc=1; }
}
[ $rc -eq 0 ] || exit 1
"$plexus" record info "$out/run.mcap" --json > "$out/info.json"
jq -r '.channels[].topic' "$out/info.json" | while read -r topic; do
  "$plexus" topic echo "$topic" --recording "$out/run.mcap" --json --count 5 > "$out/echo/${topic//\//__}.jsonl"
done
echo "$(jq '.topics' "$out/info.json") topics recorded under naming ros2; $(jq length "$out/wire.json") on the wire"
node "$here/ros2_check.mjs" "$out/run.mcap" "$ros2" "$out/echo" "$out/wire.json"
