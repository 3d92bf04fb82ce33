#!/usr/bin/env bash
# report_html.sh PLEXUS SCENARIO OUT EXPECT_ROWS PAPER_FIGURES [sim arguments...]
#
# plexus sim, plexus report, then report.html in headless Chromium:
#  1. `plexus report` exits as `plexus sim` did (0 or 1) and writes report.html;
#  2. the page, loaded in Chromium, renders the comparison table with EXPECT_ROWS rows and
#     every <img> of the page decoded (naturalWidth > 0), one per PNG in plots/, the paper
#     figures PAPER_FIGURES (comma-separated file names) among them: a small script added to
#     a copy of the page writes what it finds into the DOM, read back with --dump-dom;
#  3. a screenshot of report.html exists and is not blank (a second page draws it on a
#     canvas and counts the pixels that differ from the background);
#  4. the check itself can fail: with one figure's PNG removed it reports a broken image,
#     with the table's rows removed it reports an empty table.
# Chromium runs as root with --no-sandbox and every flag that keeps it off the network (and
# a host resolver that resolves no name: the pages are local files), each run in a fresh
# --user-data-dir removed on exit.
set -u
plexus=$1 scenario=$2 out=$3 expect_rows=$4 paper_figures=$5
shift 5
fail() { echo "FAIL: $*"; exit 1; }

. "$(dirname "$0")/../scripts/headless_chrome.sh"
[ -n "$chromium_bin" ] || fail "chromium is not installed (tools/setup/install_deps.sh)"

rm -rf "$out"
mkdir -p "$out"
run="$out/run"
"$plexus" sim "$scenario" "$@" --quiet --out "$run" >"$out/sim.out" 2>&1
sim_rc=$?
[ "$sim_rc" -eq 0 ] || [ "$sim_rc" -eq 1 ] || fail "plexus sim exited $sim_rc: $(cat "$out/sim.out")"
"$plexus" report "$run" >"$out/report.out" 2>&1
report_rc=$?
[ "$report_rc" -eq "$sim_rc" ] || fail "plexus report exited $report_rc, plexus sim $sim_rc: $(cat "$out/report.out")"
[ -s "$run/report.html" ] || fail "no report.html"
grep -q '<script' "$run/report.html" && fail "report.html has a script (it must read without JavaScript)"
grep -Eq '(src|href)="(https?:)?//' "$run/report.html" && fail "report.html loads a network resource"
pngs=$(ls "$run"/plots/*.png | wc -l)
[ "$pngs" -ge 1 ] || fail "no PNG in plots/"
for f in ${paper_figures//,/ }; do
  [ -s "$run/plots/$f" ] || fail "no paper figure plots/$f"
  grep -q "src=\"plots/$f\"" "$run/report.html" || fail "report.html does not show plots/$f"
done

# What the page renders: a copy with a script that writes its findings into the DOM.
probe='<script>
window.addEventListener("load", function () {
  var rows = document.querySelectorAll("table.comparison tbody tr");
  var table = document.querySelector("table.comparison");
  var broken = [];
  for (var i = 0; i < document.images.length; ++i) {
    var img = document.images[i];
    if (!img.complete || img.naturalWidth === 0) broken.push(img.getAttribute("src"));
  }
  var pre = document.createElement("pre");
  pre.id = "plexus-check";
  pre.textContent = "rows=" + rows.length + " cells=" + document.querySelectorAll("table.comparison tbody td").length +
      " table_height=" + Math.round(table ? table.getBoundingClientRect().height : 0) +
      " images=" + document.images.length + " broken=" + broken.length + " [" + broken.join(" ") + "]";
  document.body.appendChild(pre);
});
</script>'
probe_page() {  # probe_page HTML_IN: prints the probe's line for that page (in the run folder)
  local page="$run/probe.html"
  awk -v probe="$probe" '/<\/body>/ { print probe } { print }' "$1" >"$page"
  chrome --dump-dom "file://$page" | grep -o 'rows=[0-9]* [^<]*'
  rm -f "$page"
}
verdict() {  # verdict LINE: the problems of a probed page, empty when it is as expected
  local line=$1 rows images broken height
  rows=$(sed -n 's/.*rows=\([0-9]*\).*/\1/p' <<<"$line")
  height=$(sed -n 's/.*table_height=\([0-9]*\).*/\1/p' <<<"$line")
  images=$(sed -n 's/.*images=\([0-9]*\).*/\1/p' <<<"$line")
  broken=$(sed -n 's/.*broken=\([0-9]*\).*/\1/p' <<<"$line")
  [ -n "$rows" ] && [ -n "$images" ] && [ -n "$broken" ] && [ -n "$height" ] || { echo "no probe result"; return; }
  [ "$rows" -eq "$expect_rows" ] || echo "table has $rows rows, expected $expect_rows"
  [ "$rows" -eq 0 ] || [ "$height" -gt 20 ] || echo "table not rendered (height $height px)"
  [ "$images" -eq "$pngs" ] || echo "page has $images images, plots/ has $pngs PNGs"
  [ "$broken" -eq 0 ] || echo "$broken images not rendered: $line"
}

