#!/usr/bin/env bash
# make_test_pki.sh OUT_DIR [--days N] [--domains MIN-MAX] [NAME[:fast|:cyclone] ...]
#
# A test PKI for DDS Security (docs/security.md), made with openssl alone:
#   OUT_DIR/identity_ca.pem, identity_ca_key.pem        identity CA (signs every identity certificate)
#   OUT_DIR/permissions_ca.pem, permissions_ca_key.pem  permissions CA (signs governance and permissions)
#   OUT_DIR/governance.p7s        discovery, liveliness and every submessage and payload encrypted
#                                 (AES-GCM); join access control on, no unauthenticated participant
#   OUT_DIR/governance_sign.p7s   the same protections signed (GMAC) instead: nothing encrypted
#   Both leave the RTPS message-level protection off (rtps_protection_kind NONE): every submessage
#   is already protected, and with it on a Fast DDS 2.9 <-> Cyclone DDS 0.10 pair failed to
#   exchange its crypto tokens in about half of the secure mixed launches (docs/security.md).
#   governance_sign.p7s does not sign the payload on its own either (its submessage signature
#   covers it): Fast DDS 2.9 fails to check a signed-only payload whose length is not a multiple
#   of 4 (fixed upstream later, eProsima/Fast-DDS#6498).
#   OUT_DIR/identities/NAME/cert.pem, key.pem, permissions.p7s   one identity per name
# The .xml beside each .p7s is the document before signing (S/MIME, signed by the permissions CA).
#
# Identities: every NAME given, plus the tools (plexus_launch, plexus_topic, plexus_record,
# plexus_replay); with no NAME, also one per service executable. Under `plexus launch` a
# process uses the identity named like the process (docs/security.md).
#
# NAME:cyclone / NAME:fast: for a deployment mixing the two vendors under security. Fast DDS 2.9
# starts the authentication handshake with a DH key that Cyclone DDS 0.10 cannot decode, so each
# Cyclone participant must be the one that starts it, which is decided by the certificates'
# subject names (DDS Security 1.1, 9.3.3: the lower adjusted GUID starts). A `:cyclone`
# identity gets a subject whose SHA-256 starts with bit 0, a `:fast` one with bit 1 (a
# serialNumber attribute is added until it does), so every Cyclone identity sorts first.
#
# Keys are ECDSA P-256, unencrypted: a test PKI. Exit 2 for bad arguments.
set -euo pipefail

usage() { echo "usage: make_test_pki.sh OUT_DIR [--days N] [--domains MIN-MAX] [NAME[:fast|:cyclone] ...]" >&2; exit 2; }
die() { echo "make_test_pki.sh: $*" >&2; exit 2; }

[ $# -ge 1 ] || usage
out=$1
shift
days=3650
dmin=0
dmax=230
specs=()
while [ $# -gt 0 ]; do
  case $1 in
    --days) [ $# -ge 2 ] || usage; days=$2; shift 2
            [[ $days =~ ^[0-9]+$ ]] && [ "$days" -ge 1 ] || die "--days: expected a whole number of days >= 1, got '$days'" ;;
    --domains) [ $# -ge 2 ] || usage
               [[ $2 =~ ^([0-9]+)-([0-9]+)$ ]] || die "--domains: expected MIN-MAX (0..230), got '$2'"
               dmin=${BASH_REMATCH[1]}; dmax=${BASH_REMATCH[2]}; shift 2
               [ "$dmin" -le "$dmax" ] && [ "$dmax" -le 230 ] || die "--domains: expected MIN-MAX within 0..230 (Cyclone DDS 0.10 refuses a document naming a higher domain), got '$dmin-$dmax'" ;;
    -h|--help) usage ;;
    -*) die "unknown option '$1'" ;;
    *) specs+=("$1"); shift ;;
  esac
done
command -v openssl >/dev/null || die "openssl not found (Debian package openssl)"

tools=(plexus_launch plexus_topic plexus_record plexus_replay)
services=(plant_simulator localisation_observer motion_controller terrain_classifier icr_estimator attitude_filter
          joint_controller component_host serial_bridge udp_bridge)
