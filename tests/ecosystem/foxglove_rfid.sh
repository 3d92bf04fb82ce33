#!/usr/bin/env bash
# foxglove_rfid.sh PLEXUS BRIDGE VENDOR DOMAIN PORT OUT MODE: the RFID scenario
# (deploy/scenarios/wmr_output_feedback_rfid.yaml) in realtime, foxglove_bridge on the same
# domain (MODE alone: started by this script; launch: by `plexus launch --foxglove PORT`),
# and a real Foxglove WebSocket client (foxglove_check.mjs: @foxglove/ws-protocol,
# omgidl decoding, @range checks) subscribed to r1/position and r1/cmd for 10 s, while
# `plexus topic hz` measures the same topics over DDS for 6 s inside that. The rates the
# client saw over topic hz's window must be within 5 % of topic hz's. The bridge then stops on SIGTERM and prints its counters: frames
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
  --set duration=30 --set metrics.0.from=20 --set metrics.1.from=20 --dds "$vendor" --domain "$domain" \
  --out "$out/run" --quiet "${extra[@]}" > "$out/launch.log" 2>&1 &
launch=$!
pids+=("$launch")
if [ "$mode" = alone ]; then
  "$bridge" --dds "$vendor" --domain "$domain" --port "$port" > "$out/bridge.json" 2> "$out/bridge.log" &
  bridge_pid=$!
  pids+=("$bridge_pid")
fi
# The client first (it waits for the topics to be advertised), then topic hz over DDS inside
# the client's window, once both topics reach the client.
node "$here/foxglove_check.mjs" "ws://127.0.0.1:$port" 10 "$out/client.json" r1/position r1/cmd &
client=$!
for _ in $(seq 250); do [ -e "$out/client.json.ready" ] && break; sleep 0.1; done
[ -e "$out/client.json.ready" ] || echo "the client got no message within 25 s"
hz_pids=()
for t in r1/position r1/cmd; do
  "$plexus" topic hz "$t" --dds "$vendor" --domain "$domain" --duration 6 --json > "$out/hz_${t//\//_}.json" &
  hz_pids+=("$!")
done
wait "${hz_pids[@]}" || { echo "plexus topic hz failed"; exit 1; }
wait "$client" || { echo "the Foxglove client found mismatches (above)"; exit 1; }
if [ "$mode" = alone ]; then
  kill -TERM "$bridge_pid"
  wait "$bridge_pid" || { echo "foxglove_bridge exit $?"; cat "$out/bridge.log"; exit 1; }
else
  kill -INT "$launch"  # the run has done its part: the launcher stops it, and its bridge
  wait "$launch" || true
  grep '^{' "$out/run/logs/foxglove_bridge.log" > "$out/bridge.json" || { cat "$out/run/logs/foxglove_bridge.log"; exit 1; }
fi
fail=0
# The client's rate over exactly the window topic hz measured (a loaded machine's rate drifts).
for t in r1/position r1/cmd; do
  h=$out/hz_${t//\//_}.json
  hz=$(jq -r .rate_hz "$h")
  ws=$(jq -r --arg t "$t" --argjson a "$(jq .first_receive_ns "$h")" --argjson b "$(jq .last_receive_ns "$h")" \
    '[.[$t].receive_ns[] | select(. >= $a and . <= $b)] | if length > 1 then (length - 1) / ((max - min) / 1e9) else 0 end' \
    "$out/client.json")
  ok=$(awk -v a="$ws" -v b="$hz" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; print (b > 0 && d <= 0.05) ? 1 : 0 }')
  printf '%-14s foxglove %.2f Hz, topic hz %.2f Hz (the same window)\n' "$t" "$ws" "$hz"
  [ "$ok" = 1 ] || { echo "  not within 5 %"; fail=1; }
done
jq -e '.sent > 0 and .clients_seen >= 1' "$out/bridge.json" > /dev/null || { echo "bridge counters: nothing sent"; fail=1; }
kill -INT "$launch" 2> /dev/null || true
wait "$launch" || true
exit $fail
