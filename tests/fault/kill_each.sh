#!/usr/bin/env bash
# kill_each.sh PLEXUS THREE_ROBOTS ARM_SCENARIO OUT DOMAIN VENDOR [CASE...]
#
# Issue 14, process faults: SIGKILL of every service executable in turn, in realtime, one
# `plexus launch --kill PROCESS@T` per case on VENDOR (fast or cyclone). The killed service
# restarts 0.2 s after its death (`restart_delay`), so its output always pauses for longer
# than its consumers' input deadline and the safe output is always due. Each case checks,
# from the run's launch.json and signals/:
#   - the fault happened: the killed service's output paused past the input deadline;
#   - the safe output was applied, and how soon after the kill (reported; see below):
#       hold      a controller downstream held: the first all-zero command at the plant
#                 (launch.json fault.safe_command_after_s_by_command);
#       watchdog  the controller itself was killed: the plant applied the zero command
#                 (unicycle: the first step at which the robot stands still; the arm's
#                 applied torque is not published, so there the plant's stale reads are the
#                 evidence and no time is measured);
#       restart   nothing downstream closes a loop (the terrain classifier, the ICR EKF):
#                 no safe output is due;
#       plant     the plant simulator was killed (never restarted: the run fails after a
#                 1 s grace); every feedback controller's command goes to zero and stays;
#   - the launcher restarted it within 1 s of the kill (fault.respawned_after_s, the 0.2 s
#     restart delay included; the new process's first heartbeat is reported);
#   - the loop resumed: the output came back, the command is not the safe one at the end,
#     and the tracking error (or the balancing robot's tilt) over the last second is below
#     3/4 of its peak after the kill: a loop that did not resume lets the reference run away
#     (the error grows to the end, so its last second is its peak), while the unicycle's
#     gains (k = 0.11) take about 10 s to halve a tracking error.
# The safe output's time is bounded by the issue's two input deadlines; the bound is checked
# and reported as a figure, and a miss fails the case only with STRICT_TIMING=1 (a loaded
# machine delays loops by tens of ms; docs/distributed.md, Faults, gives the figures).
# CASE names (default: all): component_host localisation_observer motion_controller
# terrain_classifier icr_estimator attitude_filter joint_controller plant_simulator
# plant_simulator_arm.
set -u
plexus=$1 three=$2 arm=$3 out=$4 domain=$5 vendor=$6
shift 6
rm -rf "$out" && mkdir -p "$out"
# name | process to kill | scenario | kill at (s) | kind | killed output | command(s) | error
all_cases=(
  "component_host|wmr_reference|three|4|hold|wmr.reference|wmr.cmd|wmr"
  "localisation_observer|wmr_observer|three|4|hold|wmr.heading|wmr.cmd|wmr"
  "motion_controller|wmr_controller|three|4|watchdog|wmr.cmd|wmr.cmd|wmr"
  "terrain_classifier|skid_classifier|three|4|restart|skid.terrain|-|-"
  "icr_estimator|skid_ekf|three|4|restart|skid.icr|-|-"
  "attitude_filter|bal_ukf|three|4|hold|bal.attitude|bal.cmd|bal"
  "joint_controller|control|arm|2|watchdog|arm.cmd|arm.cmd|arm"
  "plant_simulator|plant_simulator|three|4|plant|-|wmr.cmd,bal.cmd|-"
  "plant_simulator_arm|plant_simulator|arm|2|plant|-|arm.cmd|-"
)
# The arm at 1 kHz as docs/distributed.md runs it in realtime: its EKF and VDC in one
# joint_controller process (`control`), the reference beside them, a 20-period deadline, the
# EKF blind 10 ms after its joint samples go stale (0.3 s by default: its controller's safe
# output came 0.32 s after the plant's death). Every loop at SCHED_FIFO 60, as the arm's
# other realtime tests run it (tests/repro/scripts/realtime_arm.cmake): a restarted process
# gets its priority again from its parameters.
arm_sets=(--set step=0.001 --set clock.input_deadline_periods=20 --set services.observer.process=control
          --set services.controller.process=control --set services.observer.blind_after_s=0.01
          --set clock.priority=60)
