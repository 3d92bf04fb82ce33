#!/usr/bin/env bash
# edge_check.sh BIN_DIR PARAMS_DIR DOMAIN SERVICE_VENDOR PUBLISHER_VENDOR
#
# Issue 12, edge checks end to end: a standalone localisation_observer is fed, on each of
# its input topics, samples with a NaN, an infinite or an out-of-range field by another
# process (on the other vendor). Every one must be refused and counted (heartbeat
# rejected_inputs, closing summary), and the estimate it publishes must stay finite. A
# refused sample is no measurement, so the observer is blind (publishes nothing) until valid
# positions follow the bad ones: the estimate is read then (docs/distributed.md).
set -u
bin=$1 params=$2 domain=$3 vendor=$4 pub_vendor=$5
"$bin/localisation_observer" --robot r1 --params "$params/heading_observer.yaml" --dds "$vendor" --domain "$domain" \
  --log-level info > /tmp/edge_check_$domain.log 2>&1 &
pid=$!
fail=0
publish() {  # topic type field value count [health topic]
  "$bin/tests/bad_sample_publisher" --dds "$pub_vendor" --domain "$domain" --topic "$1" --type "$2" --field "$3" \
    --value "$4" --count "$5" ${6:+--health "$6"} || fail=1
}
# Each batch is confirmed on the observer's heartbeat, and what a late-discovering volatile
# reader never received is resent (bad_sample_publisher --health): the count is then exact.
health=health/localisation_observer_localisation_observer
publish r1/position PositionMeasurement x nan 5 $health
publish r1/position PositionMeasurement y 2e6 5 $health     # 2000 km: beyond a position's range
publish r1/cmd UnicycleCommand omega inf 5 $health
expected=15
beat=$("$bin/plexus" topic echo $health --dds "$vendor" --domain "$domain" \
       --count 1 --wait 5 --duration 10 --json 2>&1)
echo "heartbeat: $beat"
echo "$beat" | grep -q "\"rejected_inputs\":$expected[,}]" || { echo "FAIL: expected rejected_inputs $expected"; fail=1; }
# Valid positions after the bad ones: the estimate computed from them must be finite.
"$bin/plexus" topic echo r1/heading --dds "$vendor" --domain "$domain" --count 1 --wait 10 --duration 20 --json \
  > /tmp/edge_check_heading_$domain.json 2>&1 &
echo_pid=$!
publish r1/position PositionMeasurement x 1.5 100
wait $echo_pid
heading=$(cat /tmp/edge_check_heading_$domain.json)
echo "estimate: $heading"
echo "$heading" | grep -Eq '"heading":-?[0-9]' || { echo "FAIL: no finite estimate after valid positions"; fail=1; }
echo "$heading" | grep -Eq '"direction":\[-?[0-9][^],]*,-?[0-9]' || { echo "FAIL: the observer state is not finite"; fail=1; }
kill -TERM $pid
wait $pid
rc=$?
summary=$(grep -o 'ran [0-9]* ticks.*refused samples' /tmp/edge_check_$domain.log)
echo "observer exit $rc: $summary"
[ "$rc" -eq 0 ] || { echo "FAIL: the observer did not exit 0"; fail=1; }
echo "$summary" | grep -q " $expected refused samples" || { echo "FAIL: summary does not count $expected refusals"; fail=1; }
[ $fail -eq 0 ] && echo PASS
exit $fail
