#!/usr/bin/env bash
# balancing_contract.sh SOURCE VENDOR DOMAIN OUTDIR [BIN_DIR]
#
# The balancing robot (paper 002; deploy/params/balancing_robot.yaml at a 0.002 s base
# step) against its simulator's contract (balancing_contract.yaml): SOURCE simulator
# (plant_simulator) or serial (device_emulator on a pty + serial_bridge at 1 Mbaud).
# contract_probe checks discovery (topics, types, QoS), rates within 5 % (IMU 100 Hz,
# odometry and truth 500 Hz), headers and values; no drive (a torque step topples an
# uncontrolled pendulum; the unicycle contract test drives). Exit 0 only if all pass.
set -u
source=$1 vendor=$2 domain=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
bin=${5:-$(cd "$here/../.." && pwd)/build/bin}
params=$(cd "$here/../../deploy/params" && pwd)/balancing_robot.yaml
rm -rf "$out" && mkdir -p "$out"
pids=()
trap 'for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done; wait 2>/dev/null' EXIT
case $source in
  simulator)
    "$bin/plant_simulator" --robot r1 --params "$params" --step 0.002 --dds "$vendor" --domain "$domain" \
      > "$out/source.out" 2> "$out/source.err" &
    pids+=($!) ;;
  serial)
    "$bin/device_emulator" --params "$params" --step 0.002 --pty "$out/tty" --baud 1000000 \
      > "$out/emulator.json" 2> "$out/emulator.err" &
    pids+=($!)
    for _ in $(seq 1 50); do [ -e "$out/tty" ] && break; sleep 0.1; done
    "$bin/serial_bridge" --robot r1 --params "$params" --step 0.002 --device "$out/tty" --dds "$vendor" \
      --domain "$domain" > "$out/bridge.json" 2> "$out/bridge.err" &
    pids+=($!) ;;
  *) echo "balancing_contract.sh: SOURCE: simulator or serial"; exit 2 ;;
esac
"$bin/tests/contract_probe" --dds "$vendor" --domain "$domain" --robot r1 --contract "$here/balancing_contract.yaml" \
  --discover 3 --measure 6 --label "balancing $source/$vendor" --out "$out/result.json" > "$out/probe.out" 2>&1
rc=$?
cat "$out/probe.out"
[ $rc -eq 0 ] && echo PASS || echo FAIL
exit $rc
