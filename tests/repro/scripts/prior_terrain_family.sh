#!/usr/bin/env bash
# prior_terrain_family.sh PLEXUS SCENARIOS OUT FIRST_SEED LAST_SEED: the prior reset on a
# generated family of terrain sets unlike the paper's (issue 29, item 2;
# docs/algorithms/skid_steer.md "Prior reset on other terrain sets").
#
# Each seed draws a user's terrain set, as a user would meet it:
#   - 3-5 terrains, each with one of seven vibration signatures (the paper's three and four
#     others) and its own ICRs: y_l in [0.25, 0.25 + s], y_r in [-0.25 - s, -0.25],
#     x_G in [-s/2, s/2], with the spread s drawn from [0.3, 0.5] m;
#   - a schedule of 4-6 switches, 40 s apart, each to another terrain than the current one;
#   - GPS at 5, 10 or 20 Hz.
# The user's workflow then runs three times with plexus sim: record the classifier's
# training windows on those terrains (icr_record_training.yaml), learn the ICR library on
# them at the same GPS rate (icr_record_library.yaml), and drive the switching run with both
# (icr_terrain_switch_prior.yaml, another seed). Required: every switch re-converges within
# the paper's 3 s (0.02 m band, reconvergence_time_switchN_s), every switch detected (resets
# >= switches; a window across a switch can be named a third terrain, a false alarm that is
# counted and printed), the classifier >= 0.95. Prints one line per switch (seed, switch, from -> to, ICR jump,
# GPS rate, time) and the distribution; exit 1 if any requirement fails.
set -u
plexus=$1 scenarios=$2 out=$3 first=$4 last=$5
rm -rf "$out" && mkdir -p "$out"

signatures=(
  "floor_rms: 0.15, resonances: [[18, 0.15, 0.6], [33, 0.10, 0.4]]"
  "floor_rms: 0.05, resonances: [[8, 0.05, 0.5], [24, 0.05, 0.3]]"
  "floor_rms: 0.10, resonances: [[4, 0.30, 0.8], [12, 0.40, 0.3]]"
  "floor_rms: 0.3, resonances: [[44, 0.05, 0.8]]"
  "floor_rms: 0.02, resonances: [[14, 0.03, 0.6]]"
)

