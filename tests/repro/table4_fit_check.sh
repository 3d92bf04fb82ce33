#!/usr/bin/env bash
# table4_fit_check.sh TABLE4_FIT PLEXUS SCENARIO OUT: table4_fit (issue 29) runs the closed loop
# of the scenario runner. Its set-up of deploy/scenarios/arm_table4.yaml (arm hanging, I_O about
# the joint, q(0) = 0 moving at 1 rad/s, 5 kHz, observer started steady, CT+PD with K_v on the
# motor velocity, T = 5 s) must give the figures `plexus sim` gives for that scenario, within
# 3 % (the encoder noise is drawn from another generator; the settling time, the last crossing
# of a band, within 10 %); and a bad argument exits 2.
set -u
fit=$1 plexus=$2 scenario=$3 out=$4
rm -rf "$out"; mkdir -p "$out"
line=$("$fit" --times 5 --duration 5 --jobs 1 --top 1 | tail -1)
figs=$(echo "$line" | sed 's/.*| //')
read -r v_rms1 v_rms2 v_rms v_set1 v_set2 v_max1 v_max2 c_rms1 c_rms2 c_rms c_set1 c_set2 c_max1 c_max2 <<< "$figs"
json=$("$plexus" sim "$scenario" --json --quiet --out "$out/sim" 2>/dev/null)
get() { echo "$json" | sed -n "s/.*\"$1\":\([-0-9.e+]*\).*/\1/p"; }
fail=0
close() {  # name ours theirs [tolerance]
  local tol=${4:-0.03}
  if awk -v a="$2" -v b="$3" -v t="$tol" 'BEGIN { exit !(b != "" && a != "" && (a - b) <= t * b && (b - a) <= t * b) }'; then
    echo "$1: table4_fit $2, plexus sim $3"
  else
    echo "$1: table4_fit $2 against plexus sim $3: not within $tol"; fail=1
  fi
}
close "VDC RMS |e| (mrad)" "$v_rms" "$(get vdc_rms_norm_mrad)"
close "CT+PD RMS |e| (mrad)" "$c_rms" "$(get ctpd_rms_norm_mrad)"
close "VDC peak u1 (N m)" "$v_max1" "$(get vdc_max_torque_1_nm)"
close "CT+PD peak u1 (N m)" "$c_max1" "$(get ctpd_max_torque_1_nm)"
close "VDC settling 1 (s)" "$v_set1" "$(get vdc_settling_time_1_s)" 0.10
[ "$c_set1" = inf ] || { echo "CT+PD settling 1: $c_set1, plexus sim never settles (null)"; fail=1; }
"$fit" --gravity sideways > "$out/bad.txt" 2>&1
rc=$?
grep -q "unknown value sideways" "$out/bad.txt" && [ "$rc" -eq 2 ] || { echo "bad --gravity: exit $rc"; cat "$out/bad.txt"; fail=1; }
exit $fail
