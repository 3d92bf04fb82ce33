#!/usr/bin/env bash
# capture.sh PROBE PKI VENDOR DOMAIN: what a capture of DDS traffic shows, in a network
# namespace the test creates (and removes), on its loopback, filtered to the domain's ports.
# A probe publisher sends samples whose label is a marker string and whose confidence is
# 0.7071067811865476 (bytes cd 3b 7f 66 9e a0 e6 3f) to a probe subscriber, three times:
#   no security                 : the subscriber gets them, the capture holds marker and value;
#   governance_sign.p7s (signed): the subscriber gets them, the capture still holds both
#                                 (signed, not encrypted);
#   governance.p7s (encrypted)  : the subscriber gets them, the capture holds neither.
# The first two show that the capture and the search work; the third is the claim. The
# probes use --transport udp: between Fast DDS peers, shared memory carries nothing a
# capture could see (docs/runtime.md, Transports).
set -u
probe=$1 pki=$2 vendor=$3 domain=$4
marker=plexus-plaintext-marker-7f3a
value='\xcd\x3b\x7f\x66\x9e\xa0\xe6\x3f'
lo=$((7400 + 250 * domain)) hi=$((7400 + 250 * domain + 249))
ns=plexus_sec_$$
work=$(mktemp -d)
cleanup() { kill $(jobs -p) 2>/dev/null; wait 2>/dev/null; ip netns del "$ns" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
ip netns add "$ns" || { echo "capture.sh: cannot create network namespace $ns (needs root)"; exit 1; }
ip netns exec "$ns" ip link set lo up
failed=0
run() {  # run NAME EXPECT(clear|hidden) [security args...]
  local name=$1 expect=$2
  shift 2
  ip netns exec "$ns" tcpdump -i lo -U -n -w "$work/$name.pcap" udp portrange $lo-$hi 2> "$work/$name.tcpdump" &
  local dump=$!
  for _ in $(seq 100); do grep -q "listening on" "$work/$name.tcpdump" && break; sleep 0.1; done
  ip netns exec "$ns" "$probe" sub --dds "$vendor" --domain "$domain" --label "$marker" --expect 10 --duration 40 --transport udp \
    ${1:+"$@" --identity probe_sub} > "$work/$name.sub" 2>&1 &
  local sub=$!
  ip netns exec "$ns" "$probe" pub --dds "$vendor" --domain "$domain" --label "$marker" --duration 40 --transport udp \
    ${1:+"$@" --identity probe_pub} > "$work/$name.pub" 2>&1 &
  local pub=$!
  wait $sub
  local rc=$?
  kill $pub 2>/dev/null || { echo "the publisher had exited:"; cat "$work/$name.pub"; }
  wait $pub 2>/dev/null
  sleep 0.5
  kill -INT $dump; wait $dump 2>/dev/null
  local packets markers values verdict=ok
  packets=$(tcpdump -r "$work/$name.pcap" -n 2>/dev/null | wc -l)
  markers=$(LC_ALL=C grep -a -o "$marker" "$work/$name.pcap" | wc -l)
  values=$(LC_ALL=C grep -a -o -P "$value" "$work/$name.pcap" | wc -l)
  [ $rc -eq 0 ] && [ "$packets" -gt 20 ] || verdict=FAIL
  if [ "$expect" = clear ]; then
    [ "$markers" -gt 0 ] && [ "$values" -gt 0 ] || verdict=FAIL
  else
    [ "$markers" -eq 0 ] && [ "$values" -eq 0 ] || verdict=FAIL
  fi
  printf '%-9s %s: %s; %d packets captured, marker found %d times, value %d times (expected %s)  %s\n' \
    "$name" "$vendor" "$(grep -h '^received' "$work/$name.sub")" "$packets" "$markers" "$values" "$expect" "$verdict"
  [ $verdict = ok ] || { failed=1; head -5 "$work/$name.sub" "$work/$name.pub" "$work/$name.tcpdump"; }
}
run plain clear
run signed clear --security "$pki" --governance governance_sign.p7s
run encrypted hidden --security "$pki"
exit $failed
