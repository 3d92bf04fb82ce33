#!/usr/bin/env bash
# four_robots.sh PLEXUS SCENARIO OUT DOMAIN VENDOR [--short]: the main job, every service as
# its own process over DDS (plexus launch --dds VENDOR --report), checked on three counts:
#  1. the same digest as `plexus sim` of the same settings (bit-identical lockstep);
#  2. 11 processes (the arm's loop is one, arm_loop), and a report comparing all 13 metrics with the papers;
#  3. the papers' targets: exactly the known misses fail (docs/algorithms/*.md give the
#     reasons), each bounded near today's figure, and every other target is met.
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
misses=""
if [ "$short" != --short ]; then
  # Measured 2026-11-23 (seed 7, 120 s): arm RMS 1.290 / 1.141 mrad and peak torque
  # 590 / 163 N m (Table 4: 0.649 / 0.619 mrad, 46.33 / 14.39 N m; docs/algorithms/arm.md).
  # Bounds: about 10 % around these. The skid-steer robot meets the paper's 3 s with the
  # prior reset (1.0 s; 6.45 s with the paper's covariance reset).
  misses="arm_rms_e1_mrad;arm_rms_e2_mrad;arm_max_torque_1_nm;arm_max_torque_2_nm"
  checks="$checks;arm_rms_e1_mrad >= 1.16;arm_rms_e1_mrad <= 1.42;arm_rms_e2_mrad >= 1.03;arm_rms_e2_mrad <= 1.26"
  checks="$checks;arm_max_torque_1_nm >= 530;arm_max_torque_1_nm <= 650;arm_max_torque_2_nm >= 147;arm_max_torque_2_nm <= 180"
fi
launch="$plexus|launch|$scenario|--dds|$vendor|--json|--quiet|--report|--domain|$domain|--out|$out/launch"
for a in "${args[@]}"; do launch="$launch|$a"; done
cmake_args=("-DCOMMAND=$launch" "-DEXPECT_RC=$rc" "-DCHECKS=$checks")
[ -n "$misses" ] && cmake_args+=("-DMISSES=$misses")
cmake "${cmake_args[@]}" -P "$here/../scripts/json_checks.cmake" || exit 1
processes=$(grep -c '"program":' "$out/launch/launch.json")
rows=$(grep -c '^| [a-z_0-9]* | .* | \(pass\|FAIL\) |$' "$out/launch/report.md" 2>/dev/null)
echo "digest $sim_digest on both, $processes processes, $rows compared metrics"
[ "$processes" -eq 11 ] || { echo "expected 11 processes (plant_simulator, the arm's loop group arm_loop and 9 services)"; exit 1; }
[ "$rows" -eq 13 ] || { echo "report.md should compare 13 metrics with the papers"; exit 1; }
