#!/usr/bin/env bash
# baseline.sh PLEXUS OUT DOMAIN
# --baseline finds a planted regression, and only it: two short runs (two vendor pairs, two
# sizes, 20 Hz, no vendor tools), the second with a 20 ms delay planted in one cell (the
# reader spins before taking each ping of that size in: 40 % of its time at 20 Hz, so no
# queue builds) and --baseline the first. It must exit 1 and flag that cell alone. A third
# run without the plant must exit 0. The thresholds are wide (latency +90 % and at least
# 5 ms, throughput -90 %): in the shared phase of a clean-clone CI, beside the fuzz build, a
# cell's round-trip p50 went from 0.25 to 1.95 ms with nothing planted (2026-11-30), so a
# 1 ms floor took a loaded machine for a regression.
set -u
plexus=$1 out=$2 domain=$3
here=$(cd "$(dirname "$0")" && pwd)
cell=fast-cyclone/udp/latency/4096/one_host
common=(bench --pairs fast-cyclone,cyclone-cyclone --profiles latency --sizes 64,4096 --rates 20 --seconds 2
        --topologies one_host --no-vendor-tools --domain "$domain" --threshold 0.9 --threshold-us 5000)
rm -rf "$out"
mkdir -p "$out"
"$plexus" "${common[@]}" -o "$out/old" > "$out/old.log" 2>&1 || { cat "$out/old.log"; echo "FAIL: the first run failed"; exit 1; }
"$plexus" "${common[@]}" -o "$out/new" --baseline "$out/old" --plant-delay "$cell=20000" > "$out/new.log" 2>&1
rc=$?
cat "$out/new.log"
[ "$rc" -eq 1 ] || { echo "FAIL: --baseline with a planted regression exited $rc, expected 1"; exit 1; }
python3 "$here/check_run.py" "$out/new/run.json" --baseline-flags "$cell" || exit 1
# And without the plant, the same comparison passes (exit 0): the check is not always 1.
"$plexus" "${common[@]}" -o "$out/again" --baseline "$out/old" > "$out/again.log" 2>&1
rc=$?
[ "$rc" -eq 0 ] || { cat "$out/again.log"; echo "FAIL: --baseline without a regression exited $rc, expected 0"; exit 1; }
echo "PASS: the planted regression in $cell flagged alone (exit 1); no plant, exit 0"
