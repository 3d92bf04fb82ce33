#!/usr/bin/env bash
# monitor_rfid.sh PLEXUS VENDOR DOMAIN PORT OUT [LAUNCH_ARGS...]: the RFID scenario
# (deploy/scenarios/wmr_output_feedback_rfid.yaml) in realtime under
# `plexus launch --monitor PORT`, looked at in a real browser: monitor_check.mjs drives Debian's
# chromium with puppeteer-core on http://127.0.0.1:PORT/, kills the controller, and checks
# that its row turns red within 2 s and comes back after the launcher restarts it (restart
# on_failure, 0.5 s restart delay), that every process shows a live heartbeat, and that the
# plot grows. Here: the run goes on to its end (30 s; the page's checks take about 10), and
# then the processes the page showed are exactly those the launcher reports in launch.json,
# and the launch, a controller killed and restarted, ends with 0 or 1 (1: a paper bound
# missed). The page's screenshot: OUT/monitor.png.
set -euo pipefail
plexus=$1 vendor=$2 domain=$3 port=$4 out=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
[ -d "$here/node_modules/puppeteer-core" ] || { echo "npm packages missing: run tools/setup/install_npm.sh"; exit 1; }
command -v chromium > /dev/null || { echo "chromium missing: run tools/setup/install_deps.sh"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
"$plexus" launch "$here/../../deploy/scenarios/wmr_output_feedback_rfid.yaml" --set clock.mode=realtime \
  --set duration=30 --set metrics.0.from=20 --set metrics.1.from=20 --set services.controller.restart_delay=0.5 --dds "$vendor" --domain "$domain" \
  --out "$out/run" --quiet --monitor "$port" "$@" > "$out/launch.stdout" 2> "$out/launch.log" &
launch=$!
trap 'kill -INT "$launch" 2> /dev/null || true' EXIT
fail=0
node "$here/monitor_check.mjs" "http://127.0.0.1:$port/" "$out" controller || fail=1
rc=0
wait "$launch" || rc=$?
trap - EXIT
if [ "$rc" != 0 ] && [ "$rc" != 1 ]; then
  echo "plexus launch exited $rc"; tail -5 "$out/launch.log"; fail=1
fi
planned=$(jq -c '[.services | keys[]] | sort' "$out/run/launch.json" 2> /dev/null || echo null)
shown=$(jq -c '.processes' "$out/page.json" 2> /dev/null || echo null)
echo "launch.json's processes: $planned"
echo "the page's, live:        $shown"
[ "$planned" != null ] && [ "$planned" = "$shown" ] || { echo "FAIL: the page did not show every process live"; fail=1; }
exit $fail
