# Sourced by the multi-host tests: two network namespaces joined by a veth pair,
# 10.231.0.1 (in $ns1) <-> 10.231.0.2 (in $ns2), addresses that exist only inside them. Their
# names carry the caller's PID, so such tests can run side by side. The caller traps EXIT to
# netns_pair_down first, then calls netns_pair_up (which exits 77, skipped, without root).
netns_pair_up() {
  if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
  local v1=plxa$$ v2=plxb$$
  set -e
  ip netns add "$ns1"
  ip netns add "$ns2"
  ip link add "$v1" type veth peer name "$v2"
  ip link set "$v1" netns "$ns1"
  ip link set "$v2" netns "$ns2"
  ip -n "$ns1" addr add 10.231.0.1/24 dev "$v1"
  ip -n "$ns2" addr add 10.231.0.2/24 dev "$v2"
  ip -n "$ns1" link set lo up
  ip -n "$ns2" link set lo up
  ip -n "$ns1" link set "$v1" up
  ip -n "$ns2" link set "$v2" up
  set +e
}
# Kills what still runs in the namespaces first (SIGTERM, then SIGKILL after 3 s): a process
# started with `ip netns exec` from a backgrounded shell function is that function's child, not
# the $! the caller kills, and deleting a namespace does not end its processes (a test leaked
# its four services this way, left running into later tests).
netns_pair_down() {
  local ns pids i
  for ns in "$ns1" "$ns2"; do
    pids=$(ip netns pids "$ns" 2> /dev/null)
    [ -n "$pids" ] && kill $pids 2> /dev/null
  done
  for i in $(seq 30); do
    pids="$(ip netns pids "$ns1" 2> /dev/null) $(ip netns pids "$ns2" 2> /dev/null)"
    [ -z "${pids// /}" ] && break
    sleep 0.1
  done
  [ -n "${pids// /}" ] && kill -9 $pids 2> /dev/null
  ip netns del "$ns1" 2> /dev/null
  ip netns del "$ns2" 2> /dev/null
  return 0
}
ns1=plx1_$$ ns2=plx2_$$
