#!/usr/bin/env bash
# four_robots.sh PLEXUS SCENARIO OUT DOMAIN VENDOR [--short]: the main job, every service as
# its own process over DDS (plexus launch --dds VENDOR --report), checked on three counts:
#  1. the same digest as `plexus sim` of the same settings (bit-identical lockstep);
#  2. 11 processes (the arm's loop is one, arm_loop), and a report comparing all 13 metrics with the papers;
#  3. the papers' targets: every target is met (the arm's settling times, which Table 4 itself
#     cannot produce with its other figures, are marked inconsistent in the paper and met
#     anyway: docs/algorithms/arm.md "Table 4: the set-up"); the arm's figures are bounded near
#     today's, and the run exits 0.
# --short runs 6 s of simulated time (1 and 2, and the same exit code as sim: the paper
# targets need the full run).
set -u
plexus=$1 scenario=$2 out=$3 domain=$4 vendor=$5 short=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
args=()
if [ "$short" = --short ]; then
  args=(--set duration=6 --set metrics.0.from=5 --set metrics.1.from=5)
fi
sim=$("$plexus" sim "$scenario" "${args[@]}" --json --quiet --out "$out/sim" 2>/dev/null)
rc=$?
sim_digest=$(echo "$sim" | sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p')
[ -n "$sim_digest" ] || { echo "plexus sim gave no digest"; exit 1; }
checks="digest == $sim_digest"
misses="" inconsistent=""
if [ "$short" != --short ]; then
  # Measured 2026-11-29 (seed 7, 120 s, the set-up fitted to Table 4, issue 29): arm RMS
  # 0.634 / 0.619 mrad over 3.5 s, peak torque 46.75 / 14.58 N m (Table 4: 0.649 / 0.619,
  # 46.33 / 14.39), settling 0.095 / 0.093 s (0.36 / 0.37, inconsistent in the paper).
  # Bounds: about 5 % around these. The skid-steer robot meets the paper's 3 s with the
  # prior reset (1.0 s; 6.45 s with the paper's covariance reset).
  misses=none
  inconsistent=none
  checks="$checks;arm_rms_e1_mrad >= 0.60;arm_rms_e1_mrad <= 0.67;arm_rms_e2_mrad >= 0.59;arm_rms_e2_mrad <= 0.65"
  checks="$checks;arm_max_torque_1_nm >= 44.4;arm_max_torque_1_nm <= 49.1;arm_max_torque_2_nm >= 13.9;arm_max_torque_2_nm <= 15.3"
fi
launch="$plexus|launch|$scenario|--dds|$vendor|--json|--quiet|--report|--domain|$domain|--out|$out/launch"
for a in "${args[@]}"; do launch="$launch|$a"; done
cmake_args=("-DCOMMAND=$launch" "-DEXPECT_RC=$rc" "-DCHECKS=$checks")
[ -n "$misses" ] && cmake_args+=("-DMISSES=$misses")
[ -n "$inconsistent" ] && cmake_args+=("-DINCONSISTENT=$inconsistent")
cmake "${cmake_args[@]}" -P "$here/../scripts/json_checks.cmake" || exit 1
processes=$(grep -c '"program":' "$out/launch/launch.json")
rows=$(grep -c '^| [a-z_0-9]* | .* | \(pass\|FAIL\|inconsistent in the paper (.*)\) |$' "$out/launch/report.md" 2>/dev/null)
echo "digest $sim_digest on both, $processes processes, $rows compared metrics"
[ "$processes" -eq 11 ] || { echo "expected 11 processes (plant_simulator, the arm's loop group arm_loop and 9 services)"; exit 1; }
[ "$rows" -eq 13 ] || { echo "report.md should compare 13 metrics with the papers"; exit 1; }
