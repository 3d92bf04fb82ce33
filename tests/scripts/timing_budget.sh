#!/usr/bin/env bash
# timing_budget.sh PLEXUS SCENARIO OUT DOMAIN VENDOR: the timing budget of a loop (issue 35;
# docs/distributed.md, "Loops"), on paper 004's arm at 1 kHz in realtime for 3 s.
#  1. the loop split over three processes (plant_simulator, the EKF's, the VDC's) with a
#     deadline no DDS hop can meet (20 us: a hop between two processes on loopback takes
#     tens of us at best), so the verdict does not depend on the machine's load: a warning
#     naming the loop and its hops, and launch.json's verdict fits=false with the measured hops;
#  2. the same with --strict: exit 2 and one line naming the loop;
#  3. the loop as a loop group (`process:`), the default deadline: no hop between processes,
#     fits=true, and no warning.
set -u
plexus=$1 scenario=$2 out=$3 domain=$4 vendor=$5
rm -rf "$out" && mkdir -p "$out"
run=(launch --set clock.mode=realtime --set step=0.001 --set duration=3 --dds "$vendor" --quiet --domain "$domain")
fail=0
cp "$scenario" "$out/split.yaml"
cat >> "$out/split.yaml" <<'YAML'
loops:
  arm:
    members: [arm, observer, controller]
    deadline: 0.00002
YAML
"$plexus" "${run[@]}" "$out/split.yaml" --out "$out/split" > /dev/null 2> "$out/split.err"
rc=$?
grep -h "timing budget" "$out/split.err" | cut -c1-400
{ [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ]; } || { echo "FAIL: the split run exited $rc"; tail -5 "$out/split.err"; fail=1; }
grep -q "timing budget: loop 'arm' does not fit its budget under this placement" "$out/split.err" ||
  { echo "FAIL: no warning naming loop 'arm'"; fail=1; }
grep -q "arm/cmd controller -> plant_simulator" "$out/split.err" || { echo "FAIL: the warning does not name the hop arm/cmd"; fail=1; }
jq -e '.loops.arm.fits == false and (.loops.arm.hops | length) >= 3 and all(.loops.arm.hops[]; .samples > 100)' \
  "$out/split/launch.json" > /dev/null || { echo "FAIL: launch.json lacks the verdict and measured hops"; fail=1; }

"$plexus" "${run[@]}" "$out/split.yaml" --strict --out "$out/strict" > /dev/null 2> "$out/strict.err"
rc=$?
line=$(grep "^plexus launch: --strict: loop 'arm' does not fit" "$out/strict.err")
[ "$rc" -eq 2 ] || { echo "FAIL: --strict exited $rc, expected 2"; fail=1; }
[ -n "$line" ] || { echo "FAIL: --strict did not say which loop"; tail -5 "$out/strict.err"; fail=1; }

cp "$scenario" "$out/group.yaml"
cat >> "$out/group.yaml" <<'YAML'
loops:
  arm:
    members: [arm, reference, observer, controller]
    process: arm_loop
YAML
"$plexus" "${run[@]}" "$out/group.yaml" --strict --out "$out/group" > /dev/null 2> "$out/group.err"
rc=$?
{ [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ]; } || { echo "FAIL: the loop group's run exited $rc"; tail -5 "$out/group.err"; fail=1; }
jq -e '.loops.arm.fits == true and (.loops.arm.hops | length) == 0 and .processes.arm_loop.program == "component_host"' \
  "$out/group/launch.json" > /dev/null || { echo "FAIL: the loop group is not one process that fits"; fail=1; }
if grep -q "timing budget" "$out/group.err"; then echo "FAIL: a warning for the loop group"; fail=1; fi
[ "$fail" -eq 0 ] && echo PASS
exit $fail
