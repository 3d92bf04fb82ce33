#!/usr/bin/env bash
# Issue 15's figures in one run, each next to its reference measured in the same run
# (docs/performance.md). Usage, from the repository root after the canonical build:
#
#   tools/bench/perf_table.sh [--build DIR] [--out DIR] [--quick]
#
# Writes OUT/table.md (the rows of docs/performance.md's "now" column), and the raw JSON /
# logs beside it. --quick: fewer round trips and shorter loops (a check of the script, not a
# measurement).
# DDS stays on loopback, domains 175-178. Needs jq; the loop row needs cyclictest (rt-tests)
# and the privileges for SCHED_FIFO (root), else that row says why it is missing.
set -euo pipefail

build=build
out=""
quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
    *) echo "perf_table.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
plexus="$build/bin/plexus"
bench="$build/bin/plexus_bench"
[ -x "$plexus" ] || { echo "perf_table.sh: $plexus not found: build first (README)" >&2; exit 2; }
command -v jq >/dev/null || { echo "perf_table.sh: jq not found (apt install jq)" >&2; exit 2; }
out=${out:-perf-$(date -u +%Y%m%dT%H%M%SZ)}
mkdir -p "$out"
table="$out/table.md"

count=5000; loop_s=30; bench_min=0.5
if [ "$quick" = 1 ]; then count=300; loop_s=2; bench_min=0.05; fi

load() { cut -d' ' -f1-3 /proc/loadavg; }
row() { printf '| %s | %s | %s | %s | %s |\n' "$1" "$2" "$3" "$4" "$(load)" | tee -a "$table"; }
num() { printf '%.*f' "$1" "$2"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }'; }

{
  echo "# plexus performance table, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "machine: $(nproc) CPUs, $(uname -r); load average at start: $(load)"
  echo
  echo "| measurement | plexus | reference | ratio | load (1/5/15 min) |"
  echo "|---|---|---|---|---|"
} > "$table"
cat "$table"

