#!/usr/bin/env bash
# pki_fixture.sh OUT: the PKIs of the security tests, made by tools/security/make_test_pki.sh,
# and checked with openssl (every certificate signed by its identity CA, every document
# signed by its permissions CA, each identity's permissions naming its certificate's subject):
#   OUT/pki      the scenario's processes and the probes, unmarked
#   OUT/mixed    the same, marked for a mixed deployment: the launcher, plant and path rank as
#                Fast DDS participants, observer and controller as Cyclone DDS ones
#   OUT/foreign  another CA (an intruder with a valid-looking identity)
set -euo pipefail
out=$1
make_pki=$(cd "$(dirname "$0")/../../tools/security" && pwd)/make_test_pki.sh
rm -rf "$out"
mkdir -p "$out"
"$make_pki" "$out/pki" plant_simulator path observer controller probe_pub probe_sub
"$make_pki" "$out/mixed" plexus_launch:fast plant_simulator:fast path:fast observer:cyclone controller:cyclone \
  probe_cyclone:cyclone probe_fast:fast
"$make_pki" "$out/foreign" probe_pub
for pki in "$out/pki" "$out/mixed" "$out/foreign"; do
  openssl verify -CAfile "$pki/identity_ca.pem" "$pki"/identities/*/cert.pem > /dev/null
  for doc in "$pki"/governance.p7s "$pki"/governance_sign.p7s "$pki"/identities/*/permissions.p7s; do
    openssl smime -verify -text -in "$doc" -CAfile "$pki/permissions_ca.pem" -out /dev/null 2>/dev/null ||
      { echo "pki_fixture: $doc: not signed by $pki/permissions_ca.pem"; exit 1; }
  done
  for id in "$pki"/identities/*/; do
    subject=$(openssl x509 -in "$id/cert.pem" -noout -subject -nameopt RFC2253 | sed 's/^subject=//')
    grep -qF "<subject_name>$subject</subject_name>" "$id/permissions.xml" ||
      { echo "pki_fixture: $id/permissions.xml does not name $subject"; exit 1; }
  done
done
# A governance that signs payloads on their own (data_protection_kind SIGN), which Fast DDS 2.9
# fails to check for payloads whose length is not a multiple of 4 (test security.fast_signed_payload).
sed 's|<data_protection_kind>NONE</data_protection_kind>|<data_protection_kind>SIGN</data_protection_kind>|' \
  "$out/pki/governance_sign.xml" > "$out/pki/governance_sign_payload.xml"
openssl smime -sign -text -in "$out/pki/governance_sign_payload.xml" -out "$out/pki/governance_sign_payload.p7s" \
  -signer "$out/pki/permissions_ca.pem" -inkey "$out/pki/permissions_ca_key.pem"
grep -q "<data_protection_kind>SIGN</data_protection_kind>" "$out/pki/governance_sign_payload.xml"
# The foreign CA is another CA: its identities do not verify against the test PKI's.
if openssl verify -CAfile "$out/pki/identity_ca.pem" "$out/foreign/identities/probe_pub/cert.pem" > /dev/null 2>&1; then
  echo "pki_fixture: the foreign identity verifies against the test CA"; exit 1
fi
echo "pki_fixture: $out: pki, mixed, foreign"
