#!/usr/bin/env bash
# prior_custom_icr.sh PLEXUS SCENARIOS OUT: the prior reset on a user's terrains (issue 16):
# the paper's three vibration signatures (so the shipped classifier still names them) with
# other ICRs; the user records their own library (icr_record_library.yaml) and the
# switching run (icr_terrain_switch_prior.yaml) with that library must re-converge within
# the paper's 3 s at each switch. The two runs use different seeds.
set -u
plexus=$1 scenarios=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
terrains="robots.r1.plant.terrains={\
concrete: {y_l: 0.35, y_r: -0.45, x_G: 0.05, floor_rms: 0.15, resonances: [[18, 0.15, 0.6], [33, 0.10, 0.4]]}, \
tile: {y_l: 0.6, y_r: -0.55, x_G: -0.15, floor_rms: 0.05, resonances: [[8, 0.05, 0.5], [24, 0.05, 0.3]]}, \
grass: {y_l: 0.45, y_r: -0.65, x_G: 0.1, floor_rms: 0.10, resonances: [[4, 0.30, 0.8], [12, 0.40, 0.3]]}}"
"$plexus" sim "$scenarios/icr_record_library.yaml" --quiet --out "$out/record" --set "$terrains" \
  --set "services.library.output=$out/library.txt" || { echo "recording the library failed"; exit 1; }
grep '^class' "$out/library.txt"
"$plexus" sim "$scenarios/icr_terrain_switch_prior.yaml" --quiet --out "$out/run" --set "$terrains" \
  --set "services.ekf.icr_library=$out/library.txt"
