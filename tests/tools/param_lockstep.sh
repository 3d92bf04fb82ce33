#!/usr/bin/env bash
# param_lockstep.sh BIN DEPLOY DOMAIN OUT VENDOR CLI_VENDOR: `plexus param` during a lockstep
# launch of paper 000's RFID case (docs/parameters.md), the services on VENDOR, the param tool
# on CLI_VENDOR. While the run goes on it changes the observer's L and the controller's k1,
# and tries a bad L and an unknown key. Then it checks:
#  - the changes were acknowledged with a step, a bad one refused (exit 2, the validator's
#    reason) with the running value untouched, an unknown key named (exit 2);
#  - the estimate's gain field (r1/heading's L) is the old L at every step before the
#    acknowledged one and the new L from it on;
#  - the controller's command responds at its acknowledged step, not before: against a
#    `plexus sim` with only the L change, the first command that differs is at k1's step;
#  - the recording (--record) holds the changes: `plexus param changes` gives the scenario's
#    parameter_changes, and `plexus sim` with them reproduces the launch's digest, which
#    differs from the digest of the run without them.
set -u
bin=$1 deploy=$2 domain=$3 out=$4 vendor=$5 cli=$6
rm -rf "$out" && mkdir -p "$out"
# The paper's case without its expectations: how well the robot tracks after a change depends on
# the step the change lands on (the machine's speed), and the changes (k1 = 0.05 breaks gain
# condition (15)) may well miss the published bound; what is checked here is how they apply.
scenario=$out/wmr_output_feedback_rfid.yaml
sed '/^expectations:/,$d' "$deploy/scenarios/wmr_output_feedback_rfid.yaml" > "$scenario"
observer="localisation_observer observer" controller="motion_controller controller"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
param() { "$bin/plexus" param "$@" --dds "$cli" --domain "$domain" --timeout 20; }

# The run must outlast the seven param commands below (each a participant's discovery and a
# round trip, 1-2 s): 2160 s simulated, 216 000 steps, 14-30 s in lockstep on an idle machine
# since the steps run on the receive thread (2026-11-30; 720 s, the length before, ended in
# 5-7 s on Cyclone DDS and a command found no service). A run that ended first is named below.
run_s=2160
"$bin/plexus" launch "$scenario" --set duration=$run_s --dds "$vendor" --domain "$domain" -o "$out/run" \
  --record "$out/run.mcap" > "$out/launch.log" 2>&1 &
launch=$!
trap 'kill $launch 2> /dev/null; wait 2> /dev/null' EXIT

# The two changes go first, then the checks of refusals.
param get "$observer" L > "$out/get0.txt" 2>&1 || bad "param get L before the change: $(cat "$out/get0.txt")"
grep -qx "observer.L = 0.6" "$out/get0.txt" || bad "param get L: expected 'observer.L = 0.6', got: $(cat "$out/get0.txt")"
param set "$observer" L 2.5 --json > "$out/set_L.json" 2> "$out/set_L.err" || bad "param set L 2.5: $(cat "$out/set_L.err")"
step_L=$(jq -r '.step' "$out/set_L.json" 2> /dev/null)
param set "$controller" k1 0.05 --json > "$out/set_k1.json" 2> "$out/set_k1.err" ||
  bad "param set k1 0.05: $(cat "$out/set_k1.err")"
step_k1=$(jq -r '.step' "$out/set_k1.json" 2> /dev/null)
param set "$observer" L -1 > "$out/set_bad.txt" 2>&1
rc=$?
[ "$rc" = 2 ] || bad "param set L -1 exited $rc (expected 2): $(cat "$out/set_bad.txt")"
grep -q "must be finite and > 0 (got -1); observer.L stays 2.5" "$out/set_bad.txt" ||
  bad "param set L -1: not the validator's one line: $(cat "$out/set_bad.txt")"
param get "$observer" L > "$out/get1.txt" 2>&1
grep -qx "observer.L = 2.5" "$out/get1.txt" || bad "L after a refused change: $(cat "$out/get1.txt")"
param set "$controller" k9 1 > "$out/set_unknown.txt" 2>&1
rc=$?
[ "$rc" = 2 ] && grep -q "no tunable parameter 'k9' (tunable: controller.k1, controller.k2, controller.k3)" "$out/set_unknown.txt" ||
  bad "param set k9 (unknown) exited $rc: $(cat "$out/set_unknown.txt")"
