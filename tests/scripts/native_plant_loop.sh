#!/usr/bin/env bash
# native_plant_loop.sh PLEXUS NATIVE_PLANT VENDOR DOMAIN OUT_DIR SCENARIO
#
# Issue 12's native-peer closed loop: a program built from idl/ alone (no plexus library)
# plays the unicycle plant in realtime. It subscribes r1/cmd (UnicycleCommand), integrates
# the unicycle and publishes r1/position on a 0.1 m RFID grid at 100 Hz (and r1/truth/state
# for the metrics). The observer, the controller and the reference run as plexus services
# under `plexus launch --external plant_simulator`. The robot starts on its reference
# (tests/scripts/rfid_on_reference.sh: the native plant at (0, -5) heading pi, the same
# start as the scenario's flags give the others); after 45 s the launch's expectations,
# paper 000's steady RFID bounds (max <= 0.05 m, mean <= 0.01 m) over [20, 45] s, must
# hold: the launch exits 0. The plant must have received commands and stop cleanly on SIGTERM.
set -u
plexus=$1 plant=$2 vendor=$3 domain=$4 out=$5 scenario=$6
. "$(dirname "$0")/rfid_on_reference.sh"
rfid_on_reference 45 20
rm -rf "$out" && mkdir -p "$out"
"$plant" --domain "$domain" --robot r1 --x0 0 --y0 -5 --theta0 3.141592653589793 --rate 1000 --sensor-rate 100 --grid 0.1 \
  > "$out/plant.out" 2> "$out/plant.err" &
plant_pid=$!
trap 'kill -TERM $plant_pid 2>/dev/null' EXIT
"$plexus" launch "$scenario" --set clock.mode=realtime "${RFID_STEADY[@]}" --external plant_simulator \
  --dds "$vendor" --domain "$domain" --json --out "$out/run" > "$out/launch.json" 2> "$out/launch.err"
launch_rc=$?
kill -TERM $plant_pid
wait $plant_pid
plant_rc=$?
trap - EXIT
echo "launch exit $launch_rc, plant exit $plant_rc"
cat "$out/plant.out"
grep -o '"steady_m[a-z]*_error_m":[^,}]*' "$out/launch.json" || { echo "no metrics:"; tail -5 "$out/launch.err"; }
[ "$plant_rc" -eq 0 ] || { echo "FAIL: the native plant did not exit 0 on SIGTERM"; cat "$out/plant.err"; exit 1; }
grep -Eq ', [1-9][0-9]* commands received' "$out/plant.out" || { echo "FAIL: the native plant received no command"; exit 1; }
[ "$launch_rc" -eq 0 ] || { echo "FAIL: paper 000's RFID bounds not met (or the launch failed):"; tail -5 "$out/launch.err"; exit 1; }
echo "PASS"
