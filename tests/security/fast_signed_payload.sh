#!/usr/bin/env bash
# fast_signed_payload.sh PROBE PKI DOMAIN: two Fast DDS 2.9 probes under a governance that signs
# each payload on its own (data_protection_kind SIGN, fixture governance_sign_payload.p7s). The
# TerrainClass payload is not a multiple of 4 bytes long, and Fast DDS 2.9 rejects it ("Error
# decoding encoded payload"; fixed upstream by eProsima/Fast-DDS#6498): no sample arrives. This
# is why make_test_pki.sh's signing governance leaves payloads to the submessage signature.
# Also: Fast DDS's errors go to stderr, and the subscriber's stdout holds only its result.
# Passes when all that holds; a Fast DDS that delivers the samples fails it (then the signing
# governance can sign payloads again).
set -u
probe=$1 pki=$2 domain=$3
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
args=(--dds fast --domain "$domain" --security "$pki" --governance governance_sign_payload.p7s)
"$probe" sub "${args[@]}" --identity probe_sub --expect 0 --duration 8 > "$work/out" 2> "$work/err" &
sub=$!
"$probe" pub "${args[@]}" --identity probe_pub --duration 8 > "$work/pub" 2>&1 &
wait $sub
rc=$?
wait
echo "subscriber: exit $rc, stdout: $(cat "$work/out")"
echo "publisher: $(cat "$work/pub" | tail -1)"
errors=$(grep -c "Error decoding encoded payload" "$work/err")
echo "Fast DDS errors on stderr: $errors"
failed=0
[ $rc -eq 0 ] || { echo "FAIL: samples arrived (or the probe failed): Fast DDS checks signed payloads now"; failed=1; }
[ "$errors" -gt 0 ] || { echo "FAIL: no 'Error decoding encoded payload' on stderr"; failed=1; }
[ "$(wc -l < "$work/out")" -eq 1 ] && grep -q "^received 0, " "$work/out" || { echo "FAIL: stdout is not the one result line"; failed=1; }
grep -q "matched 1" "$work/pub" || { echo "FAIL: the publisher never matched the subscriber"; failed=1; }
exit $failed