failed=0
: > "$out/switches.txt"
for seed in $(seq "$first" "$last"); do
  dir="$out/seed_$seed"
  mkdir -p "$dir"
  # The draw: awk's generator seeded with the seed (same set on every machine with one awk).
  read -r n_terrains n_switches rate spread perm <<< "$(awk -v s="$seed" 'BEGIN {
    srand(s); n = 3 + int(rand() * 3); k = 4 + int(rand() * 3); r = (rand() < 1/3) ? 5 : (rand() < 0.5 ? 10 : 20);
    sp = 0.3 + 0.2 * rand();
    for (i = 0; i < 5; ++i) p[i] = i;
    for (i = 4; i > 0; --i) { j = int(rand() * (i + 1)); t = p[i]; p[i] = p[j]; p[j] = t; }
    printf "%d %d %d %.3f %d%d%d%d%d\n", n, k, r, sp, p[0], p[1], p[2], p[3], p[4] }')"
  terrains="" names=""
  declare -A icr=()
  for i in $(seq 0 $((n_terrains - 1))); do
    read -r yl yr xg <<< "$(awk -v s="$seed" -v i="$i" -v sp="$spread" 'BEGIN {
      srand(1000 * s + i); printf "%.3f %.3f %.3f\n", 0.25 + sp * rand(), -0.25 - sp * rand(), sp * (rand() - 0.5) }')"
    sig=${signatures[${perm:$i:1}]}
    terrains+="t$i: {y_l: $yl, y_r: $yr, x_G: $xg, $sig}, "
    names+="t$i, "
    icr[$i]="$yl $yr $xg"
  done
  terrains="robots.r1.plant.terrains={${terrains%, }}"
  names="[${names%, }]"
  # The switching schedule: 40 s per segment, each to another terrain.
  schedule=$(awk -v s="$seed" -v n="$n_terrains" -v k="$n_switches" 'BEGIN {
    srand(7000 + s); cur = int(rand() * n); out = "[[0, t" cur "]"
    for (i = 1; i <= k; ++i) { nxt = int(rand() * (n - 1)); if (nxt >= cur) ++nxt; cur = nxt; out = out ", [" 40 * i ", t" cur "]" }
    print out "]" }')
  duration=$((40 * (n_switches + 1)))
  # Training: 20 s per terrain; library: 40 s per terrain at the run's GPS rate.
  training_schedule=$(awk -v n="$n_terrains" -v d=20 'BEGIN { o = "["; for (i = 0; i < n; ++i) o = o (i ? ", " : "") "[" d * i ", t" i "]"; print o "]" }')
  library_schedule=$(awk -v n="$n_terrains" -v d=40 'BEGIN { o = "["; for (i = 0; i < n; ++i) o = o (i ? ", " : "") "[" d * i ", t" i "]"; print o "]" }')
  "$plexus" sim "$scenarios/icr_record_training.yaml" --quiet --out "$dir/training_run" --set "$terrains" \
    --set "robots.r1.plant.schedule=$training_schedule" --set duration=$((20 * n_terrains)) \
    --set "services.recorder.class_names=$names" --set "services.recorder.output=$dir/training.txt" \
    --set "expectations.windows_written='== $((15 * n_terrains))'" > "$dir/training.log" 2>&1 ||
    { echo "seed $seed: recording the training windows failed ($dir/training.log)"; failed=1; continue; }
  "$plexus" sim "$scenarios/icr_record_library.yaml" --quiet --out "$dir/library_run" --set "$terrains" \
    --set "robots.r1.plant.schedule=$library_schedule" --set duration=$((40 * n_terrains)) \
    --set robots.r1.sensors.gps.rate="$rate" --set "services.classifier.training_file=$dir/training.txt" \
    --set "services.library.class_names=$names" --set "services.library.output=$dir/library.txt" \
    --set "expectations={}" > "$dir/library.log" 2>&1 ||
    { echo "seed $seed: learning the library failed ($dir/library.log)"; failed=1; continue; }
  metrics="{name: reconvergence_time_s, type: icr_reconvergence_time, estimate: r1/icr, truth: r1/truth/state, tolerance: 0.02}"
  for k in $(seq 1 "$n_switches"); do
    metrics+=", {name: switch${k}_s, type: icr_reconvergence_time, estimate: r1/icr, truth: r1/truth/state, tolerance: 0.02, switch: $k}"
  done
  metrics+=", {name: classifier_accuracy, type: classification_accuracy, classifier: r1/terrain, truth: r1/truth/state}"
  metrics+=", {name: resets, type: value_final, signal: r1/icr, field: resets}"
  "$plexus" sim "$scenarios/icr_terrain_switch_prior.yaml" --quiet --out "$dir/run" --set "$terrains" \
    --set "robots.r1.plant.schedule=$schedule" --set duration=$duration --set robots.r1.sensors.gps.rate="$rate" \
    --set "services.classifier.training_file=$dir/training.txt" --set "services.ekf.icr_library=$dir/library.txt" \
    --set "metrics=[$metrics]" \
    --set "expectations={classifier_accuracy: '>= 0.95', resets: '>= $n_switches'}" \
    > "$dir/run.log" 2>&1
  rc=$?
  # One line per switch: the terrains, the largest ICR jump and the time.
  for k in $(seq 1 "$n_switches"); do
    from=$(echo "$schedule" | sed 's/\], \[/\n/g' | sed -n "${k}p" | grep -o 't[0-9]' | tr -d t)
    to=$(echo "$schedule" | sed 's/\], \[/\n/g' | sed -n "$((k + 1))p" | grep -o 't[0-9]' | tr -d t)
    t=$(awk -v m="switch${k}_s" '$1 == m { print $2 }' "$dir/run.log")
    jump=$(awk -v a="${icr[$from]}" -v b="${icr[$to]}" 'BEGIN { split(a, x, " "); split(b, y, " "); m = 0;
      for (i = 1; i <= 3; ++i) { d = x[i] - y[i]; if (d < 0) d = -d; if (d > m) m = d } printf "%.3f", m }')
    printf 'seed %3d switch %d t%d -> t%d jump %s m gps %2d Hz: %s s\n' "$seed" "$k" "$from" "$to" "$jump" "$rate" "${t:-?}" |
      tee -a "$out/switches.txt"
    if ! awk -v t="${t:-1e9}" 'BEGIN { exit !(t <= 3) }'; then
      echo "seed $seed switch $k: re-convergence ${t:-?} s, required <= 3 s"
      failed=1
    fi
  done
  resets=$(awk '$1 == "resets" { print $2 }' "$dir/run.log")
  if [ -n "$resets" ] && [ "$resets" -gt "$n_switches" ]; then
    echo "seed $seed: $((resets - n_switches)) false alarm(s) of the classifier ($resets resets, $n_switches switches)" |
      tee -a "$out/false_alarms.txt"
  fi
  if [ $rc -ne 0 ]; then
    echo "seed $seed: FAILED (exit $rc): $(grep -h 'expectation failed\|rror' "$dir/run.log" | tr '\n' ' ')"
    failed=1
  fi
done

# The distribution of the switch times over the family.
awk '{ t = $NF == "s" ? $(NF - 1) : $NF; print t }' "$out/switches.txt" | sort -g | awk '
  { v[NR] = $1 } END { if (NR == 0) exit;
    printf "switches %d: min %.2f s, median %.2f s, p90 %.2f s, max %.2f s\n", NR, v[1], v[int((NR + 1) / 2)],
      v[int(0.9 * NR + 0.999)], v[NR] }'
exit $failed
