#!/usr/bin/env bash
# partition_realtime.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# Issue 14, network faults: a partition in realtime. The unicycle RFID loop (SCENARIO,
# wmr_output_feedback_rfid.yaml, started on its reference as in loss_realtime.sh) split
# across two network namespaces: plant and reference on h1 (which records the run),
# observer and controller on h2, the far side. 40 s on wall-clock loops; once the run is
# exchanging samples, nftables drops every packet crossing the pair, both ways, for 2 s,
# then lets them through again. Checked from the run folder (signals/, launch.json):
#   - the partition was real and mid-run: its rules dropped packets, and the recording of
#     r1/cmd (which h1 receives from h2) has a gap of at least 1.5 s that starts after 2 s
#     of run and ends before the run's last 10 s;
#   - the far side held: a listener in h2 (`plexus topic echo r1/cmd`) saw the controller
#     publish only the zero command from 0.4 s after the cut to the heal (at least 95 of the
#     2 s partition's 200 ticks), steering commands before the cut and again after the heal;
#     its heartbeats (which reach h1 again afterwards) count the stale reads (the observer,
#     without measurements for clock.blind_after_s = 0.3 s, goes blind, so the controller's
#     input goes stale: hold());
#   - the near side held: the plant found r1/cmd stale and applied the zero command, so the
#     robot stood still (its pose unchanged from one step to the next) within the gap;
#   - tracking resumed: r1/cmd came back non-zero, and the tracking error |truth - reference|
#     over the run's last 5 s is below half its peak after the partition (the robot stood
#     while the reference moved on; k = 0.11 closes that in about 10 s per halving).
# Figures printed: the gap, the stale reads, the peak and final errors.
set -u
PLEXUS=$1 SCENARIO=$2 out=$3 domain=$4 vendor=$5
here=$(cd "$(dirname "$0")" && pwd)
. "$here/netns_pair.sh"
. "$here/split_run.sh"
pair_start "$out"
rfid_on_reference 40 0 --set clock.mode=realtime
run=$out/run
split_start "$run" "$domain" "${HOSTS[@]}" "${PLACE[@]}" "${RFID_STEADY[@]}" --dds "$vendor"
problems=()
dropped=0
# 100 Hz each way plus heartbeats once the loops run; then 8 s into the run.
# A listener on the far side (h2) prints every r1/cmd sample the controller publishes with
# the wall time it arrived (receive_time_ns), so the safe output during the partition is seen
# on the far side itself, not only counted.
far=$out/far_cmd.csv
if pair_wait_busy 100 60; then
  ip netns exec "$NS2" "$PLEXUS" topic echo r1/cmd --dds "$vendor" --domain "$domain" --interface 10.231.0.2 \
    --peers 10.231.0.1,10.231.0.2 --csv --duration 16 > "$far" 2> "$out/far_cmd.log" &
  listener=$!
  sleep 8
  pair_partition || { echo "FAIL: cannot set the partition rules"; exit 1; }
  t_cut=$(date +%s.%N)
  sleep 2
  dropped=$(pair_partition_dropped)
  t_heal=$(date +%s.%N)  # before the rules go: a command may cross within milliseconds of it
  pair_heal
  wait "$listener"
else
  problems+=("the run never exchanged samples over the pair (no partition made)")
fi
split_wait 120
j=$run/launch/launch.json
sig=$run/launch/signals
[ -s "$j" ] || { echo "FAIL: no launch.json (h1 exit $SPLIT_RC, h2 exit $SPLIT_H2_RC)"; tail -5 "$run/h1.log"; tail -3 "$run/h2.log"; exit 1; }
# exit 0 or 1: a 2 s standstill may miss the paper's bounds (exit 1), which is not the point here.
[ "$SPLIT_RC" -le 1 ] && [ -z "$(jq -r '.failure // ""' "$j")" ] || problems+=("h1 exit $SPLIT_RC: $(jq -r '.failure // ""' "$j")")
[ "$SPLIT_H2_RC" -eq 0 ] || problems+=("h2 exit $SPLIT_H2_RC")
[ "$dropped" -gt 0 ] || problems+=("the partition dropped nothing")
cmd=$sig/r1.cmd.csv truth=$sig/r1.truth.state.csv ref=$sig/r1.reference.csv
for f in "$cmd" "$truth" "$ref"; do [ -s "$f" ] || problems+=("no recording $f"); done
read -r gap_from gap_to < <(awk -F, 'NR > 2 && $1 - prev > gap { gap = $1 - prev; a = prev; b = $1 } NR > 1 { prev = $1 }
                                     END { printf "%.3f %.3f\n", a, b }' "$cmd" 2>/dev/null)
end_t=$(awk -F, 'END { print $1 }' "$truth" 2>/dev/null)
gap=$(awk -v a="${gap_from:-0}" -v b="${gap_to:-0}" 'BEGIN { printf "%.3f", b - a }')
awk -v g="$gap" -v a="${gap_from:-0}" -v b="${gap_to:-0}" -v e="${end_t:-0}" 'BEGIN { exit !(g >= 1.5 && a >= 2 && b <= e - 10) }' ||
  problems+=("r1/cmd gap ${gap} s from ${gap_from:-?} to ${gap_to:-?} s of ${end_t:-?} s: not a 2 s partition mid-run")
# The far side held: every r1/cmd the controller published from 0.4 s after the cut (the
# observer's grace before it goes blind, clock.blind_after_s = 0.3 s by default, then the
# controller's input deadline, 3 periods, with margin) to the heal was the zero command, and
# there were at least half the partition's ticks of them;
# before the cut it was steering (non-zero), and after the heal it steered again.
read -r far_before far_zero far_moving far_after < <(awk -F, -v c="${t_cut:-0}" -v h="${t_heal:-0}" '
    NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "v") iv = i; if ($i == "omega") iw = i; } next }
    { t = $1 * 1e-9; zero = ($iv == 0 && $iw == 0) }
    t < c && !zero { before++ }
    t > c + 0.4 && t < h { if (zero) z++; else moving++ }
    t > h + 1 && !zero { after++ }
    END { print before + 0, z + 0, moving + 0, after + 0 }' "$far" 2>/dev/null)
