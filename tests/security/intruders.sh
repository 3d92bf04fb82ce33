#!/usr/bin/env bash
# intruders.sh BIN PARAMS PKI FOREIGN VENDOR DOMAIN: a participant with no identity, or with
# one from another CA, discovers nothing and injects nothing (docs/security.md).
# A secure plant_simulator runs on its own (--security PKI, its default identity) on VENDOR;
# intruders run on both vendors. Checks:
#   plexus topic list --security PKI (identity plexus_topic) shows its topics (the control);
#   plexus topic list without an identity, and with FOREIGN's, shows no topic at all;
#   a secure subscriber (probe_sub) gets the samples of a secure publisher (probe_pub) and
#   none of the samples that intruders without an identity or with FOREIGN's publish on the
#   same topic at the same time, and no intruder matches a reader.
set -u
bin=$1 params=$2 pki=$3 foreign=$4 vendor=$5 domain=$6
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; wait 2>/dev/null; rm -rf "$work"' EXIT
failed=0
check() {  # check EXIT-STATUS WHAT (the status first: an expansion in WHAT would reset $?)
  if [ "$1" -eq 0 ]; then echo "ok    $2"; else echo "FAIL  $2"; failed=1; fi
}
"$bin/plant_simulator" --robot r1 --params "$params" --dds "$vendor" --domain "$domain" --security "$pki" \
  > "$work/plant.log" 2>&1 &
# The control: with an identity of the PKI, the plant's topics show up (discovery and the
# handshakes take a few seconds on a loaded machine).
seen=1
for _ in 1 2 3 4; do
  "$bin/plexus" topic list --json --dds "$vendor" --domain "$domain" --wait 4 --security "$pki" > "$work/list.json" 2> "$work/list.err"
  grep -q '"r1/truth/state"' "$work/list.json" && { seen=0; break; }
done
check $seen "secure plexus topic list ($vendor) sees the secure plant's topics: $(grep -o '"topic":"[^"]*"' "$work/list.json" | tr '\n' ' ')"
for iv in fast cyclone; do
  "$bin/plexus" topic list --json --dds "$iv" --domain "$domain" --wait 6 > "$work/none.json" 2> "$work/none.err"
  [ "$(cat "$work/none.json")" = "[]" ]
  check $? "plexus topic list on $iv without an identity: $(cat "$work/none.json")"
  "$bin/plexus" topic list --json --dds "$iv" --domain "$domain" --wait 6 --security "$foreign" > "$work/foreign.json" 2> "$work/foreign.err"
  [ "$(cat "$work/foreign.json")" = "[]" ]
  check $? "plexus topic list on $iv with an identity of another CA: $(cat "$work/foreign.json")"
done
# Injection: the secure subscriber reads for 12 s at least while intruders publish.
probe=$bin/tests/security_probe
"$probe" sub --dds "$vendor" --domain "$domain" --security "$pki" --identity probe_sub --label legit --expect 5 \
  --min-duration 12 --duration 40 > "$work/sub.log" 2>&1 &
sub=$!
"$probe" pub --dds "$vendor" --domain "$domain" --security "$pki" --identity probe_pub --label legit --duration 40 \
  > "$work/pub.log" 2>&1 &
pub=$!
intruders=()
for iv in fast cyclone; do
  "$probe" pub --dds "$iv" --domain "$domain" --label intruder --duration 12 > "$work/intruder_none_$iv.log" 2>&1 &
  intruders+=($!)
  "$probe" pub --dds "$iv" --domain "$domain" --security "$foreign" --identity probe_pub --label intruder --duration 12 \
    > "$work/intruder_foreign_$iv.log" 2>&1 &
  intruders+=($!)
done
wait $sub
rc=$?
check $rc "secure subscriber ($vendor) got the secure publisher's samples and none of the intruders': $(grep -h '^received' "$work/sub.log")"
wait "${intruders[@]}"
for f in "$work"/intruder_*.log; do
  line=$(grep -h '^published' "$f")
  [[ $line == *"matched 0" ]]
  check $? "intruder $(basename "$f" .log | sed 's/intruder_//'): $line"
done
kill $pub 2>/dev/null
if [ $failed -ne 0 ]; then
  for f in "$work"/*.log "$work"/*.err; do echo "--- $(basename "$f")"; head -5 "$f"; done
fi
exit $failed
