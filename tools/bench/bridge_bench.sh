#!/usr/bin/env bash
# bridge_bench.sh BIN_DIR OUT_DIR [SECONDS]
#
# Measures the bridges against the device emulator (cases 1-2: the serial bridge on a pty,
# Fast DDS; case 3: udp_bridge on each vendor):
#   1. latency from a frame's arrival to its topic's publication, p50/p99/max (the bridge's
#      own counters), with the emulator pacing its bytes at 115200 and at 1000000 baud
#      (unicycle, sensors at 100 Hz: 80 bytes per 10 ms, within 115200 baud's 11.5 kB/s);
#   2. CPU use of the bridge (and the emulator) at 1 kHz: truth and RFID position frames at
#      1 kHz each in (the sensor runs at the base rate), a 1 kHz command stream
#      (component_host constant_command) out, 1000000 baud;
#   3. the flexible-joint arm's 1 kHz loop through udp_bridge on each vendor (below).
# Prints one JSON line per measurement. A report, not a test: timing goals live here.
set -u
bin=$1 out=$2 secs=${3:-20}
params=$(cd "$(dirname "$0")/../../deploy/params" && pwd)/unicycle_robot.yaml
mkdir -p "$out"
domain=145
pids=()
cleanup() { for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done; wait 2>/dev/null; }
trap cleanup EXIT

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }

run() {  # run LABEL BAUD STEP CMD_RATE
  local label=$1 baud=$2 step=$3 rate=$4
  rm -f "$out/$label.tty"
  "$bin/device_emulator" --params "$params" --step "$step" --pty "$out/$label.tty" --baud "$baud" \
    > "$out/$label.emulator.json" 2> "$out/$label.emulator.err" &
  local emu=$!
  for _ in $(seq 1 50); do [ -e "$out/$label.tty" ] && break; sleep 0.1; done
  "$bin/serial_bridge" --robot r1 --params "$params" --step "$step" --device "$out/$label.tty" --baud "$baud" \
    --input-rate "cmd=$rate" --domain $domain --log-level warn > "$out/$label.bridge.json" 2> "$out/$label.bridge.err" &
  local bridge=$!
  "$bin/component_host" --robot r1 --type constant_command --set v=0.05 --set omega=0.0 --set rate=$rate \
    --domain $domain --log-level warn > /dev/null 2>&1 &
  local cmd=$!
  pids=($emu $bridge $cmd)
  sleep 2
  local b0 e0 t0 b1 e1 t1
  b0=$(cpu_ticks $bridge) e0=$(cpu_ticks $emu) t0=$(date +%s.%N)
  sleep "$secs"
  b1=$(cpu_ticks $bridge) e1=$(cpu_ticks $emu) t1=$(date +%s.%N)
  kill -TERM $cmd $bridge; wait $cmd $bridge 2>/dev/null
  kill -TERM $emu; wait $emu 2>/dev/null
  pids=()
  local hz; hz=$(getconf CLK_TCK)
  local link; link=$(grep -o '"link":{[^}]*}' "$out/$label.bridge.json" | head -1)
  awk -v l="$label" -v baud="$baud" -v b="$((b1 - b0))" -v e="$((e1 - e0))" -v t0="$t0" -v t1="$t1" -v hz="$hz" -v link="$link" \
    'BEGIN { dt = t1 - t0; printf "{\"run\":\"%s\",\"baud\":%d,\"seconds\":%.1f,\"bridge_cpu_percent\":%.2f,\"emulator_cpu_percent\":%.2f,%s}\n", l, baud, dt, 100 * b / hz / dt, 100 * e / hz / dt, link }'
}

run latency_115200 115200 0.01 100
run latency_1000000 1000000 0.01 100
run cpu_1khz 1000000 0.001 1000

# 3. The flexible-joint arm at 1 kHz through udp_bridge (issue 30), on each vendor: paper 004's
#    loop (arm_vdc_ekf.yaml, reference, EKF and VDC in one process) under `plexus launch`, the
#    emulator on the far end (unpaced, device time, the run's cycle; every loop at SCHED_FIFO 60
#    as in bridges.closed_loop_arm_udp_*): 2000 frames/s in (joint states and truth, 48 + 80
#    bytes), 1000 commands/s out. The bridge's CPU over seconds 2-10 of a 12 s run.
deploy=$(cd "$(dirname "$0")/../../deploy" && pwd)
run_arm() {  # run_arm VENDOR
  local vendor=$1 label=arm_1khz_udp_$1 pe=$((40000 + 10 * domain)) pb=$((40000 + 10 * domain + 1))
  rm -rf "$out/$label"
  "$bin/plexus" launch "$deploy/scenarios/arm_vdc_ekf.yaml" --set clock.mode=realtime --set step=0.001 --set duration=12 \
    --set clock.input_deadline_periods=20 --set services.reference.process=control \
    --set services.observer.process=control --set services.controller.process=control \
    --set services.observer.blind_after_s=0.01 --set "expectations={}" \
    --set services.reference.priority=60 --set services.observer.priority=60 \
    --set services.controller.priority=60 --set robots.arm.priority=60 \
    --set "robots.arm.source={type: udp_bridge, bind: 127.0.0.1:$pb, peer: 127.0.0.1:$pe, device_time: true, cycle_sync: true}" \
    --dds "$vendor" --domain $domain --json --quiet --out "$out/$label" > "$out/$label.json" 2> "$out/$label.err" &
  local launch=$!
  local part="$out/$label/parts/udp_bridge_arm.yaml"
  for _ in $(seq 1 100); do [ -s "$part" ] && break; sleep 0.05; done
  "$bin/device_emulator" --part "$part" --udp-bind 127.0.0.1:$pe --udp-peer 127.0.0.1:$pb --baud 0 --hold-until-command \
    --priority 60 > "$out/$label.emulator.json" 2> "$out/$label.emulator.err" &
  local emu=$!
  pids=($launch $emu)
  local bridge=""
  for _ in $(seq 1 100); do
    bridge=$(pgrep -f "udp_bridge --part $part" | head -1)
    [ -n "$bridge" ] && break
    sleep 0.05
  done
  sleep 2
  local b0 e0 t0 b1 e1 t1
  b0=$(cpu_ticks $bridge) e0=$(cpu_ticks $emu) t0=$(date +%s.%N)
  sleep 8
  b1=$(cpu_ticks $bridge) e1=$(cpu_ticks $emu) t1=$(date +%s.%N)
  wait $launch
  kill -TERM $emu; wait $emu 2>/dev/null
  pids=()
  local hz; hz=$(getconf CLK_TCK)
  local link; link=$(grep -ho '{"service":"udp_bridge arm".*}' "$out/$label/logs/"*.log | tail -1 | grep -o '"link":{[^}]*}')
  awk -v l="$label" -v b="$((b1 - b0))" -v e="$((e1 - e0))" -v t0="$t0" -v t1="$t1" -v hz="$hz" -v link="$link" \
    -v rms="$(jq -c '[.rms_e1_mrad, .rms_e2_mrad]' "$out/$label.json" 2> /dev/null)" \
    'BEGIN { dt = t1 - t0; printf "{\"run\":\"%s\",\"seconds\":%.1f,\"bridge_cpu_percent\":%.2f,\"emulator_cpu_percent\":%.2f,\"rms_e_mrad\":%s,%s}\n", l, dt, 100 * b / hz / dt, 100 * e / hz / dt, rms, link }'
}
run_arm fast
run_arm cyclone
