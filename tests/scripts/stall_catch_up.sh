#!/usr/bin/env bash
# stall_catch_up.sh PLEXUS SCENARIO VENDOR DOMAIN OUT
#
# A stall of the whole machine in the middle of a realtime run (docs/distributed.md,
# "Overruns"): the 1 kHz arm of realtime_arm.cmake (plant in one process; reference, EKF and
# VDC in another), both processes stopped together for 30 ms (SIGSTOP / SIGCONT) at about
# 1.5 s, as a virtual machine's host stalls its guest. Checked, from the run's signals:
#  - physical time went on: the plant integrated the steps it missed, with the command it
#    held, where before it ran only the last 10 and the arm skipped the rest of its motion.
#    The run's recording may miss some of the samples the plant publishes at once after a
#    stall, so this is judged on the motion: across every gap of 5 steps or more in the
#    recorded truth, each joint moved as its velocity says (within 20 %), not by one step;
#  - the controller's missed steps published no command (its outputs held through them,
#    the command the plant applied), and it commanded again after the stall.
# Tracking after such a stall is reported, not bounded: with an injected 18 ms stall 12 of
# 14 runs stayed within Table 4's band (issue 33), which is not a pass/fail property.
set -u
plexus=$1 scenario=$2 vendor=$3 domain=$4 out=$5
rm -rf "$out" && mkdir -p "$out"
"$plexus" launch "$scenario" --json --quiet --domain "$domain" --out "$out/run" --dds "$vendor" \
  --set step=0.001 --set duration=3 --set clock.mode=realtime --set clock.input_deadline_periods=20 \
  --set services.reference.process=control --set services.observer.process=control \
  --set services.controller.process=control --set services.observer.blind_after_s=0.01 \
  > "$out/launch.json" 2> "$out/launch.err" &
launch=$!
plant="" control=""
for _ in $(seq 400); do
  plant=$(pgrep -f "plant_simulator .*--domain $domain( |$)" | head -1)
  control=$(pgrep -f "component_host .*--domain $domain( |$)" | head -1)
  [ -n "$plant" ] && [ -n "$control" ] && break
  sleep 0.025
done
if [ -z "$plant" ] || [ -z "$control" ]; then
  echo "FAIL: the run's two processes did not start: $(tail -3 "$out/launch.err")"
  kill "$launch" 2> /dev/null
  exit 1
fi
sleep 1.5
kill -STOP "$plant" "$control"
sleep 0.03
kill -CONT "$plant" "$control"
wait "$launch"
rc=$?
[ "$rc" -le 1 ] || { echo "FAIL: launch exited $rc: $(tail -3 "$out/launch.err")"; exit 1; }
fail=0
# gaps FILE: "first_missing..last_missing" per gap in the step column (2nd), one per line.
gaps() { awk -F, 'NR > 1 { if (NR > 2 && $2 != prev + 1) print prev + 1 ".." $2 - 1; prev = $2 }' "$1"; }
truth=$out/run/signals/arm.truth.state.csv cmd=$out/run/signals/arm.cmd.csv
truth_gaps=$(gaps "$truth") cmd_gaps=$(gaps "$cmd")
echo "truth: $(($(wc -l < "$truth") - 1)) steps, gaps: ${truth_gaps:-none}"
echo "commands: $(($(wc -l < "$cmd") - 1)) steps, gaps: ${cmd_gaps:-none}"
# Across each recorded gap of 5 steps or more: the joint moving faster moved as its mean
# velocity over the gap's time says (columns t, step, q1, q2, dq1, dq2).
jumps=$(awk -F, 'NR > 2 && $2 - s >= 5 {
    dt = $1 - t; e1 = (v1 + $5) / 2 * dt; e2 = (v2 + $6) / 2 * dt
    e = (e1 * e1 > e2 * e2) ? e1 : e2; a = (e1 * e1 > e2 * e2) ? $3 - q1 : $4 - q2
    d = a - e; if (d < 0) d = -d; if (e < 0) e = -e
    if (d > 0.2 * e + 1e-4) printf "steps %d..%d: moved %.5f rad, velocity says %.5f\n", s, $2, a, e }
    NR > 1 { t = $1; s = $2; q1 = $3; q2 = $4; v1 = $5; v2 = $6 }' "$truth")
[ -z "$jumps" ] || { echo "FAIL: the plant skipped motion, physical time did not go on through the stall: $jumps"; fail=1; }
# The stall: a gap of commands of at least 20 steps (30 ms stopped), and commands after it.
long=$(echo "$cmd_gaps" | awk -F'\\.\\.' '$0 != "" && $2 - $1 + 1 >= 20 { print; exit }')
if [ -z "$long" ]; then
  echo "FAIL: no gap of 20 or more commands: the controller's missed steps published commands"
  fail=1
else
  last=$(tail -1 "$cmd" | cut -d, -f2)
  end=${long#*..}
  [ "$last" -gt $((end + 500)) ] || { echo "FAIL: the controller did not command on after the stall"; fail=1; }
fi
echo "tracking after 1 s (reported, not bounded): $(jq -c '{rms_e1_steady_mrad, rms_e2_steady_mrad}' "$out/launch.json")"
[ $fail -eq 0 ] && echo PASS
exit $fail