line=$(probe_page "$run/report.html")
echo "report.html: $line"
problems=$(verdict "$line")
[ -z "$problems" ] || fail "report.html: $problems"

# 4. The check catches a missing figure and an empty table.
first_paper=${paper_figures%%,*}
mv "$run/plots/$first_paper" "$out/$first_paper.away"
line=$(probe_page "$run/report.html")
mv "$out/$first_paper.away" "$run/plots/$first_paper"
problems=$(verdict "$line")
grep -q "images not rendered" <<<"$problems" || fail "a missing plots/$first_paper went unnoticed: $line"
echo "missing figure detected: $problems"
sed '/^<tr class=/d' "$run/report.html" >"$run/report.empty.html"
line=$(probe_page "$run/report.empty.html")
rm -f "$run/report.empty.html"
problems=$(verdict "$line")
grep -q "table has 0 rows" <<<"$problems" || fail "an empty table went unnoticed: $line"
echo "empty table detected: $problems"

# 3. The screenshot: exists, and is not blank.
chrome --window-size=1280,2400 --screenshot="$out/screenshot.png" "file://$run/report.html" >/dev/null
[ -s "$out/screenshot.png" ] || fail "no screenshot"
[ "$(head -c 8 "$out/screenshot.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "screenshot is not a PNG"
{
  printf '<!DOCTYPE html><html><body><img id="s" src="data:image/png;base64,'
  base64 -w0 "$out/screenshot.png"
  cat <<'PAGE'
"><script>
window.addEventListener("load", function () {
  var img = document.getElementById("s"), c = document.createElement("canvas");
  c.width = img.naturalWidth; c.height = img.naturalHeight;
  var g = c.getContext("2d"); g.drawImage(img, 0, 0);
  var d = g.getImageData(0, 0, c.width, c.height).data, differ = 0, colours = {};
  for (var i = 0; i < d.length; i += 4) {
    if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) ++differ;
    colours[(d[i] >> 4) + "," + (d[i + 1] >> 4) + "," + (d[i + 2] >> 4)] = 1;
  }
  var pre = document.createElement("pre");
  pre.textContent = "pixels=" + (c.width * c.height) + " differ=" + differ + " colours=" + Object.keys(colours).length;
  document.body.appendChild(pre);
});
</script></body></html>
PAGE
} >"$out/screenshot_check.html"
line=$(chrome --dump-dom "file://$out/screenshot_check.html" | grep -o 'pixels=[0-9]* differ=[0-9]* colours=[0-9]*')
echo "screenshot: $line"
pixels=$(sed -n 's/.*pixels=\([0-9]*\).*/\1/p' <<<"$line")
differ=$(sed -n 's/.*differ=\([0-9]*\).*/\1/p' <<<"$line")
colours=$(sed -n 's/.*colours=\([0-9]*\).*/\1/p' <<<"$line")
[ -n "$pixels" ] && [ "$pixels" -gt 0 ] || fail "screenshot could not be read"
# Not blank: text, table and figures cover well over 2 % of the page, in many colours.
[ $((differ * 50)) -gt "$pixels" ] || fail "screenshot is blank ($differ of $pixels pixels differ from the background)"
[ "$colours" -gt 8 ] || fail "screenshot has only $colours colours"
echo "report.html renders: $expect_rows table rows, $pngs figures, screenshot $out/screenshot.png"
