#!/usr/bin/env bash
# closed_loop_udp.sh FAMILY PLEXUS BIN_DIR VENDOR DOMAIN OUT_DIR DEPLOY_DIR
#
# Issue 30: a paper's closed loop through udp_bridge, with the device emulator on the far end,
# against the same scenario with plant_simulator, both in realtime under `plexus launch`, one
# after the other in this test (the reference measured beside the figure it judges):
#   skid_steer  paper 001's terrain switch (icr_terrain_switch_prior.yaml, shortened to 15 s
#               with the switch concrete -> tile at 10 s; `plexus sim`: 1.25 s, accuracy 1.0):
#               the ICRs' re-convergence after the switch within 10 % of plant_simulator's or
#               one classifier decision and one GPS period (0.25 + 0.05 s, its resolution),
#               and the classifier's accuracy within 10 %;
#   arm         paper 004's arm at 1 kHz (arm_vdc_ekf.yaml as repro.realtime.arm_vdc_ekf_1khz_*
#               runs it: reference, EKF and VDC in one process; the bridge with device time
#               and the cycle sync, docs/bridges.md "Cycle sync"; every loop of both runs at
#               SCHED_FIFO 60, the emulator's too, "Closed loops"): both joints settled within
#               Table 4's band (<= 0.36 / 0.37 s) in both runs, and the RMS errors within 20 %
#               of plant_simulator's; also the loop ran through the bridge (at least 90 % of
#               the run's commands obeyed, no sample refused) and the emulator followed the
#               cycle (a cycle frame every 0.5 s, none refused).
# The robot's source is udp_bridge on loopback (ports 40000 + 10*DOMAIN + {0,1}); `plexus
# launch` starts the bridge, and the emulator (unpaced, `--hold-until-command`: the plant holds
# its initial state until the first command, as plant_simulator's starts with the run) runs
# the robot's part of the scenario that the launch wrote. Both runs must exit 0 (or 1 with
# only the paper's expectations failing) and the emulator must exit 0 having obeyed commands.
# A run in which the machine stalled or starved one of the loops (its stall_stat, a wake-up
# lateness, over stall_us) is run again, three runs at most (the arm: a stall; the balancing
# robot: a starved run; the skid-steer's figures see neither). Prints both runs' figures and
# their ratios.
set -u
family=$1 plexus=$2 bin=$3 vendor=$4 domain=$5 out=$6 deploy=$7
case $family in
  skid_steer)
    robot=r1
    args=(--set duration=15 --set "robots.r1.plant.schedule=[[0, concrete], [10, tile]]" --set "expectations={}")
    # NAME:RELATIVE[:RESOLUTION]: the re-convergence is counted in the classifier's decisions
    # (hop_s 0.25 s: measured 1.0 and 1.25 s in realtime with either source) and tested at the
    # GPS updates (20 Hz); in realtime the switch falls anywhere in a decision's hop, so one
    # decision and one GPS period is the measurement's resolution, not a difference of the
    # sources (a clean-clone CI of 704d00e measured 0.99 s through the bridge against 1.25 s).
    checks="reconvergence_time_switch1_s:0.10:0.30 classifier_accuracy:0.10"
    device_time=""
    emulator_args=()
    stall_stat="" stall_us=""  # a loop of 20 Hz GPS and 4 Hz decisions: a stall does not show
    scenario=$deploy/scenarios/icr_terrain_switch_prior.yaml ;;
  balancing)
    robot=r1
    args=(--set "expectations={}")
    # Paper 002's tilt estimates (Fig. 4's statistics) with the LQR balancing on the augmented
    # UKF's, and how far the robot tilted.
    checks="ukf_error_std_deg:0.20 ekf_error_std_deg:0.20 max_abs_tilt_deg:0.20"
    # With device time and the cycle: stamped on arrival, the IMU's samples took the link's
    # jitter into their steps, and beside CI's other realtime tests the filters' error std
    # went 27-42 % over plant_simulator's (clean clone of bb70ed4).
    device_time=", device_time: true, cycle_sync: true"
    emulator_args=()
    # A run whose loops woke half a period late in 1 % of the ticks (the worst loop's p99
    # over 5 ms at 100 Hz) was not a realtime run: the machine starved it. Its commands reach
    # the plant late, the robot tilts more and the filters' errors grow, more through the
    # bridge's four extra hops than through plant_simulator. Measured (2026-11-30, burners
    # beside the runs; the UKF's error std, bridge / simulator, and the runs' p99): 1.004 at
    # 0.8 / 0.7 ms; 1.004 at 3.0 / 1.5 ms; 1.14 at 4.0 / 2.7 ms; 1.17 at 7.8 / 7.4 ms; and the
    # failure it was written for (working tree of 7ed022d, in CI's lanes): 1.63 at 5.9 / 0.7 ms.
    # 2.5 ms was too strict: in a clean clone's lanes beside a kill-each run three simulator
    # runs in a row were at 2.9-3.3 ms (figures that had passed in thirteen suites).
    stall_stat=jitter_p99_us stall_us=5000
    scenario=$deploy/scenarios/balance_ukf_ekf.yaml ;;
  arm)
    robot=arm
    args=(--set step=0.001 --set clock.input_deadline_periods=20 --set services.reference.process=control
          --set services.observer.process=control --set services.controller.process=control
          --set services.observer.blind_after_s=0.01 --set "expectations={}"
          --set clock.priority=60)
    emulator_args=(--priority 60)
    checks="rms_e1_mrad:0.20 rms_e2_mrad:0.20"
    device_time=", device_time: true, cycle_sync: true"
    # A loop that woke 10 periods late has dropped steps (the realtime host and the emulator
    # catch up at most 10): not a figure of the loop. Seen without SCHED_FIFO (the priorities
    # above) in about 1 run of 4, once harmful: the controller's host 18.6 ms late at 3.8 s,
    # the arm 17 mrad off for 0.3 s and the run's settling lost; with them, 1 in 8 (13 ms).
    stall_stat=jitter_max_us stall_us=10000
    scenario=$deploy/scenarios/arm_vdc_ekf.yaml ;;
  *) echo "closed_loop_udp.sh: FAMILY: skid_steer, balancing or arm"; exit 2 ;;
