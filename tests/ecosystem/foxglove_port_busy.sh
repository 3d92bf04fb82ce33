#!/usr/bin/env bash
# foxglove_port_busy.sh BRIDGE PORT: a second foxglove_bridge on a port the first one holds
# must stop at once with one line naming the port, exit 2 (a configuration error, not a
# device that is absent: no retry).
set -u
bridge=$1 port=$2
"$bridge" --port "$port" --domain 214 > /dev/null 2>&1 &
first=$!
trap 'kill $first 2> /dev/null' EXIT
for _ in $(seq 50); do ss -ltn | grep -q "127.0.0.1:$port " && break; sleep 0.1; done
exec "$(dirname "$0")/../scripts/expect_exit.sh" 2 "^foxglove_bridge: error: --port: cannot listen on 127.0.0.1:$port: " \
  "$bridge" --port "$port" --domain 214
