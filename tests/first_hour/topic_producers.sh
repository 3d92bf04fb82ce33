#!/usr/bin/env bash
# topic_producers.sh BIN PARAMS DOMAIN: what `plexus topic` says of a topic's writers.
# 1. `topic echo r1/position --type Pose2D` while the writer publishes PositionMeasurement
#    printed nothing for 6 s and exited 0: now one line naming both types, exit 2.
# 2. Two plant simulators of r1 (one on Fast DDS, one on Cyclone DDS) interleave on
#    r1/position (topic hz showed 179 Hz, silently): topic hz now warns, naming both processes,
#    as soon as discovery shows the second (it checks once a second while it runs), and so does
#    each of the two services, in its log, of the topics it writes.
set -u
bin=$1 params=$2 domain=$3
work=$(mktemp -d)
expect=$(dirname "$0")/../scripts/expect_exit.sh
pids=()
trap 'kill "${pids[@]}" 2> /dev/null; wait 2> /dev/null; rm -rf "$work"' EXIT
"$bin/plant_simulator" --params "$params" --step 0.01 --dds fast --domain "$domain" > /dev/null 2> "$work/plant.log" &
pids+=($!)
"$expect" 2 "^plexus topic: error: --type plexus::msg::Pose2D: the writers of 'r1/position' publish plexus::msg::PositionMeasurement" \
  "$bin/plexus" topic echo r1/position --type Pose2D --domain "$domain" --count 1 || exit 1
"$bin/plant_simulator" --params "$params" --step 0.01 --dds cyclone --domain "$domain" --service "plant_simulator twin" \
  > /dev/null 2> "$work/twin.log" &
pids+=($!)
err=$("$bin/plexus" topic hz r1/position --domain "$domain" --duration 3 2>&1 > /dev/null)
echo "$err"
echo "$err" | grep -q "r1/position has writers in 2 processes (plant_simulator r1, plant_simulator twin): their samples interleave" ||
  { echo "FAIL: no warning of the two writers"; exit 1; }
# The services themselves: each names the other process, once per topic it writes.
for log in plant twin; do
  grep -q "r1/position has writers in 2 processes (plant_simulator r1, plant_simulator twin): their samples interleave" \
    "$work/$log.log" || { echo "FAIL: the $log service did not warn of the other writer: $(head -c 600 "$work/$log.log")"; exit 1; }
  [ "$(grep -c "r1/position has writers" "$work/$log.log")" = 1 ] || { echo "FAIL: the $log service warned more than once"; exit 1; }
done
