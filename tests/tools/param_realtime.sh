#!/usr/bin/env bash
# param_realtime.sh BIN DEPLOY DOMAIN OUT VENDOR OTHER: `plexus param` on services started
# alone, with no launcher, in realtime (docs/parameters.md): paper 000's closed loop, the plant
# and the controller on VENDOR, the reference and the observer on OTHER, a recorder and the
# param tool on both. While `plexus record` records r1/heading and param/reply:
#  - param list names the observer's L with its value, from either vendor;
#  - param set L (one vendor) and k1 (the other) are acknowledged with a step, and get gives
#    the new values; a bad k1 is refused (exit 2) and k1 stays;
#  - in the recording, every estimate whose data time is before the acknowledged step's (the
#    reply's header) carries the old L in its gain field, and every one from it on the new L;
#  - `plexus param changes` finds both changes in the recording.
set -u
bin=$1 deploy=$2 domain=$3 out=$4 vendor=$5 other=$6
rm -rf "$out" && mkdir -p "$out"
observer="localisation_observer observer" controller="motion_controller controller"
pids=()
trap 'kill "${pids[@]}" 2> /dev/null; wait 2> /dev/null' EXIT
start() {  # start LOG PROGRAM ARGS...: a service alone
  local log=$1
  shift
  "$@" --domain "$domain" > /dev/null 2> "$out/$log.log" &
  pids+=($!)
}
start plant "$bin/plant_simulator" --params "$deploy/params/unicycle_robot.yaml" --dds "$vendor"
start reference "$bin/component_host" --name reference --params "$deploy/params/figure_eight_reference.yaml" --dds "$other"
start observer "$bin/localisation_observer" --name observer --params "$deploy/params/heading_observer.yaml" --dds "$other"
start controller "$bin/motion_controller" --name controller --params "$deploy/params/trajectory_tracking.yaml" --dds "$vendor"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
param() {
  local dds=$1
  shift
  "$bin/plexus" param "$@" --dds "$dds" --domain "$domain" --timeout 20
}
"$bin/plexus" record -o "$out/rt.mcap" --topics r1/heading,param/reply --dds "$vendor" --domain "$domain" \
  > "$out/record.log" 2>&1 &
recorder=$!

param "$vendor" list "$observer" > "$out/list.txt" 2>&1 || bad "param list (on $vendor): $(cat "$out/list.txt")"
grep -Eq "^observer.L +0.6 +observer gain" "$out/list.txt" || bad "param list: no observer.L 0.6: $(cat "$out/list.txt")"
sleep 1  # the recorder has seen some estimates with the old L
param "$vendor" set "$observer" L 2.5 --json > "$out/set_L.json" 2> "$out/set_L.err" || bad "param set L: $(cat "$out/set_L.err")"
param "$other" set "$controller" k1 0.05 --json > "$out/set_k1.json" 2> "$out/set_k1.err" ||
  bad "param set k1: $(cat "$out/set_k1.err")"
param "$other" set "$controller" k1 0 > "$out/set_bad.txt" 2>&1
rc=$?
[ "$rc" = 2 ] && grep -q "k1 must be finite and > 0 (got 0); controller.k1 stays 0.05" "$out/set_bad.txt" ||
  bad "param set k1 0 exited $rc: $(cat "$out/set_bad.txt")"
param "$other" get "$observer" L > "$out/get_L.txt" 2>&1
grep -qx "observer.L = 2.5" "$out/get_L.txt" || bad "param get L: $(cat "$out/get_L.txt")"
param "$vendor" get "$controller" k1 > "$out/get_k1.txt" 2>&1
grep -qx "controller.k1 = 0.05" "$out/get_k1.txt" || bad "param get k1: $(cat "$out/get_k1.txt")"
sleep 1  # and some with the new one
kill -INT $recorder
wait $recorder || bad "plexus record exited $?: $(tail -2 "$out/record.log")"
step_L=$(jq -r .step "$out/set_L.json" 2> /dev/null)
echo "acknowledged: L at step $step_L, k1 at step $(jq -r .step "$out/set_k1.json" 2> /dev/null)"

# The gain field against the acknowledged step's data time, from the recording.
"$bin/plexus" topic echo param/reply --recording "$out/rt.mcap" --json > "$out/replies.json" 2> "$out/echo.err" ||
  bad "topic echo param/reply: $(cat "$out/echo.err")"
"$bin/plexus" topic echo r1/heading --recording "$out/rt.mcap" --json > "$out/heading.json" 2>> "$out/echo.err" ||
  bad "topic echo r1/heading: $(cat "$out/echo.err")"
at=$(jq -r 'select(.key == "observer.L" and .operation == 2 and .status == 0) | .header.data_time_ns' "$out/replies.json" | head -1)
[ -n "$at" ] || bad "the recording holds no accepted change of observer.L"
jq -s --argjson at "${at:-0}" '{before: [.[] | select(.header.data_time_ns < $at) | .gain] | unique,
    after: [.[] | select(.header.data_time_ns >= $at) | .gain] | unique,
    n_before: [.[] | select(.header.data_time_ns < $at)] | length,
    n_after: [.[] | select(.header.data_time_ns >= $at)] | length}' "$out/heading.json" > "$out/boundary.json"
cat "$out/boundary.json" | jq -c .
jq -e '.before == [0.6] and .after == [2.5] and .n_before > 10 and .n_after > 10' "$out/boundary.json" > /dev/null ||
  bad "r1/heading's L is not 0.6 before the acknowledged step and 2.5 from it on"
"$bin/plexus" param changes "$out/rt.mcap" > "$out/changes.yaml" 2>&1
grep -q "key: observer.L, value: 2.5" "$out/changes.yaml" && grep -q "key: controller.k1, value: 0.05" "$out/changes.yaml" ||
  bad "param changes: $(cat "$out/changes.yaml")"
exit $fail
