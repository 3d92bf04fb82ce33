#!/usr/bin/env bash
# quick.sh PLEXUS OUT DOMAIN
# `plexus bench --preset quick` (two vendors, two sizes, a few seconds), as a user's CI runs it:
#  1. it exits 0 and writes run.json, cells.csv and report.html;
#  2. run.json holds every cell of the matrix and every measure of each (check_run.py);
#  3. report.html renders in headless Chromium (report_renders.sh);
#  4. cells.csv has a header and one row per cell and rate.
set -u
plexus=$1 out=$2 domain=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
"$plexus" bench --preset quick --domain "$domain" -o "$out/run" > "$out/bench.log" 2>&1
rc=$?
[ "$rc" -eq 0 ] || {
  tail -20 "$out/bench.log"
  echo "FAIL: plexus bench --preset quick exited $rc"
  exit 1
}
cat "$out/bench.log"
python3 "$here/check_run.py" "$out/run/run.json" || exit 1
"$here/report_renders.sh" "$out/run" "$out/render" || exit 1
rows=$(($(wc -l < "$out/run/cells.csv") - 1))
want=$(python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(sum(max(1, len(c.get('latency') or [])) for c in r['cells']))" "$out/run/run.json")
[ "$rows" -eq "$want" ] || { echo "FAIL: cells.csv has $rows rows, expected $want"; exit 1; }
echo "PASS: quick bench, every cell and measure, report rendered, $rows CSV rows"
