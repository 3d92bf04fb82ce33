#!/usr/bin/env bash
# udp_bind_busy.sh UDP_BRIDGE PARAMS PORT: udp_bridge told to bind a UDP port another program
# holds must stop at once with one line naming the option, exit 2 (it retried forever: a busy
# port is a configuration error, not an absent device).
set -u
bridge=$1 params=$2 port=$3
python3 -c "
import socket, sys, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.bind(('127.0.0.1', $port))
sys.stdout.write('bound\n'); sys.stdout.flush()
time.sleep(20)
" > /tmp/udp_bind_busy_$port.out &
holder=$!
trap 'kill $holder 2> /dev/null' EXIT
for _ in $(seq 50); do grep -q bound /tmp/udp_bind_busy_$port.out 2> /dev/null && break; sleep 0.1; done
exec timeout 20 "$(dirname "$0")/../scripts/expect_exit.sh" 2 \
  "^udp_bridge: error: .*bind: udp 127.0.0.1:$port: cannot bind: Address already in use" \
  "$bridge" --robot r1 --params "$params" --bind "127.0.0.1:$port" --peer "127.0.0.1:$((port + 1))" --domain 214
