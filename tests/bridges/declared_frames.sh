#!/usr/bin/env bash
# declared_frames.sh BIN_DIR OUT DOMAIN VENDOR
#
# A device's own frames through udp_bridge (issue 30, item 2; docs/bridges.md, "A device's
# own frames"). encoder_board_robot.yaml declares the board's table: position x as an f32,
# y as an i16 of 1 mm, stddev as a u8 of 1 mm, ids 0x40/0x41/0x90 of its own. The device
# emulator plays the board from that file (its samples' SI values before encoding go to
# --truth-times), udp_bridge on VENDOR reads the same file (the link from its options),
# `plexus topic echo` reads r1/position on the other vendor for 8 s. Each published sample
# is matched to the emulator's record by its device time (the board stamps its samples:
# matched within 2 ms, the samples are 10 ms apart), and each field must equal the true
# value within its wire type's quantisation: x within an f32's rounding, y and stddev
# within half a millimetre. The bridge must have dropped nothing for its length or edge check.
set -u
bin=$1 out=$2 domain=$3 vendor=$4
here=$(cd "$(dirname "$0")" && pwd)
robot=$here/encoder_board_robot.yaml
other=cyclone
[ "$vendor" = cyclone ] && other=fast
rm -rf "$out" && mkdir -p "$out"
port=$((40000 + 10 * domain))
pids=()
trap 'for p in "${pids[@]}"; do kill "$p" 2> /dev/null; done' EXIT
"$bin/device_emulator" --params "$robot" --udp-bind 127.0.0.1:$((port + 1)) --udp-peer 127.0.0.1:$port \
  --truth-times "$out/truth.csv" --duration 12 > "$out/emulator.json" 2> "$out/emulator.log" &
emu=$!
pids+=("$emu")
"$bin/udp_bridge" --robot r1 --params "$robot" --bind 127.0.0.1:$port --peer 127.0.0.1:$((port + 1)) \
  --dds "$vendor" --domain "$domain" > "$out/bridge.json" 2> "$out/bridge.log" &
br=$!
pids+=("$br")
"$bin/plexus" topic echo r1/position --dds "$other" --domain "$domain" --csv --duration 8 \
  > "$out/echo.csv" 2> "$out/echo.log"
kill -TERM "$br" 2> /dev/null
wait "$br" "$emu" 2> /dev/null
grep -q "0x40" "$out/emulator.log" || { echo "FAIL: the emulator does not send the declared 0x40: $(head -3 "$out/emulator.log")"; exit 1; }
# echo.csv: receive_time_ns,header.seq_num,header.data_time_ns,...,x,y,z,stddev (by name).
result=$(awk -F, '
  FNR == 1 && NR == FNR { next }
  NR == FNR { if ($1 == 64) { n_t++; t[n_t] = $5; split($6, v, " "); tx[n_t] = v[1]; ty[n_t] = v[2]; ts[n_t] = v[3] } next }
  FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  { dt = $col["header.data_time_ns"]
    # the truth sample nearest in time (both in order: a moving index)
    while (k < n_t && (t[k + 1] <= dt || (t[k + 1] - dt) < (dt - t[k]))) k++
    if (k == 0) { unmatched++; next }
    gap = dt - t[k]; if (gap < 0) gap = -gap
    if (gap > 2e6) { unmatched++; next }
    n++
    ex = $col["x"] - tx[k]; if (ex < 0) ex = -ex; rx = (tx[k] == 0 ? ex : ex / (tx[k] < 0 ? -tx[k] : tx[k])); if (rx > mx) mx = rx
    ey = $col["y"] - ty[k]; if (ey < 0) ey = -ey; if (ey > my) my = ey
    es = $col["stddev"] - ts[k]; if (es < 0) es = -es; if (es > ms) ms = es
    if ($col["y"] != ty[k]) quantised++ }
  END { printf "%d %d %.3g %.3g %.3g %d\n", n, unmatched + 0, mx, my, ms, quantised + 0 }' "$out/truth.csv" "$out/echo.csv")
read -r n unmatched max_x max_y max_s quantised <<< "$result"
link=$(jq -c '.link | {frames_in, framing_errors, rejected_frames, unsynced_frames, clock_exchanges}' "$out/bridge.json" 2> /dev/null)
echo "declared frames ($vendor bridge, $other reader): $n samples matched ($unmatched not), |x - true| / |x| max $max_x (f32: <= 6e-8), |y - true| max $max_y m (i16 of 1e-3: <= 5e-4), |stddev - true| max $max_s m (u8 of 1e-3: <= 5e-4), $quantised of y not exact; bridge: $link"
fail=0
[ "$n" -ge 600 ] || { echo "FAIL: only $n samples matched"; fail=1; }
awk -v a="$max_x" -v b="$max_y" -v c="$max_s" 'BEGIN { exit !(a <= 6e-8 && b <= 5.000001e-4 && c <= 5.000001e-4) }' ||
  { echo "FAIL: a value outside its wire type's quantisation"; fail=1; }
[ "$quantised" -gt 0 ] || { echo "FAIL: every y arrived exact: the i16 of 1 mm was not on the wire"; fail=1; }
[ "$(jq '.link.framing_errors + .link.rejected_frames' "$out/bridge.json")" = 0 ] ||
  { echo "FAIL: the bridge dropped frames: $link"; fail=1; }
[ "$fail" = 0 ] && echo PASS
exit "$fail"
