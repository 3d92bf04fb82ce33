#!/usr/bin/env bash
# foxglove_rfid.sh PLEXUS BRIDGE VENDOR DOMAIN PORT OUT MODE: the RFID scenario
# (deploy/scenarios/wmr_output_feedback_rfid.yaml) in realtime, foxglove_bridge on the same
# domain (MODE alone: started by this script; launch: by `plexus launch --foxglove PORT`),
# and a real Foxglove WebSocket client (foxglove_check.mjs: @foxglove/ws-protocol,
# omgidl decoding, @range checks) subscribed to r1/position and r1/cmd for 6 s, while
# `plexus topic hz` measures the same topics over DDS. The rates the client saw must be
# within 5 % of topic hz's. The bridge then stops on SIGTERM and prints its counters: frames
# sent, dropped, and the latency from the DDS sample to the WebSocket send.
set -euo pipefail
plexus=$1 bridge=$2 vendor=$3 domain=$4 port=$5 out=$6 mode=$7
here=$(cd "$(dirname "$0")" && pwd)
[ -d "$here/node_modules/@foxglove/ws-protocol" ] || { echo "npm packages missing: run tools/setup/install_npm.sh"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done; }
trap cleanup EXIT
extra=()
[ "$mode" = launch ] && extra=(--foxglove "$port")
"$plexus" launch "$here/../../deploy/scenarios/wmr_output_feedback_rfid.yaml" --set clock.mode=realtime \
  --set duration=16 --set metrics.0.from=10 --set metrics.1.from=10 --dds "$vendor" --domain "$domain" \
  --out "$out/run" --quiet "${extra[@]}" > "$out/launch.log" 2>&1 &
launch=$!
pids+=("$launch")
if [ "$mode" = alone ]; then
  "$bridge" --dds "$vendor" --domain "$domain" --port "$port" > "$out/bridge.json" 2> "$out/bridge.log" &
  bridge_pid=$!
  pids+=("$bridge_pid")
fi
sleep 4
for t in r1/position r1/cmd; do
  "$plexus" topic hz "$t" --dds "$vendor" --domain "$domain" --duration 7 --json > "$out/hz_${t//\//_}.json" &
  pids+=("$!")
done
node "$here/foxglove_check.mjs" "ws://127.0.0.1:$port" 6 "$out/client.json" r1/position r1/cmd
wait "${pids[@]:$([ "$mode" = alone ] && echo 2 || echo 1)}"
if [ "$mode" = alone ]; then
  kill -TERM "$bridge_pid"
  wait "$bridge_pid" || { echo "foxglove_bridge exit $?"; cat "$out/bridge.log"; exit 1; }
else
  wait "$launch" || true  # the launcher stops its bridge at the end of the run
  grep '^{' "$out/run/logs/foxglove_bridge.log" > "$out/bridge.json" || { cat "$out/run/logs/foxglove_bridge.log"; exit 1; }
fi
fail=0
for t in r1/position r1/cmd; do
  hz=$(jq -r .rate_hz "$out/hz_${t//\//_}.json")
  ws=$(jq -r --arg t "$t" '.[$t].rate_hz' "$out/client.json")
  ok=$(awk -v a="$ws" -v b="$hz" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; print (b > 0 && d <= 0.05) ? 1 : 0 }')
  printf '%-14s foxglove %.2f Hz, topic hz %.2f Hz\n' "$t" "$ws" "$hz"
  [ "$ok" = 1 ] || { echo "  not within 5 %"; fail=1; }
done
jq -e '.sent > 0 and .clients_seen >= 1' "$out/bridge.json" > /dev/null || { echo "bridge counters: nothing sent"; fail=1; }
wait "$launch" || true
exit $fail
