#!/usr/bin/env bash
# partition_lockstep.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# Issue 14, network faults: a partition in lockstep. The unicycle RFID loop (SCENARIO,
# wmr_output_feedback_rfid.yaml, started on its reference as in loss_lockstep.sh) split
# across two network namespaces, plant and reference on h1 (with the clock), observer and
# controller on h2. Once the run is exchanging samples over the pair, nftables drops every
# packet crossing it, both ways, for 2 s, then lets them through again. The choice
# (docs/distributed.md, Faults): lockstep waits for a missing sample up to --timeout, so
#   - short: a 2 s partition inside the default 10 s timeout pauses the run, reliable QoS
#     repairs what was dropped once the link is back, and the run completes with the digest
#     of `plexus sim` (exit 0 on both hosts);
#   - long:  the same 2 s partition with --timeout 1 outlasts the timeout: the run fails
#     (exit 1) with one line naming the missing sample, its producer on the far host and the
#     step (`lockstep: no sample of 'r1/heading' from 'observer' for step N within 1 s`, or
#     the same for 'r1/cmd' from 'controller'), and the far host's share ends too.
# Each case checks that the partition was real (its rules dropped packets) and fell inside
# the run: it starts once a listener in h2 has seen 200 of the clock's steps, and the
# launcher still runs when the link comes back.
set -u
PLEXUS=$1 SCENARIO=$2 out=$3 domain=$4 vendor=$5
here=$(cd "$(dirname "$0")" && pwd)
. "$here/netns_pair.sh"
. "$here/split_run.sh"
. "$here/clock_steps.sh"
pair_start "$out"
# 60 s of the loop (6000 lockstep steps): long enough over the pair for a 2 s pause mid-run.
rfid_on_reference 60 0
sim_digest "$out" "${RFID_STEADY[@]}"
sim_digest=$SIM_DIGEST
fail=0
echo "case | vendor | timeout | partition (from step) | packets dropped | h1 exit | h2 exit | digest (sim $sim_digest) / message | result"
for c in short long; do
  run=$out/$c
  targs=()
  [ $c = long ] && targs=(--timeout 1)
  pair_reset || { echo "FAIL: cannot set the rules"; exit 1; }
  split_start "$run" "$domain" "${HOSTS[@]}" "${PLACE[@]}" "${RFID_STEADY[@]}" --dds "$vendor" "${targs[@]}"
  problems=()
  # Mid-run: a listener in h2 prints the clock's steps as they cross the pair (best effort,
  # so it slows nothing); the cut comes once it has seen 200 of them, and the last step seen
  # before the cut is reported.
  steps=$run/clock_steps.csv
  ip netns exec "$NS2" "$PLEXUS" topic echo lockstep/clock --dds "$vendor" --domain "$domain" --interface 10.231.0.2 \
    --peers 10.231.0.1,10.231.0.2 --csv --profile sensor --duration 60 > "$steps" 2> "$run/clock_steps.log" &
  listener=$!
  await_clock_steps "$steps" 200 "$SPLIT_H1"
  seen=$SEEN
  cut_step=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "step_index") c = i; next } { s = $c } END { print s + 0 }' "$steps")
  if [ "$seen" -lt 200 ]; then
    problems+=("the h2 listener saw $seen clock steps within 60 s (no partition made)")
  else
    pair_partition || { echo "FAIL: cannot set the partition rules"; exit 1; }
    t_cut=$(date +%s.%N)
    sleep 2
    dropped=$(pair_partition_dropped)
    pair_heal
    t_heal=$(date +%s.%N)
    kill -0 "$SPLIT_H1" 2>/dev/null || { [ $c = short ] && problems+=("the run had ended before the link came back: no partition mid-run"); }
    part=$(awk -v a="$t_cut" -v b="$t_heal" 'BEGIN { printf "%.2f s", b - a }')
    [ "$dropped" -gt 0 ] || problems+=("the partition dropped nothing")
  fi
  split_wait 120
  kill "$listener" 2>/dev/null
  wait "$listener" 2>/dev/null
  digest=$(json_of "$run/h1.json" .digest)
  if [ $c = short ]; then
    shown=$digest
    [ "$SPLIT_RC" -eq 0 ] && [ "$SPLIT_H2_RC" -eq 0 ] || problems+=("exit $SPLIT_RC on h1, $SPLIT_H2_RC on h2 (0 expected: the run completes)")
    [ "$digest" = "$sim_digest" ] || problems+=("digest $digest, not the sim's $sim_digest")
  else
    msg=$(grep -m1 "^plexus launch: " "$run/h1.log")
    shown=${msg:-"(no message)"}
    [ "$SPLIT_RC" -eq 1 ] || problems+=("h1 exit $SPLIT_RC (1 expected: the run fails)")
    [ "$SPLIT_H2_RC" -ne 0 ] || problems+=("h2 exit 0: the far host's share did not end with the failure")
    # One line naming the missing sample, its producer (a service on the far host) and the step.
    [[ "$msg" =~ no\ sample\ of\ \'r1/(heading|cmd)\'\ (from|\(produced\ by)\ \'(observer|controller)\'.*step\ [0-9]+.*within\ 1 ]] ||
      problems+=("the failure does not name the missing sample and its producer: '$msg'")
    [ "$digest" = null ] || problems+=("a failed run printed a digest ($digest)")
  fi
  verdict=PASS
  if [ ${#problems[@]} -gt 0 ]; then
    verdict=FAIL
    fail=1
    for p in "${problems[@]}"; do echo "FAIL $c ($vendor): $p"; done
    grep -v "gain condition" "$run/h1.log" | tail -4
    tail -3 "$run/h2.log"
  fi
  echo "$c | $vendor | ${targs[*]:-default (10 s)} | ${part:-none} (${cut_step:-?} of 6000) | ${dropped:-0} | $SPLIT_RC | $SPLIT_H2_RC | $shown | $verdict"
done
exit $fail
