#!/usr/bin/env bash
# pipeline_live.sh BIN_DIR VENDOR DOMAIN WORK_DIR: `plexus latency pipeline --live` on a
# running ping-pong demo (echo and source started first): the live recording must yield the
# ping -> pong hop and a PNG histogram.
set -u
bin=$1 vendor=$2 domain=$3 work=$4
mkdir -p "$work"
"$bin/demo_node" echo --dds "$vendor" --domain "$domain" --duration 30 &
echo_pid=$!
"$bin/demo_node" source --dds "$vendor" --domain "$domain" --rate 200 --count 2000 > /dev/null &
source_pid=$!
sleep 1
out=$("$bin/plexus" latency pipeline --live --duration 3 --topics demo/ping,demo/pong --dds "$vendor" \
  --domain "$domain" --out "$work" --json)
rc=$?
echo "$out"
kill "$echo_pid" "$source_pid" 2>/dev/null
wait "$echo_pid" "$source_pid" 2>/dev/null
[ $rc -eq 0 ] || { echo "pipeline --live exited $rc"; exit 1; }
echo "$out" | grep -q '"hops":\[{"from":"demo/ping","to":"demo/pong"' || { echo "no ping -> pong hop"; exit 1; }
[ -s "$work/pipeline.png" ] || { echo "no histogram"; exit 1; }