wanted=" $* "
fail=0
rows=()
# gap_after FILE STEP0: the largest step gap at or after step STEP0 and the first step after it.
gap_after() {
  awk -F, -v k0="$2" 'NR > 1 { if (prev >= 0 && $2 >= k0 && $2 - prev > gap) { gap = $2 - prev; next_step = $2 }
                               prev = $2 } BEGIN { prev = -1; gap = 0; next_step = -1 }
                      END { print gap, next_step }' "$1"
}
# period_steps FILE: the usual step spacing of a signal (its producer's period).
period_steps() { awk -F, 'NR == 2 { a = $2 } NR == 3 { print $2 - a; exit }' "$1"; }
# error_series KIND DIR: "t error" per step of the plant's truth (joined on the step: a
# realtime recording may miss a sample).
error_series() {
  local dir=$2/signals
  case $1 in
    wmr) awk -F, 'FNR == 1 { next } NR == FNR { rx[$2] = $3; ry[$2] = $4; next }
                  ($2 in rx) { print $1, sqrt(($3 - rx[$2])^2 + ($4 - ry[$2])^2) }' \
           "$dir/wmr.reference.csv" "$dir/wmr.truth.state.csv" ;;
    bal) awk -F, 'NR > 1 { print $1, ($5 < 0 ? -$5 : $5) * 57.29577951308232 }' "$dir/bal.truth.state.csv" ;;
    arm) awk -F, 'FNR == 1 { next } NR == FNR { r1[$2] = $3; r2[$2] = $4; next }
                  ($2 in r1) { print $1, sqrt(($3 - r1[$2])^2 + ($4 - r2[$2])^2) }' \
           "$dir/arm.reference.csv" "$dir/arm.truth.state.csv" ;;
  esac
}
for c in "${all_cases[@]}"; do
  IFS='|' read -r name proc scen at kind killed_sig commands err_kind <<< "$c"
  [ "$wanted" = "  " ] || [[ "$wanted" == *" $name "* ]] || continue
  run=$out/$name
  scenario=$three
  sets=()
  if [ "$scen" = arm ]; then scenario=$arm; sets=("${arm_sets[@]}"); fi
  if [ "$kind" != plant ]; then
    if [ "$proc" = control ]; then
      sets+=(--set services.observer.restart_delay=0.2 --set services.controller.restart_delay=0.2)
    else
      sets+=(--set "services.$proc.restart_delay=0.2")
    fi
  fi
  "$plexus" launch "$scenario" --dds "$vendor" --domain "$domain" --quiet --json --out "$run" --kill "$proc@$at" \
    --set clock.mode=realtime "${sets[@]}" > "$run.json" 2> "$run.log"
  rc=$?
  problems=()
  j=$run/launch.json
  if [ ! -s "$j" ]; then
    rows+=("$name | $vendor | launch exited $rc, no launch.json | FAIL")
    echo "FAIL $name: no launch.json (exit $rc)"; tail -5 "$run.log"; fail=1; continue
  fi
  truth=$run/signals/wmr.truth.state.csv
  [ "$scen" = arm ] && truth=$run/signals/arm.truth.state.csv
  step=$(awk -F, 'NR > 1 && $2 > 0 { printf "%.9g", $1 / $2; exit }' "$truth")  # the base step
  killed_at=$(jq -r '.fault.killed_at_s' "$j")
  deadline_periods=$(jq -r '.fault.input_deadline_periods' "$j")
  k_kill=$(awk -v t="$killed_at" -v s="$step" 'BEGIN { printf "%d", t / s }')
  safe="-" bound="-" respawn="-" beat="-" resumed="-" tracking="-"
  if [ "$kind" = plant ]; then
    failure=$(jq -r '.failure // ""' "$j")
    [ "$rc" -eq 1 ] && [[ "$failure" == plant_simulator*"exited with code 137" ]] ||
      problems+=("expected exit 1 naming the dead plant simulator, got exit $rc, failure '$failure'")
  else
    [ "$(jq -r '.failure // ""' "$j")" = "" ] || problems+=("the run failed: $(jq -r '.failure' "$j")")
    # The arm's scenario carries the paper's targets, which a run disturbed on purpose misses
    # (exit 1); three_robots.yaml has none.
    if [ "$scen" = arm ]; then [ "$rc" -le 1 ] || problems+=("launch exited $rc"); else
      [ "$rc" -eq 0 ] || problems+=("launch exited $rc"); fi
    restarts=$(jq '[.restarts[]] | add // 0' "$j")
    [ "$restarts" -ge 1 ] || problems+=("the launcher did not restart $proc")
    respawn=$(jq -r '.fault.respawned_after_s | if . == null then "null" else (. * 1000 | round / 1000) end' "$j")
    beat=$(jq -r '.fault.first_heartbeat_after_s | if . == null then "null" else (. * 1000 | round / 1000) end' "$j")
    awk -v r="$respawn" 'BEGIN { exit !(r != "null" && r <= 1.0) }' || problems+=("respawned ${respawn} s after the kill (> 1 s)")
    # The fault happened: the killed output paused past the deadline, then came back.
    sig=$run/signals/$killed_sig.csv
    p=$(period_steps "$sig")
    read -r gap next_step <<< "$(gap_after "$sig" "$((k_kill - p))")"
    need=$(awk -v d="$deadline_periods" -v p="$p" 'BEGIN { printf "%d", (d + 2) * p }')
    [ "$gap" -gt "$need" ] || problems+=("$killed_sig paused for only $gap steps (deadline $deadline_periods periods of $p steps): fault not exercised")
    if [ "$next_step" -ge 0 ]; then
      resumed=$(awk -v k="$next_step" -v s="$step" -v t="$killed_at" 'BEGIN { printf "%.3f", k * s - t }')
    else
      problems+=("$killed_sig never came back after the kill")
    fi
  fi
  # The loop resumed: the tracking error (the balancing robot's tilt) after the kill.
  fell=0
  if [ "$err_kind" != - ]; then
    tracking=$(error_series "$err_kind" "$run" | awk -v t0="$killed_at" '
        $1 >= t0 && $2 > peak { peak = $2 } { t = $1; e[NR] = $2; ts[NR] = $1; n = NR }
        END { for (i = n; i > 0 && ts[i] > t - 1; --i) { sum += e[i]; m++ }
              printf "%.3g %.3g %d", peak, (m ? sum / m : -1), (m && sum / m < 0.75 * peak) }')
    read -r peak last ok <<< "$tracking"
    tracking="peak $peak, last 1 s $last"
    if [ "$err_kind" = bal ]; then
      # The balancing robot must be upright again (a fallen one spins on: no floor in the
      # model). KNOWN FAILURE, reported and enforced only with STRICT_RECOVERY=1: it falls in
      # about 1 of 6 restarts of its attitude filter (measured 2026-11-27: 2 of 13, and 3 of 3
      # with a 0.1 s restart delay): its hold is zero torque, and an inverted pendulum tips
      # past recovery within the 0.4-0.8 s the filter is away (docs/distributed.md, Faults).
      # A fallen robot's attitude estimate leaves its physical range: the controller refuses
      # it at the edge and holds to the end, so its command stays the safe one (checked
      # below, and part of the same known failure).
      if [ "$ok" != 1 ] || ! awk -v l="$last" 'BEGIN { exit !(l < 10) }'; then
        fell=1
        echo "KNOWN FAILURE $name ($vendor): the balancing robot did not get up: mean tilt over the last second $last deg, peak $peak"
        [ "${STRICT_RECOVERY:-0}" = 1 ] && problems+=("the balancing robot did not get up (tilt $last deg)")
        tracking="$tracking (fell: known failure)"
      fi
    else
      [ "$ok" = 1 ] || problems+=("tracking did not resume: error over the last second $last, peak $peak after the kill")
    fi
  fi
  # The safe output and its bound, two input deadlines of the input that went stale.
  case $kind in
    hold|plant)
      for cmd in ${commands//,/ }; do
        topic=${cmd//./\/}
        s=$(jq -r --arg c "$topic" '.fault.safe_command_after_s_by_command[$c]' "$j")
        if [ "$s" = null ]; then problems+=("no safe (all-zero) $topic after the kill"); continue; fi
        stale_sig=$killed_sig
        [ "$kind" = plant ] && stale_sig=-
        p=1
        [ "$stale_sig" != - ] && p=$(period_steps "$run/signals/$stale_sig.csv")
        b=$(awk -v d="$deadline_periods" -v p="$p" -v s="$step" 'BEGIN { printf "%.3f", 2 * d * p * s }')
        safe=$([ "$safe" = - ] && echo "" || echo "$safe,")$(printf '%.3f' "$s")
        bound=$b
        if awk -v s="$s" -v b="$b" 'BEGIN { exit !(s > b) }'; then
          echo "$name: safe $topic ${s} s after the kill, over two input deadlines (${b} s)"
          [ "${STRICT_TIMING:-0}" = 1 ] && problems+=("safe $topic after ${s} s > ${b} s")
        fi
        last_zero=$(awk -F, 'END { z = 1; for (i = 3; i <= NF; ++i) if ($i != 0) z = 0; print z }' "$run/signals/$cmd.csv")
        if [ "$kind" = plant ]; then
          [ "$last_zero" = 1 ] || problems+=("$topic is not the safe command at the end: the controller did not keep holding")
        else
          if [ "$last_zero" = 1 ] && [ "$fell" = 1 ] && [ "${STRICT_RECOVERY:-0}" != 1 ]; then
            echo "KNOWN FAILURE $name ($vendor): $topic is still the safe command at the end (the robot fell)"
          elif [ "$last_zero" = 1 ]; then
            problems+=("$topic is still the safe command at the end: the loop did not resume")
          fi
        fi
      done ;;
    watchdog)
      if [ "$err_kind" = wmr ]; then
        # The unicycle stands still (pose unchanged from one step to the next) under the zero command.
        s=$(awk -F, -v k0="$k_kill" -v t="$killed_at" 'NR > 2 && $2 > k0 && $3 == x && $4 == y && $5 == th {
                 printf "%.3f", $1 - t; found = 1; exit } { x = $3; y = $4; th = $5 } END { if (!found) print "null" }' \
              "$run/signals/wmr.truth.state.csv")
        [ "$s" = null ] && problems+=("the robot never stood still after its controller was killed") || safe=$s
        bound=$(awk -v d="$deadline_periods" -v s="$step" 'BEGIN { printf "%.3f", 2 * d * s }')
        if [ "$s" != null ] && awk -v s="$s" -v b="$bound" 'BEGIN { exit !(s > b) }'; then
          echo "$name: zero command applied ${s} s after the kill, over two input deadlines (${bound} s)"
          [ "${STRICT_TIMING:-0}" = 1 ] && problems+=("zero command after ${s} s > ${bound} s")
        fi
      else
        stale=$(jq -r '[.services | to_entries[] | select(.key | startswith("plant_simulator")) | .value.stale_input_reads] | add' "$j")
        [ "$stale" -gt 0 ] || problems+=("the plant never found its command stale")
        safe="plant: $stale stale reads"
      fi ;;
  esac
  verdict=PASS
  if [ ${#problems[@]} -gt 0 ]; then
    verdict=FAIL
    fail=1
    for pr in "${problems[@]}"; do echo "FAIL $name ($vendor): $pr"; done
    grep -v "gain condition" "$run.log" | tail -3
  fi
  rows+=("$name | $vendor | $kind | $safe | $bound | $respawn | $beat | $resumed | $tracking | $verdict")
done
echo "case | vendor | kind | safe output after kill (s) | bound: 2 deadlines (s) | respawned after (s) | first heartbeat after (s) | output back after (s) | error (peak after kill, last 1 s) | result"
printf '%s\n' "${rows[@]}"
exit $fail