[ ${#specs[@]} -gt 0 ] || specs=("${services[@]}")
for t in "${tools[@]}"; do
  found=0
  for s in "${specs[@]}"; do [ "${s%%:*}" = "$t" ] && found=1; done
  [ $found -eq 1 ] || specs+=("$t")
done
for s in "${specs[@]}"; do
  [[ $s =~ ^[A-Za-z0-9_.-]+(:fast|:cyclone)?$ ]] ||
    die "identity '$s': expected NAME (letters, digits, _ . -) with an optional :fast or :cyclone"
done

mkdir -p "$out/identities"
cd "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now=$(date -u +%Y-%m-%dT%H:%M:%S)
until=$(date -u -d "+$days days" +%Y-%m-%dT%H:%M:%S)
org="plexus test PKI $(basename "$(pwd)")"

new_key() { openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$1" 2>/dev/null; }

# A self-signed CA, unless the folder already has it (the script adds identities to a PKI).
make_ca() {  # make_ca FILE_STEM COMMON_NAME
  [ -f "$1.pem" ] && [ -f "$1_key.pem" ] && return 0
  new_key "$1_key.pem"
  openssl req -new -x509 -sha256 -days "$days" -key "$1_key.pem" -subj "/O=$org/CN=$2" -out "$1.pem" \
    -addext "basicConstraints=critical,CA:TRUE" -addext "keyUsage=critical,keyCertSign,cRLSign,digitalSignature" 2>/dev/null
}
make_ca identity_ca "identity CA"
make_ca permissions_ca "permissions CA"

smime_sign() {  # smime_sign IN.xml OUT.p7s
  openssl smime -sign -text -in "$1" -out "$2" -signer permissions_ca.pem -inkey permissions_ca_key.pem
}

# First bit of SHA-256 over the DER subject name of a certificate request: the bit that orders
# participants in the DDS Security handshake.
subject_first_bit() {  # subject_first_bit CSR.der
  local line off hl len
  # The request info's second element (depth 2) is the subject Name.
  line=$(openssl asn1parse -inform DER -in "$1" | awk '/d=2/ {n++; if (n == 2) {print; exit}}')
  [[ $line =~ ^[[:space:]]*([0-9]+):d=2[[:space:]]+hl=([0-9]+)[[:space:]]+l=[[:space:]]*([0-9]+) ]] || die "cannot parse $1"
  off=${BASH_REMATCH[1]} hl=${BASH_REMATCH[2]} len=${BASH_REMATCH[3]}
  local byte
  byte=$(tail -c +$((off + 1)) "$1" | head -c $((hl + len)) | openssl dgst -sha256 -binary | od -An -tu1 -N1 | tr -d ' ')
  echo $((byte >> 7))
}

governance() {  # governance PROTECTION(ENCRYPT|SIGN) DATA_PROTECTION(ENCRYPT|NONE)
  # rtps_protection_kind NONE: see the header.
  cat <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>$dmin</min><max>$dmax</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>$1</discovery_protection_kind>
      <liveliness_protection_kind>$1</liveliness_protection_kind>
      <rtps_protection_kind>NONE</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>$1</metadata_protection_kind>
          <data_protection_kind>$2</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
EOF
}
governance ENCRYPT ENCRYPT > governance.xml
smime_sign governance.xml governance.p7s
governance SIGN NONE > governance_sign.xml
smime_sign governance_sign.xml governance_sign.p7s

for spec in "${specs[@]}"; do
  name=${spec%%:*}
  vendor=
  [[ $spec == *:* ]] && vendor=${spec#*:}
  dir=identities/$name
  mkdir -p "$dir"
  new_key "$dir/key.pem"
  subj="/O=$org/CN=$name"
  n=0
  while :; do
    openssl req -new -sha256 -key "$dir/key.pem" -subj "$subj" -outform DER -out "$tmp/req.der"
    bit=$(subject_first_bit "$tmp/req.der")
    if [ -z "$vendor" ] || { [ "$vendor" = cyclone ] && [ "$bit" = 0 ]; } || { [ "$vendor" = fast ] && [ "$bit" = 1 ]; }; then break; fi
    n=$((n + 1))
    [ $n -le 64 ] || die "identity $name: no subject with the wanted order after 64 tries"
    subj="/O=$org/CN=$name/serialNumber=$n"
  done
  cat > "$tmp/ext.cnf" <<EOF
basicConstraints=critical,CA:FALSE
keyUsage=critical,digitalSignature,keyAgreement
EOF
  openssl x509 -req -sha256 -days "$days" -inform DER -in "$tmp/req.der" -CA identity_ca.pem -CAkey identity_ca_key.pem \
    -CAcreateserial -CAserial "$tmp/ca.srl" -extfile "$tmp/ext.cnf" -out "$dir/cert.pem" 2>/dev/null
  subject=$(openssl x509 -in "$dir/cert.pem" -noout -subject -nameopt RFC2253 | sed 's/^subject=//')
  cat > "$dir/permissions.xml" <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$name">
      <subject_name>$subject</subject_name>
      <validity><not_before>$now</not_before><not_after>$until</not_after></validity>
      <allow_rule>
        <domains><id_range><min>$dmin</min><max>$dmax</max></id_range></domains>
        <publish><topics><topic>*</topic></topics></publish>
        <subscribe><topics><topic>*</topic></topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
EOF
  smime_sign "$dir/permissions.xml" "$dir/permissions.p7s"
  chmod 600 "$dir/key.pem"
done
chmod 600 identity_ca_key.pem permissions_ca_key.pem
echo "make_test_pki.sh: $(pwd): ${#specs[@]} identities (${specs[*]})"
