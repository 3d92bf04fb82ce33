#!/usr/bin/env bash
# loss.sh PLEXUS OUT DOMAIN
# A cell across two network namespaces with 10 % loss and 5 ms delay on the link reports
# them: the best-effort one-way loss at 1 kHz within four binomial standard deviations of
# 10 % (about 1000 pings: 62..138), the one-way p50 5..8 ms and the round trip at least
# 10 ms, on a mixed vendor pair; the burst phase's recovery and every measure are there
# (check_run.py); no namespace is left. Needs root (exit 77, skipped, without it).
set -u
plexus=$1 out=$2 domain=$3
here=$(cd "$(dirname "$0")" && pwd)
[ "$(id -u)" -eq 0 ] || { echo "needs root for network namespaces"; exit 77; }
rm -rf "$out" "$out.log"
mkdir -p "$(dirname "$out")"
"$plexus" bench --pairs fast-cyclone --transports udp --profiles sensor --sizes 64 --rates 1000 --seconds 1 \
  --topologies two_ns --loss 10 --delay-ms 5 --no-vendor-tools --domain "$domain" -o "$out" > "$out.log" 2>&1
rc=$?
[ "$rc" -eq 0 ] || {
  cat "$out.log"
  echo "FAIL: plexus bench exited $rc"
  exit 1
}
cat "$out.log"
python3 "$here/check_run.py" "$out/run.json" --loss-cell fast-cyclone/udp/sensor/64/two_ns --loss 10 --delay-ms 5 || exit 1
ip netns list | grep -q "^plxb" && { echo "FAIL: namespaces left behind: $(ip netns list | grep plxb)"; exit 1; }
echo "PASS: 10 % loss and 5 ms delay on the link reported as given"
