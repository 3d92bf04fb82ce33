#!/usr/bin/env bash
# contract.sh SOURCE VENDOR DOMAIN OUTDIR [BIN_DIR]
#
# One source of robot r1's topics (deploy/params/unicycle_robot.yaml) against the
# simulator's contract (tests/bridges/unicycle_contract.yaml, docs/bridges.md):
#   simulator  plant_simulator
#   serial     device_emulator on a pty + serial_bridge
#   udp        device_emulator on UDP + udp_bridge (ports 40000 + 10*DOMAIN + {0,1})
#   replay     a 12 s recording of the simulator (plexus record), played by plexus replay --restamp
# Each program is started standalone (no launcher). contract_probe (BIN_DIR/tests; BIN_DIR, default the
# build tree's bin/) checks discovery, rates, headers and values, and (not for replay)
# drives the robot with a step command and then lets the command go stale. For the bridges
# the emulator injects link faults (bit flips, garbage, an oversize frame, dropped bytes,
# poisoned values) inside the probe's measurement window: the bridge must count them, the
# probe must see no bad value, and the bridge must have sent STOP frames after the drive.
# Every program must stop on SIGTERM with exit 0, except plexus replay: it exits 1 when a
# signal stops it before the end of its recording ("replayed N of M samples"), so it is let
# run to the end of its 12 s and must then exit 0 having published every sample.
#
# Prints one table row:
#   source | topics/types/QoS | rates | headers | step command | stale -> stop | link faults never published
# and exits 0 only if everything applicable passed.
set -u
source=$1 vendor=$2 domain=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=${5:-$root/build/bin}
params=$root/deploy/params/unicycle_robot.yaml
contract=$here/unicycle_contract.yaml
case $source in simulator|serial|udp|replay) ;; *) echo "contract.sh: SOURCE: simulator, serial, udp or replay"; exit 2 ;; esac
case $vendor in fast|cyclone) ;; *) echo "contract.sh: VENDOR: fast or cyclone"; exit 2 ;; esac
for p in tests/contract_probe plant_simulator plexus; do
  [ -x "$bin/$p" ] || { echo "contract.sh: $bin/$p missing"; exit 2; }
done
case $source in serial) need="device_emulator serial_bridge" ;; udp) need="device_emulator udp_bridge" ;; *) need="" ;; esac
for p in $need; do [ -x "$bin/$p" ] || { echo "contract.sh: $bin/$p missing"; exit 2; }; done
rm -rf "$out" && mkdir -p "$out"
export PLEXUS_QOS_FILE=${PLEXUS_QOS_FILE:-$root/deploy/qos.yaml}
started=$(date +%s.%N)

# --- children: every one is stopped on exit, whatever happens
pids=()
cleanup() {
  local p
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done
  for _ in $(seq 1 50); do
    local alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive -eq 0 ] && break
    sleep 0.1
  done
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
}
trap cleanup EXIT
trap 'exit 130' INT TERM
forget() { local keep=() p; for p in "${pids[@]}"; do [ "$p" != "$1" ] && keep+=("$p"); done; pids=("${keep[@]}"); }

fail_notes=()
note_fail() { fail_notes+=("$1"); echo "FAIL: $1"; }

# stop PID NAME: SIGTERM, at most 10 s, exit code must be 0.
stop() {
  local pid=$1 name=$2 rc
  kill -TERM "$pid" 2>/dev/null
  for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    forget "$pid"
    note_fail "$name did not stop within 10 s of SIGTERM (killed)"
    return 1
  fi
  wait "$pid"
  rc=$?
  forget "$pid"
  [ $rc -eq 0 ] || { note_fail "$name exited $rc on SIGTERM"; return 1; }
  return 0
}

# num FILE KEY: the first "KEY":number in a JSON line (flat counters), else empty.
num() { grep -o "\"$2\":[-0-9.eE+]*" "$1" 2>/dev/null | head -1 | cut -d: -f2; }

start_simulator() {
  "$bin/plant_simulator" --robot r1 --params "$params" --step 0.01 --dds "$vendor" --domain "$domain" \
    > "$out/simulator.out" 2> "$out/simulator.err" &
  sim=$!
  pids+=($sim)
}

# Faults, in s after the emulator's start. The probe's window opens about 3.5 s after it
# (discovery 3 s, then matching) and lasts 8 s; under load processes start later, so the
# faults sit from 6 s to 8.5 s, and the script checks they did land inside the window.
faults=(--fault flip@6:count=5 --fault garbage@6.5:bytes=200 --fault oversize@7 --fault drop@7.5:bytes=6
        --fault poison@8:count=4)
health=""
probe_args=(--drive)

