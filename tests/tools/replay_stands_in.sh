#!/usr/bin/env bash
# replay_stands_in.sh PLEXUS SCENARIO VENDOR REPLAY_VENDOR DOMAIN WORK_DIR
# Replayed data stands in for the simulator. A lockstep launch records every signal
# (--record); a second launch starts only the services (--external plant_simulator) while
# `plexus replay --lockstep` publishes the recorded plant topics. The services then receive
# exactly the recorded inputs, so every signal they compute live (the observer's estimate,
# the controller's command) must come out identical to the first run's, sample for sample.
set -u
plexus=$1 scenario=$2 vendor=$3 replay_vendor=$4 domain=$5 work=$6
rm -rf "$work"
mkdir -p "$work"
set -- --set duration=101 --domain "$domain" --dds "$vendor" --quiet --json
"$plexus" launch "$scenario" "$@" --record "$work/rec.mcap" --out "$work/recorded" > "$work/recorded.json" || {
  echo "the recording launch failed"; exit 1; }
"$plexus" replay --lockstep --dds "$replay_vendor" --domain "$domain" --wait 30 \
  --topics r1/truth/state,r1/position "$work/rec.mcap" > "$work/replay.log" 2>&1 &
replay=$!
"$plexus" launch "$scenario" "$@" --external plant_simulator --out "$work/replayed" > "$work/replayed.json"
rc=$?
wait $replay
replay_rc=$?
cat "$work/replay.log"
echo "launch with replay: rc $rc, replay rc $replay_rc"
[ $rc -eq 0 ] && [ $replay_rc -eq 0 ] || exit 1
status=0
for s in r1.heading r1.cmd r1.reference; do
  if cmp -s "$work/recorded/signals/$s.csv" "$work/replayed/signals/$s.csv"; then
    echo "$s: identical ($(wc -l < "$work/replayed/signals/$s.csv") lines)"
  else
    echo "$s: differs between the simulated and the replayed run"; status=1
  fi
done
exit $status
