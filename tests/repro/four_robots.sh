#!/usr/bin/env bash
# four_robots.sh PLEXUS SCENARIO OUT DOMAIN: the main job, shortened to 6 s of simulated
# time: every service as its own process over DDS must give the same digest as `plexus sim`
# of the same settings, and `--report` must tabulate every metric against the papers.
set -u
plexus=$1 scenario=$2 out=$3 domain=$4
rm -rf "$out"
short=(--set duration=6 --set metrics.0.from=5 --set metrics.1.from=5)
sim=$("$plexus" sim "$scenario" "${short[@]}" --json --quiet --out "$out/sim" 2>/dev/null)
launch=$("$plexus" launch "$scenario" "${short[@]}" --json --quiet --report --domain "$domain" --out "$out/launch")
rc=$?
sim_digest=$(echo "$sim" | sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p')
launch_digest=$(echo "$launch" | sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p')
processes=$(echo "$launch" | grep -o '"program":' | wc -l)
rows=$(grep -c '^| [a-z_0-9]* | .* | \(pass\|FAIL\) |$' "$out/launch/report.md" 2>/dev/null)
echo "sim digest $sim_digest, launch digest $launch_digest (rc $rc), $processes processes, $rows compared metrics"
[ -n "$sim_digest" ] && [ "$sim_digest" = "$launch_digest" ] || { echo "digests differ"; exit 1; }
[ "$processes" -eq 13 ] || { echo "expected 13 processes (plant_simulator and 12 services)"; exit 1; }
[ "$rows" -eq 13 ] || { echo "report.md should compare 13 metrics with the papers"; exit 1; }
[ $rc -le 1 ] || { echo "launch failed"; exit 1; }
