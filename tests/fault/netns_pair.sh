# Sourced by the network fault tests (tests/fault/*.sh): two network namespaces joined by a
# veth pair, h1 = 10.231.0.1 and h2 = 10.231.0.2 (addresses that exist only inside them, as
# in tests/multihost/two_hosts.sh), and nftables rules inside the namespaces that drop a
# share of the packets crossing the pair, or all of them (a partition). Every namespace and
# rule is created here and removed by `pair_down`, which the caller traps on EXIT; the rules
# live in the namespaces, so they vanish with them, and the host's own ruleset is never touched.
#
#   pair_start OUT       a test's start: root or exit 77, a fresh OUT, `pair_up $$`, `pair_down` on EXIT
#   pair_up TAG          create ns plxf1_TAG / plxf2_TAG ($NS1, $NS2), the veth pair, the rules
#   pair_reset           no loss, no partition, the packet counters at zero
#   pair_loss PERCENT    drop PERCENT % of the packets arriving on each end (both directions)
#   pair_partition       drop every packet crossing the pair, both directions
#   pair_heal            remove the loss and partition rules
#   pair_counters        "dropped N of M" over both ends (what the rules did)
#   pair_packets         packets that arrived on either end so far
#   pair_wait_busy R S   wait (up to S s) until the pair carries R packets/s: a run is stepping
#   pair_partition_dropped  packets the partition rules dropped (read it before pair_heal)
#   pair_down            kill what still runs in the namespaces, delete them
# Needs root (network namespaces, nftables): callers exit 77 (skipped) without it.

pair_start() {
  if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
  trap pair_down EXIT
  rm -rf "$1" && mkdir -p "$1"
  pair_up "$$" || { echo "FAIL: cannot create the namespaces"; exit 1; }
}

pair_up() {
  local tag=$1
  NS1=plxf1_$tag NS2=plxf2_$tag VETH1=plxfa$tag VETH2=plxfb$tag
  ip netns add "$NS1" || return 1
  ip netns add "$NS2" || return 1
  ip link add "$VETH1" type veth peer name "$VETH2" || return 1
  ip link set "$VETH1" netns "$NS1" && ip link set "$VETH2" netns "$NS2" || return 1
  ip -n "$NS1" addr add 10.231.0.1/24 dev "$VETH1" && ip -n "$NS2" addr add 10.231.0.2/24 dev "$VETH2" || return 1
  local ns
  for ns in "$NS1" "$NS2"; do ip -n "$ns" link set lo up || return 1; done
  ip -n "$NS1" link set "$VETH1" up && ip -n "$NS2" link set "$VETH2" up || return 1
  pair_reset
}

# (Re)creates the rules in both namespaces: no loss, no partition, counters at zero. One
# table per namespace: a counter of every packet arriving on the veth end, then the loss and
# partition rules, each in its own chain so that it can be flushed on its own.
pair_reset() {
  local ns dev
  for ns in "$NS1" "$NS2"; do
    dev=$VETH1
    [ "$ns" = "$NS2" ] && dev=$VETH2
    ip netns exec "$ns" nft delete table inet plexus_fault 2>/dev/null
    ip netns exec "$ns" nft -f - <<EOF || return 1
table inet plexus_fault {
  chain loss {
  }
  chain partition {
  }
  chain input {
    type filter hook input priority 0; policy accept;
    iifname "$dev" counter
    iifname "$dev" jump partition
    iifname "$dev" jump loss
  }
  chain output {
    type filter hook output priority 0; policy accept;
    oifname "$dev" jump partition
  }
}
EOF
  done
}

pair_loss() {
  local percent=$1 ns
  for ns in "$NS1" "$NS2"; do
    ip netns exec "$ns" nft flush chain inet plexus_fault loss || return 1
    [ "$percent" -gt 0 ] || continue
    ip netns exec "$ns" nft add rule inet plexus_fault loss numgen random mod 100 "<" "$percent" counter drop || return 1
  done
}

pair_partition() {
  local ns
  for ns in "$NS1" "$NS2"; do
    ip netns exec "$ns" nft add rule inet plexus_fault partition counter drop || return 1
  done
}

pair_heal() {
  local ns
  for ns in "$NS1" "$NS2"; do
    ip netns exec "$ns" nft flush chain inet plexus_fault partition || return 1
    ip netns exec "$ns" nft flush chain inet plexus_fault loss || return 1
  done
}

# Packets counted by the rules, over both ends: "dropped D of N" (N: every packet that arrived
# on a veth end, dropped or not; D: what the loss rules dropped).
pair_counters() {
  local ns total=0 dropped=0 n
  for ns in "$NS1" "$NS2"; do
    n=$(ip netns exec "$ns" nft list chain inet plexus_fault input | sed -n 's/.*iifname.*counter packets \([0-9]*\).*/\1/p' | head -1)
    total=$((total + ${n:-0}))
    n=$(ip netns exec "$ns" nft list chain inet plexus_fault loss | sed -n 's/.*counter packets \([0-9]*\).*/\1/p' | head -1)
    dropped=$((dropped + ${n:-0}))
  done
  echo "dropped $dropped of $total"
}

pair_down() {
  local ns pids
  for ns in "${NS1:-}" "${NS2:-}"; do
    [ -n "$ns" ] || continue
    pids=$(ip netns pids "$ns" 2>/dev/null)
    [ -n "$pids" ] && kill $pids 2>/dev/null
  done
  for ns in "${NS1:-}" "${NS2:-}"; do
    [ -n "$ns" ] && ip netns del "$ns" 2>/dev/null
  done
  [ -n "${VETH1:-}" ] && ip link del "$VETH1" 2>/dev/null  # created but not yet moved into a namespace
  return 0
}

# pair_wait_busy RATE SECONDS: waits until the pair carries at least RATE packets/s (counted
# by the input rules of both ends) over three 0.25 s windows in a row: a run is exchanging
# its samples, not only discovering (discovery announces at a few packets/s). Returns 1 if
# that did not happen within SECONDS.
pair_wait_busy() {
  local rate=$1 limit=$2 prev now busy=0 i
  prev=$(pair_packets)
  for ((i = 0; i < limit * 4; ++i)); do
    sleep 0.25
    now=$(pair_packets)
    if [ $(((now - prev) * 4)) -ge "$rate" ]; then busy=$((busy + 1)); else busy=0; fi
    prev=$now
    [ $busy -ge 3 ] && return 0
  done
  return 1
}

# pair_packets: every packet that arrived on either veth end so far.
pair_packets() {
  local ns total=0 n
  for ns in "$NS1" "$NS2"; do
    n=$(ip netns exec "$ns" nft list chain inet plexus_fault input | sed -n 's/.*iifname.*counter packets \([0-9]*\).*/\1/p' | head -1)
    total=$((total + ${n:-0}))
  done
  echo "$total"
}

# pair_partition_dropped: packets the partition rules dropped so far, over both ends.
pair_partition_dropped() {
  local ns total=0 n
  for ns in "$NS1" "$NS2"; do
    for n in $(ip netns exec "$ns" nft list chain inet plexus_fault partition | sed -n 's/.*counter packets \([0-9]*\).*/\1/p'); do
      total=$((total + n))
    done
  done
  echo "$total"
}
