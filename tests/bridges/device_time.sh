#!/usr/bin/env bash
# device_time.sh BIN_DIR OUT DOMAIN VENDOR
#
# Device time through udp_bridge (issue 30, item 3; docs/bridges.md, "Device time"). The
# device emulator runs the unicycle of device_time_robot.yaml (position at 100 Hz, Gaussian
# noise so that every sample is unique) with a clock 2.5 s ahead and 150 ppm fast, on a UDP
# link that delays each frame by 0-2 ms at random in each direction, and writes down when it
# took each sample (--truth-times: its device time and the true host time). The bridge runs
# on VENDOR; `plexus topic echo` reads r1/position on the other vendor.
#   Run 1, device time on both ends, 20 s: every sample taken from 10 s on must carry a
#   data_time_ns within 100 us of its true time; the bridge's clock estimate (exit line and
#   heartbeat) must show the drift within 10 ppm and the offset within 1 ms of the truth.
#   Run 2, the same link without device time, 6 s: the arrival stamps are reported beside
#   it; they must be late by the link's delay (median >= 0.5 ms), which shows the jitter
#   was there in run 1 too.
# Prints one summary line per run: median, p99 and max of |data_time - true| in us.
set -u
bin=$1 out=$2 domain=$3 vendor=$4
here=$(cd "$(dirname "$0")" && pwd)
robot=$here/device_time_robot.yaml
other=cyclone
[ "$vendor" = cyclone ] && other=fast
rm -rf "$out" && mkdir -p "$out"
port=$((40000 + 10 * domain))  # as contract.sh: between DDS domains' port ranges
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2> /dev/null; done' EXIT
fail=0

# run NAME SECONDS DEVICE_TIME(0|1)
run() {
  local name=$1 secs=$2 dt=$3 dir=$out/$1
  mkdir -p "$dir"
  local emu_dt=() br_dt=()
  [ "$dt" = 1 ] && emu_dt=(--device-time) && br_dt=(--device-time)
  "$bin/device_emulator" --params "$robot" --udp-bind 127.0.0.1:$((port + 1)) --udp-peer 127.0.0.1:$port \
    --clock-offset 2.5 --clock-drift-ppm 150 --jitter-ms 2 --seed "$domain" "${emu_dt[@]}" \
    --truth-times "$dir/truth.csv" --duration $((secs + 3)) > "$dir/emulator.json" 2> "$dir/emulator.log" &
  local emu=$!
  pids+=("$emu")
  "$bin/udp_bridge" --robot r1 --params "$robot" --bind 127.0.0.1:$port --peer 127.0.0.1:$((port + 1)) \
    "${br_dt[@]}" --dds "$vendor" --domain "$domain" > "$dir/bridge.json" 2> "$dir/bridge.log" &
  local br=$!
  pids+=("$br")
  local beat=""
  if [ "$dt" = 1 ]; then  # the estimate on the wire, in the heartbeat, after 15 s
    (sleep 15; "$bin/plexus" topic echo health/udp_bridge_r1 --dds "$other" --domain "$domain" --json --count 1 \
       > "$dir/heartbeat.json" 2> "$dir/heartbeat.log") &
    beat=$!
    pids+=("$beat")
  fi
  "$bin/plexus" topic echo r1/position --dds "$other" --domain "$domain" --csv --duration "$secs" \
    > "$dir/echo.csv" 2> "$dir/echo.log"
  [ -n "$beat" ] && wait "$beat" 2> /dev/null
  kill -TERM "$br" 2> /dev/null
  wait "$br" "$emu" 2> /dev/null
}

# stats DIR FROM_S: "n median p99 max" of |data_time - true| (us) for samples taken FROM_S
# or more after the first one matched; joined on the sample's x (unique: Gaussian noise).
stats() {
  awk -F, -v from="$2" '
    FNR == 1 { next }
    NR == FNR { if ($1 == 16) truth[sprintf("%.17g", $3)] = $5; next }
    { x = sprintf("%.17g", $6); if (!(x in truth)) next
      t = truth[x]; if (t0 == "") t0 = t
      if ((t - t0) / 1e9 >= from) { e = ($3 - t) / 1e3; print (e < 0 ? -e : e) } }' "$1/truth.csv" "$1/echo.csv" |
    sort -g | awk '{ e[++n] = $1 } END { if (n == 0) { print 0, 0, 0, 0; exit }
                   p = int(0.99 * n); if (p < 1) p = 1
                   printf "%d %.1f %.1f %.1f\n", n, e[int((n + 1) / 2)], e[p], e[n] }'
}

run device_time 20 1
read -r n med p99 max <<< "$(stats "$out/device_time" 10)"
link=$(jq -c .link "$out/device_time/bridge.json" 2> /dev/null)
drift=$(jq -r '.link.clock_drift_ppm // "null"' "$out/device_time/bridge.json" 2> /dev/null)
offset=$(jq -r '.link.clock_offset_s // "null"' "$out/device_time/bridge.json" 2> /dev/null)
# The true offset (device clock minus host clock) at the last sample the emulator took.
true_offset=$(awk -F, 'NR > 1 { d = $4; t = $5 } END { printf "%.9f", d - t / 1e9 }' "$out/device_time/truth.csv")
echo "device time ($vendor bridge, $other reader): $n samples from 10 s: |data_time - true| median $med us, p99 $p99 us, max $max us; bridge: $link"
[ "$n" -ge 900 ] || { echo "FAIL: only $n samples matched from 10 s on"; fail=1; }
awk -v m="$max" 'BEGIN { exit !(m <= 100) }' || { echo "FAIL: a mapped timestamp $max us from the true sample time (> 100 us)"; fail=1; }
awk -v d="$drift" 'BEGIN { exit !(d != "null" && d >= 140 && d <= 160) }' ||
  { echo "FAIL: drift estimate $drift ppm, the device's is 150 ppm"; fail=1; }
awk -v o="$offset" -v t="$true_offset" 'BEGIN { d = o - t; if (d < 0) d = -d; exit !(o != "null" && d <= 1e-3) }' ||
  { echo "FAIL: offset estimate $offset s, true $true_offset s"; fail=1; }
hb=$(jq -r '.link.clock_exchanges // .[0].link.clock_exchanges // empty' "$out/device_time/heartbeat.json" 2> /dev/null | head -1)
[ -n "$hb" ] && [ "$hb" -gt 0 ] 2> /dev/null ||
  { echo "FAIL: the heartbeat carries no clock estimate: $(head -c 300 "$out/device_time/heartbeat.json") $(tail -2 "$out/device_time/heartbeat.log")"; fail=1; }

run arrival 6 0
read -r n2 med2 p992 max2 <<< "$(stats "$out/arrival" 1)"
echo "arrival stamps, same link: $n2 samples: |data_time - true| median $med2 us, p99 $p992 us, max $max2 us"
[ "$n2" -ge 300 ] || { echo "FAIL: only $n2 arrival-stamped samples matched"; fail=1; }
awk -v m="$med2" 'BEGIN { exit !(m >= 500) }' ||
  { echo "FAIL: arrival stamps only $med2 us late: the link's 0-2 ms delay was not applied"; fail=1; }
[ "$fail" = 0 ] && echo PASS
exit "$fail"
