#!/usr/bin/env bash
# What foxglove_bridge costs (issue 28, docs/viewing.md). Usage, from the repository root
# after the canonical build:
#
#   tools/bench/foxglove_cost.sh [--build DIR] [--out DIR] [--dds V] [--seconds S] [--robots N]
#
# N RFID unicycles (tools/scenarios/fleet_unicycles.sh N; default 2: 10 typed topics at 100 Hz,
# the issue's load, plus a heartbeat per process) in realtime with `plexus launch --foxglove`,
# and one Foxglove client (tests/ecosystem/foxglove_check.mjs, npm packages of
# tests/ecosystem) subscribed to every topic. The bridge's CPU time over S seconds (default
# 20) from the client's first message on every topic (from /proc/PID/stat), the frames it
# sent and dropped, and its latency from the DDS sample to the WebSocket send (p50/p99/max).
# Domain 176 (perf_table.sh's range), port 18799. Writes OUT/results.md.
set -euo pipefail
build=build out="" dds=fast seconds=20 robots=2
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --dds) dds="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --robots) robots="$2"; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "foxglove_cost.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
plexus=$build/bin/plexus
[ -x "$plexus" ] || { echo "foxglove_cost.sh: $plexus not found: build first (README)" >&2; exit 2; }
out=${out:-foxglove-cost-$(date -u +%Y%m%dT%H%M%SZ)}
rm -rf "$out" && mkdir -p "$out"
port=18799 domain=176
tools/scenarios/fleet_unicycles.sh "$robots" type $((2 * seconds + 35)) > "$out/fleet.yaml" ||
  { echo "foxglove_cost.sh: --robots $robots: no such fleet" >&2; exit 2; }
"$plexus" launch "$out/fleet.yaml" --set clock.mode=realtime \
  --dds "$dds" --domain "$domain" --foxglove "$port" --out "$out/run" --quiet > "$out/launch.log" 2>&1 &
launch=$!
sleep 4
pid=$(pgrep -f "foxglove_bridge .*--port $port" | head -1)
[ -n "$pid" ] || { echo "foxglove_cost.sh: no foxglove_bridge running"; kill "$launch"; exit 1; }
ticks() { awk '{ print $14 + $15 }' "/proc/$pid/stat"; }
hz=$(getconf CLK_TCK)
# The client subscribes to every topic; the bridge's CPU is taken over S seconds from its
# first message (the client's own window may run longer: it waits for each topic's first).
node tests/ecosystem/foxglove_check.mjs "ws://127.0.0.1:$port" "$seconds" "$out/client.json" '*' > "$out/client.log" 2>&1 &
client=$!
for _ in $(seq 250); do [ -e "$out/client.json.ready" ] && break; sleep 0.1; done
t0=$(ticks) w0=$(date +%s.%N)
sleep "$seconds"
t1=$(ticks) w1=$(date +%s.%N)
wait "$client" || true
wait "$launch" || true
stats=$(grep '^{' "$out/run/logs/foxglove_bridge.log" || echo '{}')
{
  echo "# foxglove_bridge cost, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $dds"
  echo "machine: $(nproc) CPUs; load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  echo "one client on $(jq 'length' "$out/client.json") topics for $seconds s: $(jq '[.[].messages] | add' "$out/client.json") messages"
  awk -v a="$t0" -v b="$t1" -v h="$hz" -v s="$w0" -v e="$w1" \
    'BEGIN { printf "bridge CPU: %.2f s over %.1f s = %.2f %% of a core (aim <= 5 %%)\n", (b - a) / h, e - s, 100 * (b - a) / h / (e - s) }'
  echo "bridge counters: $stats"
} | tee "$out/results.md"
