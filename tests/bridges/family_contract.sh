#!/usr/bin/env bash
# family_contract.sh FAMILY SOURCE VENDOR DOMAIN OUTDIR [BIN_DIR]
#
# A robot of one family against its simulator's contract (tests/bridges/FAMILY_contract.yaml,
# written from plant_simulator's discovery): the same topics, types and QoS, rates within 5 %,
# headers and values. No drive (the unicycle's contract test, contract.sh, drives):
#   balancing   paper 002, deploy/params/balancing_robot.yaml at a 0.002 s base step (IMU
#               100 Hz, odometry and truth 500 Hz)
#   skid_steer  paper 001, deploy/params/skid_steer_robot.yaml (GPS 20 Hz, tracks, IMU and
#               truth 100 Hz)
#   arm         paper 004, deploy/params/arm_robot.yaml (joint states and truth at 1 kHz; on
#               the serial line at 500 Hz: a 2-joint arm's frames take 140 kB/s at 1 kHz,
#               more than 1 Mbaud carries, docs/bridges.md)
# SOURCE: simulator (plant_simulator), serial (device_emulator on a pty + serial_bridge at
# 1 Mbaud) or udp (device_emulator + udp_bridge on loopback, ports 40000 + 10*DOMAIN + {0,1},
# unpaced).
# Every program is started standalone. Exit 0 only if every check passes.
set -u
family=$1 source=$2 vendor=$3 domain=$4 out=$5
here=$(cd "$(dirname "$0")" && pwd)
bin=${6:-$(cd "$here/../.." && pwd)/build/bin}
params_dir=$(cd "$here/../../deploy/params" && pwd)
case $family in
  balancing) robot=r1 params=$params_dir/balancing_robot.yaml step=0.002 ;;
  skid_steer) robot=r2 params=$params_dir/skid_steer_robot.yaml step=0.01 ;;
  arm) robot=r4 params=$params_dir/arm_robot.yaml step=0.001
    [ "$source" = serial ] && step=0.002 ;;
  *) echo "family_contract.sh: FAMILY: balancing, skid_steer or arm"; exit 2 ;;
esac
contract=$here/${family}_contract.yaml
[ "$family" = arm ] && [ "$source" = serial ] && contract=$here/arm_500hz_contract.yaml
rm -rf "$out" && mkdir -p "$out"
pids=()
trap 'for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done; wait 2>/dev/null' EXIT
# TRANSPORT (environment, optional): auto, udp or shm for the source and the probe.
transport=(--transport "${TRANSPORT:-auto}")
common=(--robot "$robot" --params "$params" --step "$step" --dds "$vendor" --domain "$domain" "${transport[@]}")
case $source in
  simulator)
    "$bin/plant_simulator" "${common[@]}" > "$out/source.out" 2> "$out/source.err" &
    pids+=($!) ;;
  serial)
    "$bin/device_emulator" --params "$params" --step "$step" --pty "$out/tty" --baud 1000000 \
      > "$out/emulator.json" 2> "$out/emulator.err" &
    pids+=($!)
    for _ in $(seq 1 50); do [ -e "$out/tty" ] && break; sleep 0.1; done
    "$bin/serial_bridge" "${common[@]}" --device "$out/tty" > "$out/bridge.json" 2> "$out/bridge.err" &
    pids+=($!) ;;
  udp)
    pe=$((40000 + 10 * domain)) pb=$((40000 + 10 * domain + 1))
    # Unpaced: a UDP link is not a serial line (the emulator paces at 1 Mbaud by default,
    # which a 2-joint arm's 140 kB/s at 1 kHz exceeds).
    "$bin/device_emulator" --params "$params" --step "$step" --udp-bind 127.0.0.1:$pe --udp-peer 127.0.0.1:$pb --baud 0 \
      > "$out/emulator.json" 2> "$out/emulator.err" &
    pids+=($!)
    "$bin/udp_bridge" "${common[@]}" --bind 127.0.0.1:$pb --peer 127.0.0.1:$pe > "$out/bridge.json" 2> "$out/bridge.err" &
    pids+=($!) ;;
  *) echo "family_contract.sh: SOURCE: simulator, serial or udp"; exit 2 ;;
esac
"$bin/tests/contract_probe" --dds "$vendor" --domain "$domain" "${transport[@]}" --robot "$robot" --contract "$contract" \
  --discover 3 --measure 6 --label "$family $source/$vendor" --out "$out/result.json" > "$out/probe.out" 2>&1
rc=$?
cat "$out/probe.out"
for p in "${pids[@]}"; do kill -0 "$p" 2> /dev/null || { echo "a source process had exited:"; tail -3 "$out"/*.err; rc=1; }; done
[ $rc -eq 0 ] && echo PASS || echo FAIL
exit $rc
