#!/usr/bin/env bash
# two_hosts.sh PLEXUS SCENARIO OUT DOMAIN [launch args...]
# Two network namespaces joined by a veth pair (10.231.0.1 <-> 10.231.0.2, addresses that
# exist only inside them), `plexus launch --host h1` in one and `--host h2` in the other;
# passes if the distributed run gives the same digest as `plexus sim`. The namespaces and
# the veth pair are removed on exit, whatever happens. Needs root (CI runs as root).
# Environment: BOTH="--set k=v ..." goes to `plexus sim` and to both launches (to place a
# scenario's robots and services on h1 and h2); REALTIME=1 runs in realtime instead and
# passes when the run meets the scenario's expectations (no digest: wall-clock loops).
set -u
plexus=$1 scenario=$2 out=$3 domain=$4
shift 4
if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
tag=$$
ns1=plx1_$tag ns2=plx2_$tag v1=plxa$tag v2=plxb$tag
cleanup() {
  [ -n "${h2_pid:-}" ] && kill "$h2_pid" 2>/dev/null
  ip netns del "$ns1" 2>/dev/null
  ip netns del "$ns2" 2>/dev/null
}
trap cleanup EXIT
set -e
ip netns add "$ns1"
ip netns add "$ns2"
ip link add "$v1" type veth peer name "$v2"
ip link set "$v1" netns "$ns1"
ip link set "$v2" netns "$ns2"
ip -n "$ns1" addr add 10.231.0.1/24 dev "$v1"
ip -n "$ns2" addr add 10.231.0.2/24 dev "$v2"
for ns in "$ns1" "$ns2"; do ip -n "$ns" link set lo up; done
ip -n "$ns1" link set "$v1" up
ip -n "$ns2" link set "$v2" up
set +e
read -r -a both <<< "${BOTH:-}"
if [ "${REALTIME:-0}" = 1 ]; then
  set -- "$@" --set clock.mode=realtime
else
  sim=$("$plexus" sim "$scenario" --json --quiet --out "$out/sim" "${both[@]}")
fi
ip netns exec "$ns2" "$plexus" launch "$scenario" --host h2 --domain "$domain" --quiet "${both[@]}" "$@" &
h2_pid=$!
launch=$(ip netns exec "$ns1" "$plexus" launch "$scenario" --host h1 --domain "$domain" --json --quiet --out "$out/launch" "${both[@]}" "$@")
rc=$?
wait "$h2_pid"
h2_rc=$?
h2_pid=
if [ "${REALTIME:-0}" = 1 ]; then
  echo "realtime two-host run: $launch (h1 rc $rc, h2 rc $h2_rc; h1 exits 1 when an expectation fails)"
  [ $rc -eq 0 ] && [ $h2_rc -eq 0 ]
  exit
fi
sim_digest=$(echo "$sim" | sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p')
launch_digest=$(echo "$launch" | sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p')
echo "sim digest $sim_digest, two-host launch digest $launch_digest (h1 rc $rc, h2 rc $h2_rc)"
[ -n "$sim_digest" ] && [ "$sim_digest" = "$launch_digest" ] && [ $rc -eq 0 ] && [ $h2_rc -eq 0 ]
