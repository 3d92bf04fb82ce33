#!/usr/bin/env bash
# loss_realtime.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# Issue 14, network faults: realtime over a lossy link. The unicycle RFID loop (SCENARIO,
# wmr_output_feedback_rfid.yaml) split across two network namespaces as in loss_lockstep.sh
# (plant and reference on h1, observer and controller on h2), on wall-clock loops, three
# times AT ONCE, each in a pair of namespaces of its own: without loss, with nftables
# dropping 10 %, and 30 %, of the packets arriving on each end of the veth pair (both
# directions). At once, because on a shared machine the tracking error of a realtime run is
# set by the CPU stalls it meets (the same loss-free run measured 2 mm and 47 mm in two runs
# a few minutes apart), not by 10 % loss; runs side by side meet the same stalls.
#
# The figure is the RFID case's steady-state tracking error, the mean of |truth - reference|
# (paper 000's V_t). To measure it in 60 s instead of the paper's 480 s the robot starts on
# its reference (tests/scripts/rfid_on_reference.sh), so the error is steady from about 20 s
# on, and the mean and max are taken over [20, 60] s (`plexus sim` of the same: mean 2.0 mm).
#
# Asserted: every run lived to the end (both hosts exit 0, or 1 for a missed paper bound, the
# metrics exist, each loss rule dropped packets), and at 10 % the loop still tracks: a steady
# mean error under 0.1 m (a loop that stopped, or held its zero command, leaves the figure
# eight by metres). 30 % is reported only (3.2-253 mm measured). Reported, and failing the
# test only with STRICT_TIMING=1 (as every realtime timing goal: docs/testing.md): the
# issue's bound, at 10 % a mean within 2x the
# loss-free one, and the paper's 10 mm at 10 %. Both depend on the CPU the runs got, not
# only on the loss: a reliable sample lost on the link is repaired within a few ms
# (NetworkOptions::reliable_heartbeat_s), and an input is held stale only when its repair
# takes over 3 periods (30 ms); on a loaded machine the repair's heartbeat and answer are
# late, and each stale input is a tick of zero command. Measured: 0.93-2.12x on an idle or
# lightly loaded machine, 6.3x (12.4 mm, 255 stale controller reads) in one CI run
# (docs/distributed.md, Faults).
set -u
PLEXUS=$1 SCENARIO=$2 out=$3 domain=$4 vendor=$5
if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
here=$(cd "$(dirname "$0")" && pwd)
. "$here/netns_pair.sh"
. "$here/split_run.sh"
rm -rf "$out" && mkdir -p "$out"
rfid_on_reference 60 20 --set clock.mode=realtime
losses=(0 10 30)
# One loss case in its own namespaces (a subshell: netns_pair.sh keeps its names in globals).
run_case() {
  local loss=$1
  trap pair_down EXIT
  pair_up "${$}l$loss" || { echo "FAIL: cannot create the namespaces for $loss %"; exit 1; }
  pair_loss "$loss" || { echo "FAIL: cannot set the $loss % loss rules"; exit 1; }
  # At 30 % each way the start handshake (discovery, then the start signal to every child)
  # can take longer than the default 10 s: a clean-clone CI run (2026-11-29) lost h2's plant
  # simulator that way ("no start signal from plexus launch within 10 s"). 30 s there.
  local start=()
  [ "$loss" -ge 30 ] && start=(--timeout 30)
  split_start "$out/loss_$loss" "$domain" "${HOSTS[@]}" "${PLACE[@]}" "${RFID_STEADY[@]}" --dds "$vendor" "${start[@]}"
  split_wait 150
  pair_counters > "$out/loss_$loss.dropped"
  echo "$SPLIT_RC $SPLIT_H2_RC" > "$out/loss_$loss.rc"
}
cases=()
stop_cases() { [ ${#cases[@]} -gt 0 ] && kill "${cases[@]}" 2>/dev/null; return 0; }
trap stop_cases EXIT
for loss in "${losses[@]}"; do
  ( run_case "$loss" ) &
  cases+=($!)
done
wait "${cases[@]}"
cases=()
fail=0
declare -A mean_of
echo "vendor | loss (each way) | packets dropped | steady mean error (m) | steady max error (m) | stale reads (plant, observer, controller) | late reads | result"
for loss in "${losses[@]}"; do
  run=$out/loss_$loss
  read -r rc1 rc2 < "$out/loss_$loss.rc" 2>/dev/null || { rc1=none; rc2=none; }
  dropped=$(cat "$out/loss_$loss.dropped" 2>/dev/null)
  j=$run/h1.json
  mean=$(json_of "$j" .steady_mean_error_m)
  max=$(json_of "$j" .steady_max_error_m)
  mean_of[$loss]=$mean
  stale=$(jq -r '[.services["plant_simulator r1", "localisation_observer observer", "motion_controller controller"].stale_input_reads] | map(tostring) | join(", ")' "$j" 2>/dev/null)
  late=$(jq -r '[.services[].late_input_reads] | add' "$j" 2>/dev/null)
  verdict=PASS
  # exit 0, or 1 when a paper bound is missed (reported); h2 exits 0 when its processes do.
  if [[ ! "$rc1" =~ ^[01]$ ]] || [ "$rc2" != 0 ] || [ "$mean" = null ]; then verdict=FAIL; fail=1; fi
  [ "$verdict" = PASS ] && [ "$rc1" = 1 ] && verdict="PASS (the paper's bounds missed: reported)"
  if [ "$loss" = 10 ] && [ "$mean" != null ] && [ "${mean_of[0]}" != null ]; then
    ratio=$(awk -v a="$mean" -v b="${mean_of[0]}" 'BEGIN { printf "%.2f", a / b }')
    within=$(awk -v a="$mean" -v r="$ratio" 'BEGIN { print (r <= 2 ? "within" : "ABOVE") " 2x the loss-free run (" r "x), " (a <= 0.01 ? "within" : "ABOVE") " the paper'"'"'s 10 mm" }')
    if [[ $within == *ABOVE* ]] && [ "${STRICT_TIMING:-0}" = 1 ]; then
      verdict="FAIL (STRICT_TIMING: $within)"
      fail=1
    else
      verdict="$verdict ($within; reported)"
    fi
  fi
  # At 10 % the loop still tracks (a stopped or held loop leaves the figure eight by metres).
  # 30 % is reported only, as the issue asks: 3.2-253 mm measured, by the CPU the runs got.
  if [ "$loss" = 10 ] && [ "$mean" != null ] && ! awk -v a="$mean" 'BEGIN { exit !(a < 0.1) }'; then
    verdict="FAIL (mean $mean m at $loss % loss: the loop no longer tracks, bound 0.1 m)"
    fail=1
  fi
  echo "$vendor | $loss % | $dropped | $mean | $max | $stale | $late | $verdict"
  [[ $verdict == PASS* ]] || { grep -v "gain condition" "$run/h1.log" | tail -4; tail -2 "$run/h2.log"; }
  if [ "$loss" -gt 0 ]; then
    [[ "$dropped" =~ ^dropped\ ([0-9]+) ]] && [ "${BASH_REMATCH[1]}" -gt 0 ] ||
      { echo "FAIL: the $loss % rule dropped nothing ($dropped)"; fail=1; }
  fi
done
exit $fail
