#!/usr/bin/env bash
# mcap_main_job.sh PLEXUS VENDOR DOMAIN OUT [SECONDS]: records a shortened main job
# (deploy/scenarios/four_robots.yaml, every robot and service, in lockstep) with
# `plexus launch --record`, then checks the MCAP file with third-party readers
# (mcap_check.mjs: @mcap/core, @foxglove/omgidl-parser, @foxglove/omgidl-serialization)
# against plexus's own summary (`plexus record info --json`) and its own decoding
# (`plexus topic echo --recording --json`, the first 25 samples of every topic).
# Needs the npm packages of tests/ecosystem (tools/setup/install_npm.sh).
set -euo pipefail
plexus=$1 vendor=$2 domain=$3 out=$4 seconds=${5:-10}
# The two "after 100 s" metrics start within a shortened run (as tests/repro/four_robots.sh --short).
from=$((seconds > 1 ? seconds - 1 : 0))
here=$(cd "$(dirname "$0")" && pwd)
[ -d "$here/node_modules/@mcap/core" ] || { echo "npm packages missing: run tools/setup/install_npm.sh"; exit 1; }
rm -rf "$out" && mkdir -p "$out/echo"
"$plexus" launch "$here/../../deploy/scenarios/four_robots.yaml" --set duration="$seconds" \
  --set metrics.0.from="$from" --set metrics.1.from="$from" --dds "$vendor" --domain "$domain" \
  --record "$out/run.mcap" --out "$out/run" --quiet > "$out/launch.log" 2>&1 || {
  rc=$?
  # The main job fails its paper expectations in a shortened run (exit 1): the recording is what is checked.
  [ $rc -eq 1 ] || { cat "$out/launch.log"; echo "plexus launch exit $rc"; exit 1; }
}
"$plexus" record info "$out/run.mcap" --json > "$out/info.json"
jq -r '.channels[].topic' "$out/info.json" | while read -r topic; do
  "$plexus" topic echo "$topic" --recording "$out/run.mcap" --json --count 25 > "$out/echo/${topic//\//__}.jsonl"
done
jq -e '.complete and .from_summary and .messages > 0' "$out/info.json" > /dev/null || { cat "$out/info.json"; exit 1; }
node "$here/mcap_check.mjs" "$out/run.mcap" "$out/info.json" "$out/echo"
