#!/usr/bin/env bash
# service_list.sh BIN DEPLOY DOMAIN OUT: `plexus service list` (docs/tools.md) finds two
# services started alone, with no launcher, on two vendors: a plant_simulator on Fast DDS
# and a localisation_observer on Cyclone DDS, listed by a Fast DDS and by a Cyclone DDS
# participant. Each row must name the process as plexus launch does ("plant_simulator r1";
# alone it used to be "plant_simulator r1/plant,r1/pos..."), with its heartbeat on
# health/<executable>_<name>, this machine's host name, state running (or degraded: a hold
# since the last heartbeat), a loop rate of the order of 100 Hz (the plant runs without
# --step: the params file's `step: 0.01`; it ran at 1 kHz before), a heartbeat seen during
# the wait, and its typed topics out and in.
# What is checked is what the command reports, not how well the loop keeps time: this test
# runs beside others (label light), and a starved loop skips ticks (its rate measured over
# the 1 Hz heartbeats fell to 91 Hz beside a SCHED_FIFO burner) and beats late. Hence the
# rate in 40..250 Hz (10 Hz or 1 kHz would be a wrong period) and an age under the 3 s wait;
# a CI run failed the former 80..120 Hz / 1.5 s / running-only bounds (2026-11-30).
set -u
bin=$1 deploy=$2 domain=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
pids=()
trap 'kill "${pids[@]}" 2> /dev/null; wait 2> /dev/null' EXIT
"$bin/plant_simulator" --params "$deploy/params/unicycle_robot.yaml" --dds fast --domain "$domain" \
  > /dev/null 2> "$out/plant.log" &
pids+=($!)
"$bin/localisation_observer" --params "$deploy/params/heading_observer.yaml" --dds cyclone --domain "$domain" \
  > /dev/null 2> "$out/observer.log" &
pids+=($!)
sleep 1
fail=0
host=$(hostname)
for vendor in fast cyclone; do
  "$bin/plexus" service list --dds "$vendor" --domain "$domain" --wait 3 --json > "$out/$vendor.json" 2> "$out/$vendor.err"
  rc=$?
  "$bin/plexus" service list --dds "$vendor" --domain "$domain" --wait 3 > "$out/$vendor.txt" 2>&1 || rc=$?
  [ "$rc" = 0 ] || { echo "FAIL ($vendor): plexus service list exited $rc"; cat "$out/$vendor.err"; fail=1; continue; }
  cat "$out/$vendor.txt"
  plant=$(jq -c '.[] | select(.name == "plant_simulator r1")' "$out/$vendor.json")
  [ -n "$plant" ] || { echo "FAIL ($vendor): no row 'plant_simulator r1': $(jq -c '[.[].name]' "$out/$vendor.json")"; fail=1; continue; }
  echo "$plant" | jq -e --arg h "$host" '.heartbeat_topic == "health/plant_simulator_r1" and .host == $h
      and (.state == "running" or .state == "degraded") and .loop_hz > 40 and .loop_hz < 250 and .uptime_s > 0
      and .heartbeat_age_s < 3
      and (.out | map(select(.topic == "r1/position" and .type == "plexus::msg::PositionMeasurement")) | length) == 1
      and (.in | map(.topic) | index("r1/cmd")) != null' > /dev/null ||
    { echo "FAIL ($vendor): plant row: $plant"; fail=1; }
  obs=$(jq -c '.[] | select(.executable == "localisation_observer")' "$out/$vendor.json")
  echo "$obs" | jq -e --arg h "$host" '(.name | test("^localisation_observer [a-z0-9_,]+$")) and .host == $h
      and (.state == "running" or .state == "degraded") and .heartbeat_topic == ("health/" + (.name | gsub(" "; "_")))
      and (.in | map(.topic) | index("r1/position")) != null' > /dev/null 2>&1 ||
    { echo "FAIL ($vendor): observer row: $obs"; fail=1; }
done
# The heartbeat as `plexus topic echo` prints it for reading: its state by name (issue 31);
# --json keeps the wire's integer, as every third-party decoder gives it.
for vendor in fast cyclone; do
  "$bin/plexus" topic echo health/plant_simulator_r1 --dds "$vendor" --domain "$domain" --count 1 > "$out/echo_$vendor.txt" 2>&1
  "$bin/plexus" topic echo health/plant_simulator_r1 --dds "$vendor" --domain "$domain" --count 1 --json > "$out/echo_$vendor.json" 2>&1
  grep -Eq '"state": "SERVICE_(RUNNING|DEGRADED)"' "$out/echo_$vendor.txt" ||
    { echo "FAIL ($vendor): topic echo does not name the heartbeat's state: $(grep -m1 '"state"' "$out/echo_$vendor.txt")"; fail=1; }
  jq -e '.state == 2 or .state == 3' "$out/echo_$vendor.json" > /dev/null 2>&1 ||
    { echo "FAIL ($vendor): topic echo --json: state is not the wire's integer: $(head -c 300 "$out/echo_$vendor.json")"; fail=1; }
done
exit $fail
