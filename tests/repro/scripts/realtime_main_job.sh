#!/usr/bin/env bash
# realtime_main_job.sh PLEXUS SCENARIO OUT DOMAIN VENDOR [DURATION]: the main job
# (four_robots.yaml) in realtime, shortened to DURATION s (default 45: the skid-steer robot's
# first terrain switch is at 40 s), as the README runs it (the arm a loop group).
# What it asserts, on a loaded machine too:
#  - every process ran the whole run (its loop ticked at least 90 % of the run's 10 ms periods:
#    every host of the main job ticks at 100 Hz or faster) and the skid-steer's services
#    refused no sample;
#  - the skid-steer's figures of paper 001 as in lockstep: ICRs re-converged within 3 s of the
#    switch (lockstep: 1.0 s) and terrain classified with accuracy >= 0.95 (lockstep: 1.0).
#    Its estimators use each sample at its own step (docs/distributed.md, "Late samples"), so
#    these do not depend on when the samples arrive;
#  - overruns: at most 5 % of each process's loop ticks (a loop that cannot keep its period
#    at all). Issue 35's bound, 0.1 % per service, is a timing goal: printed, and enforced
#    with STRICT_TIMING=1 (as every realtime timing goal of the suite, docs/testing.md).
#  - the arm's figures of paper 004 Table 4 as in lockstep: its 1 kHz loop is a loop group
#    (one process, `loops:` in the scenario), so it settles within Table 4's band (<= 0.36 /
#    0.37 s; lockstep 0.123 / 0.122 s), and its RMS error and peak torque stay within the
#    bounds tests/repro/four_robots.sh puts around lockstep's (Table 4's RMS and peak torque
#    are missed in lockstep too: docs/algorithms/arm.md);
#  - the loop's timing budget was checked: launch.json has the verdict for loop 'arm'.
set -u
plexus=$1 scenario=$2 out=$3 domain=$4 vendor=$5 duration=${6:-45}
rm -rf "$out"
mkdir -p "$out"
from=$((duration - 10))
"$plexus" launch "$scenario" --set clock.mode=realtime --set duration="$duration" \
  --set metrics.0.from=$from --set metrics.1.from=$from \
  --dds "$vendor" --json --quiet --domain "$domain" --out "$out/launch" > "$out/metrics.json" 2> "$out/stderr.txt"
rc=$?
if [ "$rc" -ne 0 ] && [ "$rc" -ne 1 ]; then
  echo "plexus launch exited $rc"; tail -20 "$out/stderr.txt"; exit 1
fi
j=$out/launch/launch.json
[ -s "$j" ] || { echo "no launch.json"; tail -20 "$out/stderr.txt"; exit 1; }
fail=0
# The processes' loops: ticks, overruns, late and stale reads, refused samples.
min_ticks=$((duration * 90))
printf '%-52s %8s %8s %8s %8s %8s\n' process ticks overruns '%' late stale
while IFS=$'\t' read -r name ticks overruns late stale rejected; do
  pct=$(awk -v o="$overruns" -v t="$ticks" 'BEGIN { printf "%.3f", (t > 0 ? 100 * o / t : 100) }')
  printf '%-52s %8s %8s %8s %8s %8s\n' "$name" "$ticks" "$overruns" "$pct" "$late" "$stale"
  if awk -v p="$pct" 'BEGIN { exit !(p > 5) }'; then echo "  $name: overruns above 5 % of its ticks"; fail=1; fi
  if [ "${STRICT_TIMING:-0}" = 1 ] && awk -v p="$pct" 'BEGIN { exit !(p > 0.1) }'; then
    echo "  $name: overruns above 0.1 % of its ticks (STRICT_TIMING)"; fail=1
  fi
  [ "$ticks" -ge "$min_ticks" ] || { echo "  $name: $ticks loop ticks, fewer than $min_ticks"; fail=1; }
  case "$name" in
    *skid*) [ "$rejected" -eq 0 ] || { echo "  $name: $rejected refused samples"; fail=1; } ;;
  esac
done < <(jq -r '.services | to_entries[] | [.key, .value.loop_count, .value.overruns, .value.late_input_reads,
                .value.stale_input_reads, .value.rejected_inputs] | @tsv' "$j")
# The estimators' late samples (services' closing lines, when the log has them).
grep -ho '[0-9]* estimator steps run after their tick, [0-9]* late samples dropped or bridged' "$out"/launch/logs/*.log |
  sed 's/^/  /' || true
m=$out/metrics.json
reconv=$(jq -r '.skid_reconvergence_time_s' "$m")
acc=$(jq -r '.skid_classifier_accuracy' "$m")
echo "skid re-convergence ${reconv} s (paper <= 3, lockstep 1.0), classifier accuracy ${acc} (>= 0.95, lockstep 1.0)"
arm() { jq -r ".arm_$1" "$m"; }
echo "arm: settling $(arm settling_time_1_s) / $(arm settling_time_2_s) s (Table 4 <= 0.36 / 0.37)," \
     "rms $(arm rms_e1_mrad) / $(arm rms_e2_mrad) mrad (Table 4 0.649 / 0.619, lockstep 0.634 / 0.619)," \
     "peak torque $(arm max_torque_1_nm) / $(arm max_torque_2_nm) N m (Table 4 46.33 / 14.39, lockstep 46.75 / 14.58)"
within() {  # within NAME LOW HIGH
  awk -v v="$(arm "$1")" -v lo="$2" -v hi="$3" 'BEGIN { exit !(v != "null" && v >= lo && v <= hi) }' ||
    { echo "arm_$1 = $(arm "$1") outside [$2, $3]"; fail=1; }
}
within settling_time_1_s 0 0.36
within settling_time_2_s 0 0.37
within rms_e1_mrad 0 0.746
within rms_e2_mrad 0 0.712
within max_torque_1_nm 0 53.28
within max_torque_2_nm 0 16.55
fits=$(jq -r '.loops.arm.fits' "$j")
echo "timing budget of loop arm: fits=$fits ($(jq -c '.loops.arm.hops | length' "$j") hops between processes)"
[ "$fits" = true ] || { echo "loop arm: no verdict, or it does not fit its budget"; fail=1; }
awk -v r="$reconv" 'BEGIN { exit !(r != "null" && r <= 3) }' || { echo "skid re-convergence above 3 s"; fail=1; }
awk -v a="$acc" 'BEGIN { exit !(a != "null" && a >= 0.95) }' || { echo "skid classifier accuracy below 0.95"; fail=1; }
exit $fail
