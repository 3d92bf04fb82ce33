#!/usr/bin/env bash
# What recording costs (issue 28, docs/tools.md "Recording: what it costs"). Usage, from the
# repository root after the canonical build:
#
#   tools/bench/record_cost.sh [--build DIR] [--out DIR] [--rounds N] [--duration S] [--dds V]
#
# 1. The main job (deploy/scenarios/four_robots.yaml, lockstep, --set duration=S, default
#    the full 120 s) without and with `--record run.mcap`, alternated in ABBA order over N
#    rounds (default 2), so a change in the machine's load hits both alike: steps/s of each
#    run (launch --json), and the CPU time of the launcher and its 13 processes (bash `time`).
# 2. The sizes of that recording as MCAP zstd (written by the run), MCAP lz4 and uncompressed,
#    and SQLite (plexus record convert of it: the same samples).
# 3. `plexus record` (a separate recorder, every topic) beside the main job in realtime for
#    S seconds: the recorder's own CPU time and the samples it wrote.
# Writes OUT/results.md and the raw files beside it. DDS stays on loopback, domain 176
# (perf_table.sh's range). Needs jq.
set -euo pipefail

build=build out="" rounds=2 duration=120 dds=fast
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --duration) duration="$2"; shift 2 ;;
    --dds) dds="$2"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) echo "record_cost.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
plexus="$build/bin/plexus"
[ -x "$plexus" ] || { echo "record_cost.sh: $plexus not found: build first (README)" >&2; exit 2; }
command -v jq > /dev/null || { echo "record_cost.sh: jq not found (apt install jq)" >&2; exit 2; }
out=${out:-record-cost-$(date -u +%Y%m%dT%H%M%SZ)}
mkdir -p "$out"
res="$out/results.md"
scenario=deploy/scenarios/four_robots.yaml
domain=176
load() { cut -d' ' -f1-3 /proc/loadavg; }
{
  echo "# recording cost, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $dds"
  echo "machine: $(nproc) CPUs; load average at start: $(load)"
  echo
  echo "| run | record | steps/s | CPU s (user+sys, launcher and children) | wall s | load (1/5/15 min) |"
  echo "|---|---|---|---|---|---|"
} > "$res"

# run_launch NAME RECORD(0/1): one main-job run; prints "steps_per_s cpu_s wall_s".
run_launch() {
  local name=$1 record=$2 args=()
  [ "$record" = 1 ] && args=(--record "$out/$name.mcap")
  local t0 t1 TIMEFORMAT='%U %S'
  t0=$(date +%s.%N)
  local cpu
  cpu=$( { time "$plexus" launch "$scenario" --set duration="$duration" --dds "$dds" --domain "$domain" --json --quiet \
            --out "$out/$name" "${args[@]}" > "$out/$name.json" 2> "$out/$name.err"; } 2>&1 | tail -1) || true
  t1=$(date +%s.%N)
  local rate
  rate=$(jq -r '.steps_per_s // empty' "$out/$name.json" 2> /dev/null || true)
  [ -n "$rate" ] || { echo "record_cost.sh: $name failed: $(tail -2 "$out/$name.err")" >&2; rate=0; }
  awk -v r="$rate" -v c="$cpu" -v a="$t0" -v b="$t1" 'BEGIN { split(c, u, " "); printf "%.0f %.1f %.1f\n", r, u[1] + u[2], b - a }'
}

declare -a with=() without=()
for r in $(seq 1 "$rounds"); do
  order="0 1"
  [ $((r % 2)) = 0 ] && order="1 0"  # ABBA
  for rec in $order; do
    name="round${r}_$([ "$rec" = 1 ] && echo with || echo without)"
    read -r rate cpu wall <<< "$(run_launch "$name" "$rec")"
    printf '| %s | %s | %s | %s | %s | %s |\n' "$name" "$([ "$rec" = 1 ] && echo "--record (MCAP zstd)" || echo "-")" \
      "$rate" "$cpu" "$wall" "$(load)" | tee -a "$res"
    if [ "$rec" = 1 ]; then with+=("$rate $cpu"); else without+=("$rate $cpu"); fi
  done
done
mw=$(printf '%s\n' "${with[@]}" | awk '{ s += $1; n++ } END { printf "%.0f", s / n }')
mo=$(printf '%s\n' "${without[@]}" | awk '{ s += $1; n++ } END { printf "%.0f", s / n }')
cw=$(printf '%s\n' "${with[@]}" | awk '{ s += $2; n++ } END { printf "%.1f", s / n }')
co=$(printf '%s\n' "${without[@]}" | awk '{ s += $2; n++ } END { printf "%.1f", s / n }')
{
  echo
  echo "mean steps/s: without $mo, with $mw: cost $(awk -v a="$mo" -v b="$mw" 'BEGIN { printf "%.1f", 100 * (a - b) / a }') % (aim <= 5 %)"
  echo "mean CPU s: without $co, with $cw: the recording adds $(awk -v a="$co" -v b="$cw" 'BEGIN { printf "%.1f", b - a }') s"
} | tee -a "$res"

# Sizes: the last recording in every format (the same samples).
rec=$(ls "$out"/round*_with.mcap | tail -1)
"$plexus" record convert "$rec" "$out/sizes_lz4.mcap" --compression lz4 > /dev/null
"$plexus" record convert "$rec" "$out/sizes_none.mcap" --compression none > /dev/null
"$plexus" record convert "$rec" "$out/sizes.sqlite" > /dev/null
n=$("$plexus" record info "$rec" --json | jq -r .messages)
{
  echo
  echo "recording of one run: $n samples, $("$plexus" record info "$rec" --json | jq -r .topics) topics"
  echo
  echo "| format | bytes | bytes/sample |"
  echo "|---|---|---|"
  for f in "$rec:MCAP zstd (default)" "$out/sizes_lz4.mcap:MCAP lz4" "$out/sizes_none.mcap:MCAP uncompressed" "$out/sizes.sqlite:SQLite"; do
    b=$(stat -c %s "${f%%:*}")
    printf '| %s | %s | %.1f |\n' "${f#*:}" "$b" "$(awk -v b="$b" -v n="$n" 'BEGIN { print b / n }')"
  done
} | tee -a "$res"

# 3. plexus record beside the realtime main job.
rt=$((duration < 60 ? duration : 60))
# The two "after 100 s" metrics start within the shortened run (as tests/repro/four_robots.sh --short).
"$plexus" launch "$scenario" --set clock.mode=realtime --set duration=$((rt + 15)) --set metrics.0.from=$((rt + 10)) \
  --set metrics.1.from=$((rt + 10)) --dds "$dds" --domain "$domain" --quiet --out "$out/realtime" > "$out/realtime.log" 2>&1 &
launcher=$!
sleep 8
TIMEFORMAT='%U %S'
cpu=$( { time "$plexus" record --dds "$dds" --domain "$domain" -o "$out/realtime.mcap" --duration "$rt" \
          > "$out/record.out" 2> "$out/record.err"; } 2>&1 | tail -1)
wait "$launcher" || true
samples=$("$plexus" record info "$out/realtime.mcap" --json | jq -r .messages)
{
  echo
  echo "plexus record beside the realtime main job for $rt s: $samples samples ($(awk -v n="$samples" -v t="$rt" 'BEGIN { printf "%.0f", n / t }')/s),"
  echo "recorder CPU $(echo "$cpu" | awk -v t="$rt" '{ printf "%.2f s = %.1f %% of a core", $1 + $2, 100 * ($1 + $2) / t }'), load $(load)"
} | tee -a "$res"