case $source in
  simulator)
    start_simulator
    ;;
  serial|udp)
    if [ "$source" = serial ]; then
      "$bin/device_emulator" --params "$params" --step 0.01 --pty "$out/tty" "${faults[@]}" \
        > "$out/emulator.json" 2> "$out/emulator.err" &
      emu=$!
      pids+=($emu)
      for _ in $(seq 1 100); do [ -e "$out/tty" ] && break; sleep 0.05; done
      [ -e "$out/tty" ] || { note_fail "the emulator made no pty"; cat "$out/emulator.err"; }
      "$bin/serial_bridge" --robot r1 --params "$params" --device "$out/tty" --dds "$vendor" --domain "$domain" \
        > "$out/bridge.json" 2> "$out/bridge.err" &
      bridge=$!
      health=health/serial_bridge_r1
    else
      pe=$((40000 + 10 * domain)) pb=$((40000 + 10 * domain + 1))
      "$bin/device_emulator" --params "$params" --step 0.01 --udp-bind 127.0.0.1:$pe --udp-peer 127.0.0.1:$pb \
        "${faults[@]}" > "$out/emulator.json" 2> "$out/emulator.err" &
      emu=$!
      pids+=($emu)
      "$bin/udp_bridge" --robot r1 --params "$params" --bind 127.0.0.1:$pb --peer 127.0.0.1:$pe --dds "$vendor" \
        --domain "$domain" > "$out/bridge.json" 2> "$out/bridge.err" &
      bridge=$!
      health=health/udp_bridge_r1
    fi
    pids+=($bridge)
    probe_args+=(--health "$health")
    ;;
  replay)
    start_simulator
    "$bin/plexus" record -o "$out/r1.mcap" --topics r1/position,r1/truth/state --duration 12 --dds "$vendor" \
      --domain "$domain" > "$out/record.out" 2> "$out/record.err"
    rc=$?
    [ $rc -eq 0 ] || { note_fail "plexus record exited $rc"; tail -3 "$out/record.err"; }
    stop $sim plant_simulator
    # --wait 10: the replay starts once the probe's readers matched (as under plexus launch).
    "$bin/plexus" replay "$out/r1.mcap" --restamp --topics r1/position,r1/truth/state --wait 10 --dds "$vendor" \
      --domain "$domain" > "$out/replay.out" 2> "$out/replay.err" &
    replay=$!
    pids+=($replay)
    probe_args=(--no-command-reader)
    ;;
esac

"$bin/tests/contract_probe" --dds "$vendor" --domain "$domain" --robot r1 --contract "$contract" --discover 3 --measure 8 \
  "${probe_args[@]}" --label "$source" --out "$out/result.json" 2> "$out/probe.err"
probe_rc=$?
cat "$out/probe.err"
[ $probe_rc -le 1 ] && [ -s "$out/result.json" ] || note_fail "contract_probe exited $probe_rc"

# --- stop the source
case $source in
  simulator) stop $sim plant_simulator ;;
  serial|udp)
    stop $bridge "${source}_bridge"
    stop $emu device_emulator
    emu_end=$(date +%s.%N)
    ;;
  replay)
    # The recording lasts 12 s from the probe's match; the replay then ends by itself.
    for _ in $(seq 1 200); do kill -0 $replay 2>/dev/null || break; sleep 0.1; done
    if kill -0 $replay 2>/dev/null; then
      stop $replay "plexus replay"
    else
      wait $replay
      rc=$?
      forget $replay
      [ $rc -eq 0 ] || note_fail "plexus replay exited $rc: $(cat "$out/replay.out")"
    fi
    echo "replay: $(cat "$out/replay.out")"
    ;;
esac

# --- the table
# check STATUS PREFIX...: pass if every check of the probe whose name starts with one of the
# prefixes passed (and there is one), fail otherwise.
checks_of() {  # name passed: one per line, from the probe's result
  tr -d '\n' < "$out/result.json" | grep -o '"name": *"[^"]*", *"passed": *[a-z]*' |
    sed 's/"name": *"\([^"]*\)", *"passed": *\([a-z]*\)/\1 \2/'
}
column() {
  local prefix n=0 bad=0 name passed
  while read -r name passed; do
    for prefix in "$@"; do
      if [ "${name#"$prefix"}" != "$name" ]; then
        n=$((n + 1))
        [ "$passed" = true ] || bad=$((bad + 1))
      fi
    done
  done < <(checks_of)
  if [ $n -eq 0 ]; then echo fail; elif [ $bad -eq 0 ]; then echo pass; else echo fail; fi
}
and() { [ "$1" = pass ] && [ "$2" = pass ] && echo pass || echo fail; }

discovery=$(column discovery.)
rates=$(column rate.)
headers=$(column headers. values.)
step=n.a. stale=n.a. faults_col=n.a.
if [ "$source" != replay ]; then
  step=$(column drive.step)
  stale=$(column drive.stale_stop)
fi

