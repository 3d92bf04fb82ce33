#!/usr/bin/env bash
# fleet_scale.sh lockstep|realtime OUT.csv [options]
#
# Issue 15 section 5 (scale in robots): runs the fleet scenario
# (tools/scenarios/fleet_unicycles.sh N GROUPING) under `plexus launch` for each N and
# grouping, and appends one CSV row per run to OUT.csv (header written when the file is new).
# A report, not a test: the figures depend on the machine and its load, recorded per row.
#
#   lockstep: steps/s of the lockstep run (launch --json `steps_per_s`: the clock's steps over
#             the wall time of the run, start-up excluded);
#   realtime: clock.mode=realtime at the scenario's 100 Hz; the per-service loop counters of
#             launch.json (`services.<process>`: overruns = deadline misses of its loop,
#             stale_input_reads, late_input_reads), summed and the worst process named.
#
# Options (environment):
#   NS="1 5 10 25 50"        robot counts
#   GROUPINGS="type robot"   fleet_unicycles.sh groupings
#   VENDORS="cyclone"        fast | cyclone, each in turn
#   DURATION=10              s of simulated time per run (realtime: of wall time), given to the
#                            generator (a short run has its own expectations: fleet_unicycles.sh)
#   DOMAIN=195               DDS domain of the runs (issue 15: 195-199 for this part)
#   TRANSPORT=               auto | udp | shm, given to plexus launch --transport (empty: the
#                            scenario's, auto)
#   PRIORITY=                realtime: SCHED_FIFO priority 1..99 of every loop (each robot's
#                            and each service's `priority`; empty: normal scheduling)
#   BIN=build/bin            where plexus is
#   KEEP=                    non-empty: keep the run folders (under OUT.csv's folder, runs-*)
#
# Columns: mode,vendor,grouping,n,processes,duration_s,rc,steps_per_s,wall_s,startup_s,
#   overruns,stale_input_reads,late_input_reads,loops,worst_process,worst_overruns,
#   worst_stale,load1,load5,load15,utc
# (steps_per_s, wall_s empty in realtime; the loop columns empty in lockstep).
set -u
mode=${1:?usage: fleet_scale.sh lockstep|realtime OUT.csv}
out=${2:?usage: fleet_scale.sh lockstep|realtime OUT.csv}
case $mode in lockstep | realtime) ;; *) echo "fleet_scale.sh: mode '$mode': lockstep or realtime" >&2; exit 2 ;; esac
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
gen=$root/tools/scenarios/fleet_unicycles.sh
bin=${BIN:-$root/build/bin}
NS=${NS:-"1 5 10 25 50"}
GROUPINGS=${GROUPINGS:-"type robot"}
VENDORS=${VENDORS:-cyclone}
DURATION=${DURATION:-10}
DOMAIN=${DOMAIN:-195}
command -v jq > /dev/null || { echo "fleet_scale.sh: needs jq (Debian package jq)" >&2; exit 2; }
[ -x "$bin/plexus" ] || { echo "fleet_scale.sh: $bin/plexus: not built" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
outdir=$(dirname "$out")
mkdir -p "$outdir"
[ -s "$out" ] || echo "mode,vendor,grouping,n,processes,duration_s,rc,steps_per_s,wall_s,startup_s,overruns,stale_input_reads,late_input_reads,loops,worst_process,worst_overruns,worst_stale,load1,load5,load15,utc" > "$out"

for vendor in $VENDORS; do
  for grouping in $GROUPINGS; do
    for n in $NS; do
      scen=$work/fleet_${n}_${grouping}.yaml
      "$gen" "$n" "$grouping" "$DURATION" > "$scen" || exit 2
      if [ -n "${PRIORITY:-}" ]; then  # every robot's and every service's loop
        sed -i -E -e "s/^(  r[0-9]+:)$/\1\n    priority: $PRIORITY/" \
          -e "/^services:/,/^metrics:/ s/^(  r[0-9]+_[a-z_]+: \{.*)\}$/\1, priority: $PRIORITY}/" "$scen"
      fi
      run=$work/run
      [ -n "${KEEP:-}" ] && run=$outdir/runs-$mode-$vendor-$grouping-$n
      rm -rf "$run"
      read -r l1 l5 l15 _ < /proc/loadavg
      utc=$(date -u +%Y-%m-%dT%H:%M:%SZ)
      args=(launch "$scen" --json --quiet --dds "$vendor" --domain "$DOMAIN" --out "$run")
      [ "$mode" = realtime ] && args+=(--set clock.mode=realtime)
      [ -n "${TRANSPORT:-}" ] && args+=(--transport "$TRANSPORT")
      "$bin/plexus" "${args[@]}" > "$work/out.json" 2> "$work/err.txt"
      rc=$?
      lj=$run/launch.json
      if [ ! -s "$lj" ]; then
        echo "fleet_scale.sh: $mode $vendor $grouping N=$n: no launch.json (rc $rc): $(grep -v "gain condition" "$work/err.txt" | tail -c 400)" >&2
        echo "$mode,$vendor,$grouping,$n,,$DURATION,$rc,,,,,,,,,,,$l1,$l5,$l15,$utc" >> "$out"
        continue
      fi
      procs=$(jq '.processes | length' "$lj")
      startup=$(jq '.startup_s' "$lj")
      if [ "$mode" = lockstep ]; then
        sps=$(jq '.steps_per_s' "$lj")
        wall=$(jq -r '(.steps_per_s) as $s | if $s > 0 then ('"$DURATION"' * 100 + 1) / $s else 0 end' "$lj")
        echo "$mode,$vendor,$grouping,$n,$procs,$DURATION,$rc,$sps,$wall,$startup,,,,,,,,$l1,$l5,$l15,$utc" >> "$out"
        echo "$mode $vendor $grouping N=$n: $sps steps/s ($procs processes, rc $rc, load $l1)" >&2
      else
        # A process is named "<program> <service>,<service>...": the program and its first
        # service name it here (no comma or space in a CSV field).
        IFS=$'\t' read -r ovr stale late loops worst wover wstale < <(jq -r '.services as $s
          | [($s | [.[].overruns] | add), ($s | [.[].stale_input_reads] | add), ($s | [.[].late_input_reads] | add),
             ($s | [.[].loop_count] | add),
             ($s | to_entries | max_by(.value.overruns + .value.stale_input_reads)
                 | (.key | split(" ") | .[0] + ":" + (.[1] | split(",")[0])), .value.overruns, .value.stale_input_reads)]
          | @tsv' "$lj")
        echo "$mode,$vendor,$grouping,$n,$procs,$DURATION,$rc,,,$startup,$ovr,$stale,$late,$loops,$worst,$wover,$wstale,$l1,$l5,$l15,$utc" >> "$out"
        echo "$mode $vendor $grouping N=$n: overruns $ovr, stale reads $stale, late reads $late (worst $worst: $wover/$wstale; $procs processes, rc $rc, load $l1)" >&2
      fi
    done
  done
done
