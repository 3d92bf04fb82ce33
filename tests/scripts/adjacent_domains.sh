#!/usr/bin/env bash
# adjacent_domains.sh PLEXUS SCENARIO VENDOR_A DOMAIN_A VENDOR_B DOMAIN_B OUT
#
# Two deployments on one host, on different domains, never see each other (issue 33, item
# 1; docs/testing.md, "Known flakiness": twice in CI a process of one test showed up in
# another test's domain). SCENARIO runs under `plexus launch` in realtime on DOMAIN_A with
# VENDOR_A and on DOMAIN_B with VENDOR_B, the second 4 s after the first, with the collision
# that caused the leak forced (step 2 below; docs/runtime.md, "Domains on one host");
# `plexus topic list` on each domain, twice during the run, must show no writer, reader or
# type beyond what the same launch shows when it is alone.
#
# The baselines (each launch alone) and the pair run in network namespaces of their own
# (unshare --net, loopback only), so no other test of the suite can add to the counts or
# take part in a leak: what is checked is the pair alone. Needs root; exit 77 (skip) else.
#
# The launch's own expectations are for its full duration and are not checked here.
#
# Inner mode: adjacent_domains.sh --one TAG SCENARIO VENDOR DOMAIN OUT (one launch and its
# two listings, in the current network namespace).
set -u
run_one() {  # run_one PLEXUS TAG SCENARIO VENDOR DOMAIN OUT
  local plexus=$1 tag=$2 scenario=$3 vendor=$4 domain=$5 out=$6/$2
  mkdir -p "$out"
  "$plexus" launch "$scenario" --set clock.mode=realtime --set duration=20 --quiet --dds "$vendor" --domain "$domain" \
    --out "$out/run" > "$out/launch.out" 2> "$out/launch.err" &
  local launch=$!
  sleep 8
  "$plexus" topic list --json --dds "$vendor" --domain "$domain" --wait 3 > "$out/list1.json" 2> "$out/list1.err"
  sleep 2
  "$plexus" topic list --json --dds "$vendor" --domain "$domain" --wait 3 > "$out/list2.json" 2> "$out/list2.err"
  wait "$launch"
  echo $? > "$out/launch.rc"
}
if [ "${1:-}" = "--one" ]; then
  shift
  plexus=$1
  shift
  run_one "$plexus" "$@"
  exit 0
fi

plexus=$1 scenario=$2 vendor_a=$3 domain_a=$4 vendor_b=$5 domain_b=$6 out=$7
self=$(readlink -f "$0")
unshare --net true 2> /dev/null || {
  echo "SKIP: adjacent_domains.sh needs network namespaces (root)"
  exit 77
}
in_netns() { unshare --net bash -c 'ip link set lo up && exec "$@"' in_netns "$@"; }
rm -rf "$out" && mkdir -p "$out"

# 1. Each launch alone, in a namespace of its own (both at once: the two namespaces cannot
#    reach each other).
in_netns "$self" --one "$plexus" alone_a "$scenario" "$vendor_a" "$domain_a" "$out" &
in_netns "$self" --one "$plexus" alone_b "$scenario" "$vendor_b" "$domain_b" "$out" &
wait
# 2. Both together, in one namespace, with the collision forced that caused the CI sightings:
#    launch b starts while the namespace's ephemeral port range is exactly a's participant
#    ports (7400 + 250 d + 10 .. + 73: the unicast discovery and data ports of participants
#    0-31), so every socket b binds to "any port" lands on one of them; then the range is
#    restored and launch a starts. A Cyclone DDS process reads its transmit socket, which
#    is such a socket, and Fast DDS 2.9 announces itself to every participant port of its
#    domain with no domain id in the announcement (docs/runtime.md, "Domains on one host").
a_ports="$((7400 + 250 * domain_a + 10)) $((7400 + 250 * domain_a + 73))"
in_netns bash -c 'sysctl -qw net.ipv4.ip_local_port_range="$9" && ("$1" --one "$2" pair_b "$3" "$6" "$7" "$8" &
    sleep 4 && sysctl -qw net.ipv4.ip_local_port_range="32768 60999" && "$1" --one "$2" pair_a "$3" "$4" "$5" "$8" & wait)' \
  pair "$self" "$plexus" "$scenario" "$vendor_a" "$domain_a" "$vendor_b" "$domain_b" "$out" "$a_ports"

fail=0
# The most of each topic's writers and readers, and its types, over a launch's two listings.
most() { jq -s 'add | group_by(.topic) | map({topic: .[0].topic, writers: (map(.writers) | max),
                readers: (map(.readers) | max), types: (map(.types[]) | unique)})' "$@"; }
for side in a b; do
  for f in "$out/alone_$side"/list{1,2}.json "$out/pair_$side"/list{1,2}.json; do
    jq -e 'type == "array"' "$f" > /dev/null 2>&1 || {
      echo "FAIL: $f is not a topic list: $(head -c 200 "$f") $(head -c 200 "${f%.json}.err")"
      fail=1
    }
  done
  [ $fail -eq 0 ] || continue
  most "$out/alone_$side"/list{1,2}.json > "$out/alone_$side/most.json"
  most "$out/pair_$side"/list{1,2}.json > "$out/pair_$side/most.json"
  # The run took place: its command topic is there, as alone.
  jq -e 'any(.[]; .topic == "r1/cmd" and .writers >= 1)' "$out/pair_$side/most.json" > /dev/null ||
    {
      echo "FAIL: launch $side of the pair shows no r1/cmd writer: $(cat "$out/pair_$side/launch.err" | tail -3)"
      fail=1
    }
  # Nothing beyond the launch alone: no topic, writer, reader or type more.
  extra=$(jq -c --slurpfile alone "$out/alone_$side/most.json" '[.[] as $t
      | ($alone[0] | map(select(.topic == $t.topic)) | .[0]) as $a
      | select($a == null or $t.writers > $a.writers or $t.readers > $a.readers or ($t.types - $a.types) != [])
      | {topic: $t.topic, pair: {writers: $t.writers, readers: $t.readers, types: $t.types},
         alone: (if $a == null then null else {writers: $a.writers, readers: $a.readers} end)}]' \
    "$out/pair_$side/most.json")
  if [ "$extra" = "[]" ]; then
    echo "ok    domain $([ $side = a ] && echo "$domain_a ($vendor_a)" || echo "$domain_b ($vendor_b)"):" \
      "$(jq length "$out/pair_$side/most.json") topics, as alone"
  else
    echo "FAIL  domain $([ $side = a ] && echo "$domain_a ($vendor_a)" || echo "$domain_b ($vendor_b)") shows more" \
      "with the other launch beside it than alone: $extra"
    fail=1
  fi
done
exit $fail
