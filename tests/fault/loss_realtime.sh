#!/usr/bin/env bash
# loss_realtime.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# Issue 14, network faults: realtime over a lossy link. The unicycle RFID loop (SCENARIO,
# wmr_output_feedback_rfid.yaml) split across two network namespaces as in loss_lockstep.sh
# (plant and reference on h1, observer and controller on h2), on wall-clock loops, run three
# times in a row: without loss, then with nftables dropping 10 %, then 30 %, of the packets
# arriving on each end of the veth pair (both directions).
#
# The figure is the RFID case's steady-state tracking error, the mean of |truth - reference|
# (paper 000's V_t). To measure it in 80 s instead of the paper's 480 s the robot starts on
# its reference (RFID_STEADY), so the error is steady from about 20 s on, and the mean and
# max are taken over [20, 80] s (`plexus sim` of the same: mean 1.96 mm, max 5.1 mm).
# Asserted: without loss and at 10 %, the run meets the paper's bounds (mean <= 10 mm, max
# <= 50 mm: the scenario's expectations, exit 0), and at 10 % the mean is within 2x the
# loss-free run's (the issue's bound). At 30 % the figures are reported and only the loop's
# life is asserted (every process ran to the end, the metrics exist): discovery across a
# link losing 30 % of its packets takes seconds, during which the plant runs on the zero
# command while the reference moves on, and the 0.11 gains take longer than the run to
# close the gap that leaves (docs/distributed.md, Faults).
# Status: not registered in ctest. The 10 % run misses the 2x bound on both vendors
# (2026-11-24: Cyclone 22 mm against 2.1 mm; Fast DDS 0.40 m against 0.043 m on a loaded
# machine); docs/distributed.md, Faults, gives the figures and what is left to find out.
set -u
PLEXUS=$1 SCENARIO=$2 out=$3 domain=$4 vendor=$5
if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
here=$(cd "$(dirname "$0")" && pwd)
. "$here/netns_pair.sh"
. "$here/split_run.sh"
trap pair_down EXIT
rm -rf "$out" && mkdir -p "$out"
pair_up "$$" || { echo "FAIL: cannot create the namespaces"; exit 1; }
RFID_STEADY=(--set robots.r1.plant.y0=-5 --set robots.r1.plant.theta0=3.141592653589793 --set services.observer.z3_0=-0.2
             --set duration=80 --set metrics.0.from=20 --set metrics.1.from=20 --set clock.mode=realtime)
PLACE=(--set robots.r1.host=h1 --set services.reference.host=h1 --set services.observer.host=h2
       --set services.controller.host=h2)
fail=0
declare -A mean_of
echo "vendor | loss (each way) | packets dropped | steady mean error (m) | steady max error (m) | stale reads (plant, observer, controller) | late reads | result"
for loss in 0 10 30; do
  run=$out/loss_$loss
  pair_reset && pair_loss "$loss" || { echo "FAIL: cannot set the loss rules"; exit 1; }
  split_start "$run" "$domain" "${HOSTS[@]}" "${PLACE[@]}" "${RFID_STEADY[@]}" --dds "$vendor"
  split_wait
  dropped=$(pair_counters)
  j=$run/h1.json
  mean=$(json_of "$j" .steady_mean_error_m)
  max=$(json_of "$j" .steady_max_error_m)
  mean_of[$loss]=$mean
  stale=$(jq -r '[.services["plant_simulator r1", "localisation_observer observer", "motion_controller controller"].stale_input_reads] | map(tostring) | join(", ")' "$j" 2>/dev/null)
  late=$(jq -r '[.services[].late_input_reads] | add' "$j" 2>/dev/null)
  verdict=PASS
  # exit 0: every expectation (the paper's bounds) held; h2 exits 0 when its processes do.
  # At 30 %: exit 1 (an expectation missed) is reported, not failed.
  allowed=0
  [ "$loss" = 30 ] && allowed=1
  if [ "$SPLIT_RC" -gt $allowed ] || [ "$SPLIT_H2_RC" -ne 0 ] || [ "$mean" = null ]; then verdict=FAIL; fail=1; fi
  [ "$loss" = 30 ] && [ "$SPLIT_RC" = 1 ] && verdict="PASS (reported: the paper's bounds missed)"
  if [ "$loss" = 10 ] && [ "$mean" != null ] && [ "${mean_of[0]}" != null ]; then
    if awk -v a="$mean" -v b="${mean_of[0]}" 'BEGIN { exit !(a <= 2 * b) }'; then
      verdict="$verdict (mean within 2x the loss-free ${mean_of[0]})"
    else
      verdict="FAIL (mean above 2x the loss-free ${mean_of[0]})"
      fail=1
    fi
  fi
  echo "$vendor | $loss % | $dropped | $mean | $max | $stale | $late | $verdict"
  [[ $verdict == PASS* ]] || { grep -v "gain condition" "$run/h1.log" | tail -4; tail -2 "$run/h2.log"; }
  if [ "$loss" -gt 0 ]; then
    [[ "$dropped" =~ ^dropped\ ([0-9]+) ]] && [ "${BASH_REMATCH[1]}" -gt 0 ] ||
      { echo "FAIL: the $loss % rule dropped nothing ($dropped)"; fail=1; }
  fi
done
exit $fail
