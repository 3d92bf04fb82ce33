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
. "$(dirname "$0")/netns_pair.sh"
cleanup() {
  [ -n "${h2_pid:-}" ] && kill "$h2_pid" 2>/dev/null
  netns_pair_down
}
trap cleanup EXIT
netns_pair_up
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
