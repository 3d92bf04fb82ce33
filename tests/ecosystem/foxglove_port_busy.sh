#!/usr/bin/env bash
# foxglove_port_busy.sh BRIDGE PLEXUS SCENARIO PORT OUT: with PORT held by a first foxglove_bridge,
# a second one, and `plexus launch SCENARIO --foxglove PORT`, must each stop at once with one
# line naming the port, exit 2 (a configuration error, not an absent device: no retry).
set -u
bridge=$1 plexus=$2 scenario=$3 port=$4 out=$5
rm -rf "$out" && mkdir -p "$out"
expect=$(dirname "$0")/../scripts/expect_exit.sh
"$bridge" --port "$port" --domain 214 > /dev/null 2>&1 &
first=$!
trap 'kill $first 2> /dev/null' EXIT
for _ in $(seq 50); do ss -ltn | grep -q "127.0.0.1:$port " && break; sleep 0.1; done
"$expect" 2 "^foxglove_bridge: error: --port: cannot listen on 127.0.0.1:$port: " "$bridge" --port "$port" --domain 214 || exit 1
"$expect" 2 "^plexus launch: error: --foxglove: foxglove_bridge stopped at once \(.*foxglove_bridge.log says why\)" \
  "$plexus" launch "$scenario" --foxglove "$port" --domain 214 --out "$out/run" --quiet