# --- 1/2. ping-pong, plexus against the vendor's tool, per vendor, transport and size ---------
transports=$("$plexus" latency pingpong --help 2>&1 | grep -q -- '--transport' && echo "udp shm" || echo "udp")
for vendor in fast cyclone; do
  for transport in $transports; do
    for size in 64 4096; do
      f="$out/pingpong_${vendor}_${transport}_${size}.json"
      topt=()
      [ "$transports" = "udp" ] || topt=(--transport "$transport")
      if "$plexus" latency pingpong --dds "$vendor" "${topt[@]}" --size "$size" --rate 1000 --count "$count" \
           --domain 175 --json > "$f" 2> "$f.err"; then
        tool=$(jq -r '.vendor.implementation // "vendor"' "$f")
        row "ping-pong $vendor $transport $size B, round trip p50 / p99 (us)" \
            "$(jq -r '"\(.plexus.rtt_p50_us|floor) / \(.plexus.rtt_p99_us|floor)"' "$f")" \
            "$tool $(jq -r '"\(.vendor.rtt_p50_us // 0|floor) / \(.vendor.rtt_p99_us // 0|floor)"' "$f")" \
            "$(jq -r '"\((.ratio.p50 // 0) * 100 | round / 100) / \((.ratio.p99 // 0) * 100 | round / 100)"' "$f")"
      else
        row "ping-pong $vendor $transport $size B" "failed: $(tail -1 "$f.err")" "" ""
      fi
    done
  done
done

# --- 4. lockstep against the ddsperf round-trip rate (unpaced, 1 / median round trip) --------
f="$out/ddsperf_rate.json"
"$plexus" latency pingpong --dds cyclone --size 64 --rate 0 --count "$count" --domain 176 --json > "$f" 2> "$f.err"
dds_rate=$(jq -r '1e6 / .vendor.rtt_p50_us | floor' "$f")
row "ddsperf round trips/s (1 / p50 round trip, unpaced, 64 B)" "" "$dds_rate" ""

launch() {  # scenario vendor duration-override -> "<wall s> <steps/s>"
  local sc="$1" vendor="$2" set=("${@:3}") log="$out/launch_$(basename "$1" .yaml)_$2.log"
  "$plexus" launch "deploy/scenarios/$sc" --dds "$vendor" -q --domain 177 -o "$out/runs/${sc%.yaml}_$vendor" \
    "${set[@]}" > "$log" 2>&1 || true
  sed -n 's/.* in lockstep over .*, \([0-9.]*\) s, \([0-9]*\) steps\/s.*/\1 \2/p' "$log" | tail -1
}
for vendor in cyclone fast; do
  read -r wall rate <<< "$(launch wmr_output_feedback_rfid.yaml "$vendor" --set duration=120)" || true
  row "lockstep wmr_output_feedback_rfid $vendor, steps/s against ddsperf's round trips/s" "${rate:-failed}" "$dds_rate" \
      "$(ratio "${rate:-0}" "$dds_rate")"
done
for vendor in cyclone fast; do
  read -r wall rate <<< "$(launch four_robots.yaml "$vendor")" || true
  row "main job four_robots $vendor (120 s simulated), real-time factor" "${wall:-failed} s wall" "120 s" \
      "$(ratio 120 "${wall:-0}")"
done

# --- 5. a fleet of 50 unicycles (tools/scenarios/fleet_unicycles.sh), Cyclone, by service type --
f="$out/fleet.csv"
for mode in lockstep realtime; do
  NS=50 GROUPINGS=type VENDORS=cyclone DURATION=20 DOMAIN=178 BIN="$build/bin" \
    tools/bench/fleet_scale.sh "$mode" "$f" 2>> "$out/fleet.err" || true
done
row "fleet of 50 unicycles, Cyclone, by type: lockstep steps/s" \
    "$(awk -F, '$1 == "lockstep" { printf "%.0f\n", $8 }' "$f" | tail -1)" "" ""
row "fleet of 50 unicycles, Cyclone, by type: realtime 100 Hz, 20 s, deadline misses / stale input reads" \
    "$(awk -F, '$1 == "realtime" { print $11 " / " $12 }' "$f" | tail -1)" "0 / 0 (aim)" ""

# --- 3. loop wake-up lateness against cyclictest --------------------------------------------
f="$out/loop.json"
if "$plexus" latency loop --rate 1000 --duration "$loop_s" --rounds 6 --json > "$f" 2> "$f.err"; then
  row "loop 1 kHz wake-up lateness p50 / p99 (us), against cyclictest" \
      "$(jq -r '"\(.plexus.p50_us * 10 | round / 10) / \(.plexus.p99_us * 10 | round / 10)"' "$f")" \
      "cyclictest $(jq -r '"\(.cyclictest.p50_us // 0) / \(.cyclictest.p99_us // 0)"' "$f")" \
      "$(jq -r '"\((.ratio.p50 // 0) * 100 | round / 100) / \((.ratio.p99 // 0) * 100 | round / 100)"' "$f")"
else
  row "loop 1 kHz" "failed: $(tail -1 "$f.err")" "" ""
fi

# --- 6. algorithm step costs (Google Benchmark, CPU time) -----------------------------------
if [ -x "$bench" ]; then
  f="$out/bench.json"
  "$bench" --benchmark_filter='^(BM_IcrEkfStep|BM_UkfAdditiveStep|BM_VdcEkfStep|BM_VdcEkfStepOnArm/1)$' \
    --benchmark_min_time="$bench_min" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_format=json > "$f" 2> "$f.err"
  for b in BM_IcrEkfStep:0.5 BM_UkfAdditiveStep:0.5 BM_VdcEkfStep:3 BM_VdcEkfStepOnArm/1:3; do
    name=${b%%:*}; aim=${b##*:}
    us=$(jq -r --arg n "${name}_median" '.benchmarks[] | select(.name == $n) | .cpu_time / 1000' "$f")
    row "$name, median CPU time of 3 repetitions (us)" "$(num 3 "$us")" "aim $aim" "$(ratio "$us" "$aim")"
  done
fi
echo "load average at the end: $(load)" | tee -a "$table"