esac
rm -rf "$out" && mkdir -p "$out"
emu=""
launch=""
trap '[ -n "$emu" ] && kill -TERM $emu 2>/dev/null; [ -n "$launch" ] && kill -TERM $launch 2>/dev/null; wait 2>/dev/null' EXIT
run() {  # run NAME [ARGS...]: one realtime launch; its metrics in $out/NAME.json
  local name=$1 rc
  shift
  "$plexus" launch "$scenario" --set clock.mode=realtime "${args[@]}" "$@" --dds "$vendor" --domain "$domain" \
    --json --quiet --out "$out/$name" > "$out/$name.json" 2> "$out/$name.err" &
  launch=$!
}
finish() {  # finish NAME: waits for the launch; exit 0 or 1 (an expectation) accepted
  local rc
  wait $launch
  rc=$?
  launch=""
  if [ $rc -ne 0 ] && [ $rc -ne 1 ]; then echo "FAIL: the $1 run exited $rc"; tail -5 "$out/$1.err"; exit 1; fi
  [ -s "$out/$1.json" ] || { echo "FAIL: the $1 run printed no metrics"; tail -5 "$out/$1.err"; exit 1; }
}

stalled() {  # stalled NAME: true if a loop's stall_stat in the run was over stall_us (prints it)
  [ -n "$stall_us" ] || return 1
  local worst
  worst=$({ jq -r ".services[] | .$stall_stat" "$out/$1/launch.json"
            [ "$1" = bridge ] && jq -r ".$stall_stat" "$out/emulator.json" | tail -1; } 2> /dev/null |
          awk 'BEGIN { m = 0 } $1 + 0 > m { m = $1 + 0 } END { print m }')
  awk -v w="$worst" -v s="$stall_us" 'BEGIN { exit !(w > s) }' || return 1
  echo "the $1 run: a loop's $stall_stat was $(awk -v w="$worst" 'BEGIN { printf "%.1f", w / 1000 }') ms" \
       "(more than $(awk -v s="$stall_us" 'BEGIN { printf "%g", s / 1000 }') ms: the machine stalled or starved it," \
       "not the loop's figure); run again"
}

# 1. The reference, plant_simulator, and 2. the same through udp_bridge and the emulator. A run
# in which the machine stalled or starved a loop (stall_stat over stall_us) is not a figure of
# the loop: it is run again, at most three times in all; such a run is never judged.
pe=$((40000 + 10 * domain)) pb=$((40000 + 10 * domain + 1))
part="$out/bridge/parts/udp_bridge_$robot.yaml"
sim_done=0 bridge_done=0
for attempt in 1 2 3; do
  if [ $sim_done -eq 0 ]; then
    rm -rf "$out/simulator"
    run simulator
    finish simulator
    stalled simulator || sim_done=1
  fi
  if [ $bridge_done -eq 0 ]; then
    rm -rf "$out/bridge"
    run bridge --set "robots.$robot.source={type: udp_bridge, bind: 127.0.0.1:$pb, peer: 127.0.0.1:$pe$device_time}"
    for _ in $(seq 1 100); do [ -s "$part" ] && break; sleep 0.05; done
    [ -s "$part" ] || { echo "FAIL: the launcher wrote no part for udp_bridge $robot"; cat "$out/bridge.err"; exit 1; }
    "$bin/device_emulator" --part "$part" --udp-bind 127.0.0.1:$pe --udp-peer 127.0.0.1:$pb --baud 0 \
      --hold-until-command "${emulator_args[@]}" > "$out/emulator.json" 2> "$out/emulator.err" &
    emu=$!
    finish bridge
    kill -TERM $emu
    wait $emu
    emu_rc=$?
    emu=""
    [ "$emu_rc" -eq 0 ] || { echo "FAIL: the emulator exited $emu_rc"; tail -5 "$out/emulator.err"; exit 1; }
    stalled bridge || bridge_done=1
  fi
  [ $sim_done -eq 1 ] && [ $bridge_done -eq 1 ] && break
