#!/usr/bin/env bash
# late_reads_alone.sh BIN DEPLOY DOMAIN OUT: the RFID closed loop started by hand, each service
# alone from its parameters (plant, reference, observer, controller; no launcher), stopped
# with SIGTERM after 4 s. A service alone does not know its producers' stages, so it reads
# the newest sample there is and counts a read late only when that sample is more than one
# period old (docs/distributed.md, "Overruns and late samples"): the observer reads the
# controller's command, a later stage, whose sample of the observer's own step never exists
# yet at its tick, and counted every such read late (1363 late reads in 1358 ticks). Here
# each service's stop summary must show late reads on at most half of its ticks.
set -u
bin=$1 deploy=$2 domain=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
common=(--dds fast --domain "$domain")
"$bin/plant_simulator" --params "$deploy/params/unicycle_robot.yaml" "${common[@]}" > /dev/null 2> "$out/plant.log" &
p1=$!
"$bin/component_host" --name reference --params "$deploy/params/figure_eight_reference.yaml" "${common[@]}" \
  > /dev/null 2> "$out/reference.log" &
p2=$!
"$bin/localisation_observer" --params "$deploy/params/heading_observer.yaml" "${common[@]}" > /dev/null 2> "$out/observer.log" &
p3=$!
"$bin/motion_controller" --params "$deploy/params/trajectory_tracking.yaml" "${common[@]}" > /dev/null 2> "$out/controller.log" &
p4=$!
sleep 4
kill -TERM $p1 $p2 $p3 $p4
wait $p1 $p2 $p3 $p4
fail=0
for s in plant reference observer controller; do
  line=$(grep -E ": ran [0-9]+ ticks: " "$out/$s.log" | tail -1)
  echo "$s: ${line:-no stop summary}"
  ticks=$(echo "$line" | sed -nE 's/.*: ran ([0-9]+) ticks: .*/\1/p')
  late=$(echo "$line" | sed -nE 's/.* ([0-9]+) late input reads.*/\1/p')
  [ -n "$ticks" ] && [ -n "$late" ] || { echo "FAIL: no stop summary with late reads from $s"; fail=1; continue; }
  [ "$ticks" -ge 100 ] || { echo "FAIL: $s ran $ticks ticks in 4 s"; fail=1; }
  [ $((late * 2)) -le "$ticks" ] || { echo "FAIL: $s counted $late late reads in $ticks ticks"; fail=1; }
done
exit $fail
