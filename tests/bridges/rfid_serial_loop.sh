#!/usr/bin/env bash
# rfid_serial_loop.sh PLEXUS BIN_DIR VENDOR DOMAIN OUT_DIR SCENARIO BAUD DURATION FROM [BRIDGE_VENDOR [UNPLUG_AT]]
#
# Issue 13's closed loop: paper 000's RFID case (section 6.3.2) in realtime with the serial
# bridge and the device emulator in place of the plant simulator. The scenario is the
# simulator's, with one line changed: robots.r1.source = serial_bridge on a pty. `plexus
# launch` starts serial_bridge for r1; the device is absent at first (the bridge waits and
# retries), then the emulator starts on the robot's own part of the scenario (the same plant
# and RFID sensor as plant_simulator would run) and creates the pty. The robot starts on its
# reference (tests/scripts/rfid_on_reference.sh) and the run lasts DURATION s: the launch's
# expectations, the paper's steady bounds (max <= 0.05 m, mean <= 0.01 m) over [FROM,
# DURATION] s, must hold (launch exit 0), the emulator must have obeyed the controller's
# 100 Hz commands for most of the run, and both must stop cleanly.
#
# BRIDGE_VENDOR runs the bridge on another vendor than the services (a mixed deployment).
# UNPLUG_AT (s after the emulator starts) unplugs the device for 0.5 s: the bridge must stop
# publishing (the controller's inputs go stale, it holds), reconnect and resume, and the
# bounds must still hold after FROM s (the robot stands while the device is away and falls
# behind the moving reference; the controller's gains halve that error in about 10 s).
#
# Every loop (the three services, the bridge, the emulator) runs at SCHED_FIFO
# PLEXUS_TEST_PRIORITY (default 60; 0: normal scheduling) with its DDS and link threads, as
# the arm's closed loops do (docs/performance.md, "Priorities"): at normal priority, busy
# neighbours starve the delivery threads and the paper's bounds are missed (docs/testing.md,
# "Known flakiness"). Needs root or CAP_SYS_NICE, as those tests do.
set -u
plexus=$1 bin=$2 vendor=$3 domain=$4 out=$5 scenario=$6 baud=$7 duration=$8 from=$9 bridge_vendor=${10:-$3} unplug_at=${11:-}
. "$(dirname "$0")/../scripts/rfid_on_reference.sh"
rfid_on_reference "$duration" "$from"
rm -rf "$out" && mkdir -p "$out"
priority=${PLEXUS_TEST_PRIORITY:-60}
case $priority in
  '' | *[!0-9]*) echo "rfid_serial_loop.sh: PLEXUS_TEST_PRIORITY '$priority' is not a priority (0..99)" >&2; exit 2 ;;
esac
priorities=() emulator_priority=()
if [ "$priority" -gt 0 ]; then
  priorities=(--set clock.priority=$priority)
  emulator_priority=(--priority $priority)
fi
emu=""
trap '[ -n "$emu" ] && kill -TERM $emu 2>/dev/null; kill -TERM $launch 2>/dev/null' EXIT
"$plexus" launch "$scenario" --set clock.mode=realtime "${RFID_STEADY[@]}" "${priorities[@]}" \
  --set "robots.r1.source={type: serial_bridge, device: $out/tty, baud: $baud}" \
  --dds "$vendor" --vendor "serial_bridge r1=$bridge_vendor" --domain "$domain" --json --quiet --out "$out/run" \
  > "$out/launch.json" 2> "$out/launch.err" &
launch=$!
part="$out/run/parts/serial_bridge_r1.yaml"
for _ in $(seq 1 100); do [ -s "$part" ] && break; sleep 0.1; done
[ -s "$part" ] || { echo "FAIL: the launcher wrote no part for serial_bridge r1"; cat "$out/launch.err"; exit 1; }
sleep 1  # the bridge starts with its device absent: it must wait and retry
faults=()
[ -n "$unplug_at" ] && faults=(--fault "unplug@$unplug_at:for=0.5")
"$bin/device_emulator" --part "$part" --pty "$out/tty" --baud "$baud" "${faults[@]}" "${emulator_priority[@]}" > "$out/emulator.json" 2> "$out/emulator.err" &
emu=$!
wait $launch
launch_rc=$?
kill -TERM $emu
wait $emu
emu_rc=$?
emu=""
trap - EXIT
echo "launch exit $launch_rc, emulator exit $emu_rc"
grep -o '"steady_m[a-z]*_error_m":[^,}]*' "$out/launch.json" || { echo "no metrics:"; tail -5 "$out/launch.err"; }
bridge_line=$(grep -ho '{"service":"serial_bridge r1".*}' "$out/run/logs/"*.log 2>/dev/null | tail -1)
echo "bridge: $bridge_line"
echo "emulator: $(tail -1 "$out/emulator.json")"
[ "$emu_rc" -eq 0 ] || { echo "FAIL: the emulator did not exit 0"; tail -5 "$out/emulator.err"; exit 1; }
commands=$(grep -o '"commands":[0-9]*' "$out/emulator.json" | head -1 | cut -d: -f2)
min_commands=$(( duration * 100 / 2 ))  # 100 Hz for half the run at least (the device starts late)
[ "${commands:-0}" -ge "$min_commands" ] || {
  echo "FAIL: the emulator got ${commands:-0} commands (at least $min_commands expected: 100 Hz over $duration s)"; exit 1; }
[ "$launch_rc" -eq 0 ] || { echo "FAIL: paper 000's RFID bounds not met (or the launch failed):"; tail -5 "$out/launch.err"; exit 1; }
if [ -n "$unplug_at" ]; then
  count() { echo "$bridge_line" | grep -o "\"$1\":[0-9]*" | cut -d: -f2; }
  [ "$(count disconnects)" -ge 1 ] && [ "$(count reconnects)" -ge 1 ] || {
    echo "FAIL: the bridge did not see the unplug and reconnect (disconnects $(count disconnects), reconnects $(count reconnects))"; exit 1; }
  stale=$(grep -o '"motion_controller controller":{[^}]*' "$out/launch.json" | grep -o '"stale_input_reads":[0-9]*' | cut -d: -f2)
  [ "${stale:-0}" -ge 1 ] || { echo "FAIL: the controller's inputs never went stale while the device was unplugged"; exit 1; }
  echo "unplugged at $unplug_at s for 0.5 s: bridge disconnects $(count disconnects), reconnects $(count reconnects); controller stale input reads $stale (held)"
fi
echo "PASS"