done
[ $sim_done -eq 1 ] && [ $bridge_done -eq 1 ] || { echo "FAIL: three stalled or starved runs (the machine is too busy)"; exit 1; }
commands=$(jq -r '.commands' "$out/emulator.json" 2> /dev/null | tail -1)
[ "${commands:-0}" -gt 0 ] 2> /dev/null || { echo "FAIL: the emulator obeyed no command"; exit 1; }
echo "emulator: $commands commands, $(jq -r '.frames_produced' "$out/emulator.json" | tail -1) frames," \
     "overruns $(jq -r '.overruns' "$out/emulator.json" | tail -1)"
[ -n "$device_time" ] && echo "emulator: cycle $(jq -c '.cycle' "$out/emulator.json" | tail -1)"
bridge_line=$(grep -ho "{\"service\":\"udp_bridge $robot\".*}" "$out/bridge/logs/"*.log 2> /dev/null | tail -1)
[ -n "$bridge_line" ] && echo "bridge: frames in $(jq -r '.link.frames_in' <<< "$bridge_line"), out" \
  "$(jq -r '.link.frames_out' <<< "$bridge_line"), frame-to-topic latency p50 $(jq -r '.link.latency_p50_us' <<< "$bridge_line") us," \
  "p99 $(jq -r '.link.latency_p99_us' <<< "$bridge_line") us"

# 3. The figures.
fail=0
missed=0
printf '%-32s %12s %12s %8s %14s\n' metric simulator bridge ratio bound
for check in $checks; do
  IFS=: read -r name tol res <<< "$check"
  s=$(jq -r ".$name" "$out/simulator.json") b=$(jq -r ".$name" "$out/bridge.json")
  verdict=$(awk -v s="$s" -v b="$b" -v t="$tol" -v res="${res:-0}" 'BEGIN {
    if (s == "null" || b == "null" || s != s + 0 || b != b + 0) { print "nan FAIL"; exit }
    r = (s == 0) ? (b == 0 ? 1 : 1e9) : b / s
    a = b - s; if (a < 0) a = -a
    d = (s == 0) ? (b == 0 ? 0 : 1e9) : a / s
    printf "%.3f %s", r, (d <= t || a <= res + 1e-9 ? "ok" : "FAIL") }')
  bound="+-$(awk -v t="$tol" 'BEGIN { printf "%g %%", 100 * t }')${res:+ or $res}"
  printf '%-32s %12.4g %12.4g %8s %14s %s\n' "$name" "$s" "$b" "${verdict% *}" "$bound" "${verdict#* }"
  [ "${verdict#* }" = ok ] || missed=1
done
if [ "$family" = arm ]; then
  for run in simulator bridge; do
    echo "$run: settling $(jq -r '.settling_time_1_s' "$out/$run.json") / $(jq -r '.settling_time_2_s' "$out/$run.json") s" \
         "(Table 4 <= 0.36 / 0.37), rms $(jq -r '.rms_norm_mrad' "$out/$run.json") mrad"
    for j in 1:0.36 2:0.37; do
      v=$(jq -r ".settling_time_${j%%:*}_s" "$out/$run.json")
      awk -v v="$v" -v b="${j##*:}" 'BEGIN { exit !(v != "null" && v + 0 == v && v <= b) }' || missed=1
    done
  done
  commands=$(jq -r '.commands' "$out/emulator.json" | tail -1)
  [ "$commands" -ge 4500 ] || { echo "FAIL: the emulator obeyed $commands commands (>= 4500 of the run's 5000)"; fail=1; }
  syncs=$(jq -r '.cycle.syncs' "$out/emulator.json" | tail -1) refused=$(jq -r '.cycle.refused' "$out/emulator.json" | tail -1)
  [ "$syncs" -ge 5 ] && [ "$refused" = 0 ] ||
    { echo "FAIL: the emulator followed $syncs cycle frames and refused $refused (>= 5 and 0 expected)"; fail=1; }
  rejected=$(jq -r '[.services[] | .rejected_inputs] | add' "$out/bridge/launch.json")
  [ "$rejected" = 0 ] || { echo "FAIL: $rejected samples refused"; fail=1; }
  awk -v r="$(jq -r '.rms_norm_mrad' "$out/bridge.json")" 'BEGIN { exit !(r + 0 == r && r < 100) }' ||
    { echo "FAIL: the arm through the bridge left 100 mrad of RMS error"; fail=1; }
fi
[ $missed -eq 0 ] || fail=1
[ $fail -eq 0 ] && echo PASS || echo FAIL
exit $fail
