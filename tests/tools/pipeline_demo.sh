#!/usr/bin/env bash
# pipeline_demo.sh BIN_DIR VENDOR DOMAIN WORK_DIR: records the ping-pong demo and runs
# `plexus latency pipeline` on the recording (JSON with per-hop and end-to-end figures, PNG).
set -eu
bin=$1 vendor=$2 domain=$3 work=$4
mkdir -p "$work"
f=$work/demo.mcap
"$bin/demo_node" echo --dds "$vendor" --domain "$domain" --duration 30 &
echo_pid=$!
"$bin/plexus" record --dds "$vendor" --domain "$domain" --topics demo/ping,demo/pong -o "$f" --count 400 --duration 25 --wait 10 &
rec=$!
sleep 1
"$bin/demo_node" source --dds "$vendor" --domain "$domain" --rate 200 --count 200 > /dev/null
wait $rec
kill $echo_pid; wait $echo_pid || true
out=$("$bin/plexus" latency pipeline "$f" --out "$work" --json)
echo "$out"
echo "$out" | grep -q '"hops":\[{"from":"demo/ping","to":"demo/pong"' || { echo "no ping -> pong hop"; exit 1; }
test -s "$work/pipeline.png"