param list "$controller" --json > "$out/list.json" 2> "$out/list.err" || bad "param list: $(cat "$out/list.err")"
[ "$(jq -r '[.[].key] | join(",")' "$out/list.json" 2> /dev/null)" = "controller.k1,controller.k2,controller.k3" ] ||
  bad "param list of the controller: $(cat "$out/list.json")"
kill -0 $launch 2> /dev/null ||
  bad "the lockstep run ended before the param commands did (the checks above then find no service): lengthen run_s"
wait $launch
rc=$?
trap - EXIT
[ "$rc" = 0 ] || { bad "the launch exited $rc"; tail -5 "$out/launch.log"; }
echo "acknowledged: L at step $step_L, k1 at step $step_k1"
[[ "$step_L" =~ ^[0-9]+$ && "$step_k1" =~ ^[0-9]+$ ]] || { bad "no acknowledged steps"; exit 1; }
grep -q "observer.L 0.6 -> 2.5 at step $step_L (plexus param set)" "$out/run/logs/localisation_observer_observer.log" ||
  bad "the observer's log does not hold the change"

# The estimate's gain: the old L before the acknowledged step, the new one from it on.
awk -F, -v s="$step_L" 'NR > 1 && (($2 < s && $6 != 0.6) || ($2 >= s && $6 != 2.5)) { print; n++ } END { exit n > 0 }' \
  "$out/run/signals/r1.heading.csv" > "$out/heading_wrong.txt" ||
  bad "r1/heading's L is not 0.6 before step $step_L and 2.5 from it: $(head -3 "$out/heading_wrong.txt")"

# The recording's changes replay the run: same digest in one process.
"$bin/plexus" param changes "$out/run.mcap" > "$out/changes.yaml" 2> "$out/changes.err" || bad "param changes: $(cat "$out/changes.err")"
cat "$out/changes.yaml"
grep -q "{step: $step_L, key: observer.L, value: 2.5}" "$out/changes.yaml" &&
  grep -q "{step: $step_k1, key: controller.k1, value: 0.05}" "$out/changes.yaml" ||
  bad "param changes does not give both acknowledged changes"
cat "$out/run/scenario.resolved.yaml" "$out/changes.yaml" > "$out/replay.yaml"  # the launch's scenario, as it ran
grep -v "controller.k1" "$out/replay.yaml" > "$out/replay_L.yaml"
"$bin/plexus" sim "$out/replay.yaml" -q -o "$out/sim" > /dev/null 2> "$out/sim.err" || bad "sim with the changes: $(cat "$out/sim.err")"
"$bin/plexus" sim "$out/replay_L.yaml" -q -o "$out/sim_L" > /dev/null 2> "$out/sim_L.err" || bad "sim with L: $(cat "$out/sim_L.err")"
"$bin/plexus" sim "$scenario" --set duration=$run_s -q -o "$out/sim_none" > /dev/null 2> "$out/sim_none.err" || bad "sim: $(cat "$out/sim_none.err")"
launched=$(jq -r .digest "$out/run/metrics.json") replayed=$(jq -r .digest "$out/sim/metrics.json")
unchanged=$(jq -r .digest "$out/sim_none/metrics.json")
echo "digests: launch $launched, sim with the recorded changes $replayed, sim without $unchanged"
[ "$launched" = "$replayed" ] || bad "the recorded changes do not reproduce the launch's digest"
[ "$launched" != "$unchanged" ] || bad "the changes changed nothing"
# The command responds to k1 at its step: the first r1/cmd row that differs from the run
# with only the L change.
first=$(paste -d, "$out/run/signals/r1.cmd.csv" "$out/sim_L/signals/r1.cmd.csv" |
  awk -F, 'NR > 1 && ($3 != $7 || $4 != $8) { print $2; exit }')
echo "first command that responds to k1: step ${first:-none}"
[ "$first" = "$step_k1" ] || bad "the command first responds to k1 at step ${first:-none}, not at its acknowledged step $step_k1"
exit $fail
