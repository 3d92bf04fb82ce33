#!/usr/bin/env bash
# report_renders.sh REPORT_DIR OUT
#
# The report of `plexus bench` (REPORT_DIR: report.html, plots/, run.json, as
# write_bench_report writes them), loaded in headless Chromium:
#  1. report.html has no script and loads nothing from the network;
#  2. the summary table has one row per ok cell of REPORT_DIR/run.json, the table of cells
#     that did not run one per other cell, at least one best mark; every <img> is decoded
#     (naturalWidth > 0), one per PNG of plots/, each in a figure with a caption: a small script
#     added to a copy of the page (in OUT) writes what it finds into the DOM, read back with
#     --dump-dom;
#  3. the check itself can fail: with a PNG removed from a copy it reports a broken image,
#     with the summary's rows removed it reports the missing rows.
# Prints one line per failure; exits 0 if none, 1 otherwise. Chromium runs with --no-sandbox
# and every flag that keeps it off the network, in a fresh --user-data-dir removed on exit.
set -u
[ $# -eq 2 ] || { echo "usage: $0 REPORT_DIR OUT"; exit 1; }
report=$1 out=$2
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
give_up() {
  fail "$@"
  exit 1
}

. "$(dirname "$0")/../scripts/headless_chrome.sh"
[ -n "$chromium_bin" ] || give_up "chromium is not installed (tools/setup/install_deps.sh)"
command -v python3 >/dev/null || give_up "python3 is not installed"
[ -s "$report/report.html" ] || give_up "no $report/report.html"
[ -s "$report/run.json" ] || give_up "no $report/run.json"

mkdir -p "$out" || give_up "cannot create $out"

# What the page should show, from run.json.
counts=$(python3 -c '
import json, sys
cells = json.load(open(sys.argv[1])).get("cells") or []
ok = sum(1 for c in cells if isinstance(c, dict) and c.get("status") == "ok")
print(ok, len(cells) - ok)' "$report/run.json") || give_up "cannot read $report/run.json"
read -r expect_ok expect_skipped <<<"$counts"
pngs=$(find "$report/plots" -maxdepth 1 -name '*.png' 2>/dev/null | wc -l)

# 1. A static page.
grep -qi '<script' "$report/report.html" && fail "report.html has a script (it must read without JavaScript)"
grep -Eqi '(src|href)="(https?:)?//' "$report/report.html" && fail "report.html loads a network resource"
[ "$pngs" -ge 1 ] || fail "no PNG in $report/plots"

# 2. What the page renders: a copy with a script that writes its findings into the DOM.
probe='<script>
window.addEventListener("load", function () {
  var count = function (q) { return document.querySelectorAll(q).length; };
  var table = document.getElementById("summary");
  var broken = [], uncaptioned = 0;
  for (var i = 0; i < document.images.length; ++i) {
    var img = document.images[i], fig = img.closest("figure");
    if (!img.complete || img.naturalWidth === 0) broken.push(img.getAttribute("src"));
    if (!fig || !fig.querySelector("figcaption") || !fig.querySelector("figcaption").textContent.trim()) ++uncaptioned;
  }
  var pre = document.createElement("pre");
  pre.id = "plexus-check";
  pre.textContent = "rows=" + count("#summary tbody tr[data-cell]") + " skipped=" + count("#skipped tbody tr") +
      " best=" + count("#summary td.best") +
      " table_height=" + Math.round(table ? table.getBoundingClientRect().height : 0) +
      " images=" + document.images.length + " uncaptioned=" + uncaptioned +
      " broken=" + broken.length + " [" + broken.join(" ") + "]";
  document.body.appendChild(pre);
});
</script>'
probe_page() {  # probe_page DIR: the probe line of DIR/report.html (DIR: a copy of the report)
  awk -v probe="$probe" '/<\/body>/ { print probe } { print }' "$1/report.html" >"$1/probe.html"
  chrome --dump-dom "file://$(cd "$1" && pwd)/probe.html" | grep -o 'rows=[0-9]* [^<]*'
}
field() { sed -n "s/.*$1=\([0-9]*\).*/\1/p" <<<"$2"; }
verdict() {  # verdict LINE: the problems of a probed page, one a line; none if it is as expected
  local line=$1 rows skipped best height images uncaptioned broken
  rows=$(field rows "$line") skipped=$(field skipped "$line") best=$(field best "$line")
  height=$(field table_height "$line") images=$(field images "$line")
  uncaptioned=$(field uncaptioned "$line") broken=$(field broken "$line")
  [ -n "$rows" ] && [ -n "$skipped" ] && [ -n "$best" ] && [ -n "$height" ] && [ -n "$images" ] &&
    [ -n "$uncaptioned" ] && [ -n "$broken" ] || { echo "no probe result (chromium: $out/chromium.log)"; return; }
  [ "$rows" -eq "$expect_ok" ] || echo "summary table has $rows rows, run.json has $expect_ok ok cells"
  [ "$rows" -eq 0 ] || [ "$height" -gt 20 ] || echo "summary table not rendered (height $height px)"
  [ "$skipped" -eq "$expect_skipped" ] || echo "table of skipped cells has $skipped rows, expected $expect_skipped"
  [ "$expect_ok" -lt 2 ] || [ "$best" -ge 1 ] || echo "no best mark in the summary table"
  [ "$images" -eq "$pngs" ] || echo "page has $images images, plots/ has $pngs PNGs"
  [ "$uncaptioned" -eq 0 ] || echo "$uncaptioned images without a figure caption"
  [ "$broken" -eq 0 ] || echo "$broken images not rendered: $line"
}
copy_of() {  # copy_of NAME: a fresh copy of the report in OUT/NAME
  rm -rf "${out:?}/$1"
  mkdir -p "$out/$1" && cp -r "$report/report.html" "$report/plots" "$out/$1/" || give_up "cannot copy $report to $out/$1"
}

copy_of page
line=$(probe_page "$out/page")
echo "report.html: $line"
while IFS= read -r problem; do [ -z "$problem" ] || fail "report.html: $problem"; done <<<"$(verdict "$line")"

# 3. The check catches a broken image and missing rows.
copy_of broken
first_png=$(grep -o 'src="plots/[^"]*\.png"' "$out/broken/report.html" | head -1 | sed 's/^src="//; s/"$//')
if [ -n "$first_png" ]; then
  rm -f "$out/broken/$first_png"
  line=$(probe_page "$out/broken")
  problems=$(verdict "$line")
  grep -q "images not rendered" <<<"$problems" || fail "a missing $first_png went unnoticed: $line"
  echo "missing figure detected: $(grep "images not rendered" <<<"$problems")"
fi
if [ "$expect_ok" -gt 0 ]; then
  copy_of norows
  sed -i '/^<tr data-cell=/d' "$out/norows/report.html"
  line=$(probe_page "$out/norows")
  problems=$(verdict "$line")
  grep -q "summary table has 0 rows" <<<"$problems" || fail "an empty summary table went unnoticed: $line"
  echo "empty table detected: $(grep "summary table has" <<<"$problems")"
fi

[ "$failures" -eq 0 ] || exit 1
echo "report renders: $expect_ok summary rows, $expect_skipped skipped cells, $pngs figures"