if [ "$source" = serial ] || [ "$source" = udp ]; then
  echo "bridge:   $(tail -1 "$out/bridge.json")"
  echo "emulator: $(tail -1 "$out/emulator.json")"
  link_ok=pass
  crc=$(num "$out/bridge.json" crc_errors) framing=$(num "$out/bridge.json" framing_errors)
  oversize=$(num "$out/bridge.json" oversize) resyncs=$(num "$out/bridge.json" resyncs)
  rejected=$(num "$out/bridge.json" rejected_frames) stops=$(num "$out/bridge.json" stop_frames)
  forwarded=$(num "$out/bridge.json" commands_forwarded)
  emu_commands=$(num "$out/emulator.json" commands) emu_stops=$(num "$out/emulator.json" stops)
  emu_run=$(num "$out/emulator.json" run_s)
  if [ -z "$crc" ] || [ -z "$emu_run" ]; then
    note_fail "no JSON line from the bridge or the emulator"
    link_ok=fail step=fail stale=fail
  else
    [ $((crc + framing)) -gt 0 ] || { note_fail "bridge: no CRC or framing error counted (flip, drop)"; link_ok=fail; }
    [ "$oversize" -ge 1 ] || { note_fail "bridge: oversize $oversize, expected >= 1"; link_ok=fail; }
    [ "$resyncs" -gt 0 ] || { note_fail "bridge: no resync counted (garbage, oversize)"; link_ok=fail; }
    [ "$rejected" -ge 4 ] || { note_fail "bridge: rejected_frames $rejected, expected >= 4 (poison)"; link_ok=fail; }
    # Every fault applied, inside the probe's measurement window (emulator t0 = its end - run_s).
    win=$(tr -d '\n ' < "$out/result.json" | grep -o '"window":{[^}]*}')
    ws=$(echo "$win" | grep -o '"start_wall_s":[0-9.eE+]*' | cut -d: -f2)
    we=$(echo "$win" | grep -o '"end_wall_s":[0-9.eE+]*' | cut -d: -f2)
    fault_list=$(grep -o '"faults":\[[^]]*\]' "$out/emulator.json")
    n_faults=$(echo "$fault_list" | grep -o '"kind"' | wc -l)
    n_applied=$(echo "$fault_list" | grep -o '"applied":true' | wc -l)
    [ "$n_faults" -eq 5 ] && [ "$n_applied" -eq 5 ] || { note_fail "emulator: $n_applied of $n_faults faults applied: $fault_list"; link_ok=fail; }
    if [ -n "$ws" ] && [ -n "$we" ]; then
      landed=""
      for at in $(echo "$fault_list" | grep -o '"started_at":[0-9.eE+-]*' | cut -d: -f2); do
        inside=$(awk -v end="$emu_end" -v run="$emu_run" -v at="$at" -v ws="$ws" -v we="$we" \
          'BEGIN { t = end - run + at; printf "%s %.2f %.2f", (t >= ws && t + 0.3 <= we) ? "yes" : "no", t - ws, we - t }')
        landed+=" +$(echo "$inside" | cut -d' ' -f2)"
        [ "${inside%% *}" = yes ] ||
          { note_fail "a fault at ${at} s landed outside the measurement window (window start +$(echo "$inside" | cut -d' ' -f2) s, $(echo "$inside" | cut -d' ' -f3) s before its end)"; link_ok=fail; }
      done
      echo "faults (flip, garbage, oversize, drop, poison) at window start$landed s (window $(awk -v a="$ws" -v b="$we" 'BEGIN { printf "%.1f", b - a }') s)"
    else
      note_fail "no measurement window in the probe's result"
      link_ok=fail
    fi
    # The probe saw no bad value on any topic (values.*) while the faults were on the link.
    faults_col=$(and "$link_ok" "$(column values.)")
    # The step command reached the device; after it, STOP frames (the probe checked that the
    # bridge's heartbeat counted new ones after the commands stopped; here the device got them).
    [ "${forwarded:-0}" -ge 100 ] && [ "${emu_commands:-0}" -ge 100 ] ||
      { note_fail "commands: bridge forwarded ${forwarded:-0}, device took ${emu_commands:-0} (200 sent)"; step=fail; }
    [ "${stops:-0}" -gt 0 ] && [ "${emu_stops:-0}" -gt 0 ] ||
      { note_fail "stop frames: bridge sent ${stops:-0}, device took ${emu_stops:-0}"; stale=fail; }
  fi
fi

ok=1
for col in "$discovery" "$rates" "$headers" "$step" "$stale" "$faults_col"; do
  [ "$col" = fail ] && ok=0
done
[ ${#fail_notes[@]} -eq 0 ] || ok=0
took=$(awk -v a="$started" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
echo "took ${took} s"
echo "source | topics/types/QoS | rates | headers | step command | stale -> stop | link faults never published"
printf '%s | %s | %s | %s | %s | %s | %s\n' "$source/$vendor" "$discovery" "$rates" "$headers" "$step" "$stale" "$faults_col" |
  tee "$out/row.txt"
[ $ok -eq 1 ] && exit 0
[ ${#fail_notes[@]} -eq 0 ] || printf 'failed: %s\n' "${fail_notes[@]}"
exit 1