[ "${far_before:-0}" -gt 0 ] || problems+=("the far-side listener saw no steering command before the partition")
[ "${far_zero:-0}" -ge 95 ] && [ "${far_moving:-1}" -eq 0 ] ||
  problems+=("during the partition the controller published ${far_zero:-0} zero and ${far_moving:-?} steering commands (>= 95 zero and no steering expected): it did not hold")
[ "${far_after:-0}" -gt 0 ] || problems+=("the far side never steered again after the partition")
period=0.01
ticks=$(awk -v g="$gap" -v p="$period" 'BEGIN { printf "%d", g / p }')
stale_ctl=$(jq -r '.services["motion_controller controller"].stale_input_reads // "null"' "$j")
stale_obs=$(jq -r '.services["localisation_observer observer"].stale_input_reads // "null"' "$j")
stale_plant=$(jq -r '.services["plant_simulator r1"].stale_input_reads // "null"' "$j")
[ "$stale_ctl" != null ] && [ "$stale_ctl" -ge $((ticks / 2)) ] ||
  problems+=("the controller found its input stale $stale_ctl times (>= $((ticks / 2)) expected: half the partition's ticks): it did not hold")
[ "$stale_plant" != null ] && [ "$stale_plant" -ge $((ticks / 2)) ] ||
  problems+=("the plant found r1/cmd stale $stale_plant times (>= $((ticks / 2)) expected)")
# The robot stood still (zero command at the plant) at some step inside the gap.
still=$(awk -F, -v a="${gap_from:-0}" -v b="${gap_to:-0}" 'NR > 2 && $1 > a && $1 < b && $3 == x && $4 == y && $5 == th { n++ }
                                                          { x = $3; y = $4; th = $5 } END { print n + 0 }' "$truth" 2>/dev/null)
[ "${still:-0}" -gt 0 ] || problems+=("the robot never stood still during the partition: the plant did not apply the zero command")
# r1/cmd back and not the safe (zero) command at the end.
last_zero=$(awk -F, 'END { z = 1; for (i = 3; i <= NF; ++i) if ($i != 0) z = 0; print z }' "$cmd" 2>/dev/null)
[ "$last_zero" = 0 ] || problems+=("r1/cmd is still the zero command at the end: the loop did not resume")
read -r peak last < <(awk -F, -v t0="${gap_from:-0}" 'FNR == 1 { next } NR == FNR { rx[$2] = $3; ry[$2] = $4; next }
    ($2 in rx) { e = sqrt(($3 - rx[$2])^2 + ($4 - ry[$2])^2); t[++n] = $1; v[n] = e; if ($1 >= t0 && e > peak) peak = e }
    END { for (i = n; i > 0 && t[i] > t[n] - 5; --i) { s += v[i]; m++ } printf "%.4f %.4f\n", peak, m ? s / m : -1 }' "$ref" "$truth" 2>/dev/null)
awk -v p="${peak:-0}" -v l="${last:--1}" 'BEGIN { exit !(l >= 0 && p > 0 && l < 0.5 * p) }' ||
  problems+=("tracking did not resume: error over the last 5 s ${last:-?} m, peak ${peak:-?} m after the partition")
echo "vendor | partition dropped | r1/cmd gap at h1 | far side: zero / steering commands in the partition | stale reads (controller, observer, plant) | robot still (steps) | error peak after / last 5 s (m) | steady mean error (m) | result"
verdict=PASS
if [ ${#problems[@]} -gt 0 ]; then
  verdict=FAIL
  for p in "${problems[@]}"; do echo "FAIL ($vendor): $p"; done
  grep -v "gain condition" "$run/h1.log" | tail -4
  tail -3 "$run/h2.log"
fi
echo "$vendor | $dropped | ${gap} s (${gap_from}-${gap_to} s) | ${far_zero:-?} / ${far_moving:-?} | $stale_ctl, $stale_obs, $stale_plant | $still | $peak / $last | $(json_of "$run/h1.json" .steady_mean_error_m) | $verdict"
[ $verdict = PASS ]
