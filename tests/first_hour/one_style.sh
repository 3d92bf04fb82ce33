#!/usr/bin/env bash
# one_style.sh BIN_DIR: one CLI style across plexus and the services (issue 19).
#  1. one flag name per meaning: the QoS profile is --profile, the output -o/--out, in every
#     subcommand's help (--qos and --output are gone);
#  2. every service's --help says what it hosts and its topics, and points at no source file;
#  3. one log line format (ISO time, level, [source]) on stderr, the short warning once;
#  4. --json output is JSON alone on stdout, a warning on stderr, with advice that fits.
set -u
bin=$1
scenarios=$(cd "$(dirname "$0")/../../deploy/scenarios" && pwd)
fail() { echo "FAIL: $*"; exit 1; }

helps=("" "demo" "qos" "launch" "sim" "report" "topic list" "topic echo" "topic hz" "topic info" "record" "replay"
       "latency pingpong" "latency loop" "latency pipeline")
for h in "${helps[@]}"; do
  # shellcheck disable=SC2086
  text=$("$bin/plexus" $h --help 2>&1) || fail "plexus $h --help exited $?"
  if echo "$text" | grep -Eq -- '--qos([^-]|$)|--output'; then fail "plexus $h --help still has --qos or --output"; fi
  if echo "$text" | grep -Eq -- '--out([^p]|$)' && ! echo "$text" | grep -q -- '-o,--out'; then
    fail "plexus $h: --out without -o"
  fi
done
"$bin/plexus" record --help | grep -q -- '-o,--out' || fail "record has no -o,--out"
for h in record replay "topic echo"; do
  # shellcheck disable=SC2086
  "$bin/plexus" $h --help | grep -q -- '--profile' || fail "plexus $h has no --profile"
done
echo "flags: one name per meaning in ${#helps[@]} help texts"

for s in plant_simulator localisation_observer motion_controller terrain_classifier icr_estimator attitude_filter \
         joint_controller component_host; do
  text=$("$bin/$s" --help) || fail "$s --help exited $?"
  echo "$text" | grep -q 'Topics are <robot>/<port>' || fail "$s --help does not say what its topics are"
  if echo "$text" | grep -Eq '\.(hpp|cpp|h)\b'; then fail "$s --help points at a source file"; fi
  [ "$s" = component_host ] && continue
  echo "$text" | grep -Eq '^      out  r1/[a-z_/]+  [A-Z][A-Za-z0-9]+$' || fail "$s --help lists no typed output topic"
done
"$bin/localisation_observer" --help | grep -Eq '^      out  r1/heading  HeadingEstimate$' || fail "observer topic"
echo "services: every --help lists what it hosts and its typed topics"

err=$("$bin/plexus" sim "$scenarios/wmr_output_feedback_rfid.yaml" --quiet --set duration=101 --out "$(mktemp -d)/run" 2>&1 >/dev/null)
echo "$err" | grep -q 'gain condition' || fail "no gain-condition warning from sim"
if echo "$err" | grep -Eq '^\[[0-9]{4}-'; then fail "a log line in spdlog's default format: $(echo "$err" | grep -E '^\[[0-9]{4}-' | head -1)"; fi
line=$(echo "$err" | grep 'gain condition')
[ "$(echo "$line" | wc -l)" -eq 1 ] || fail "the gain-condition warning appears $(echo "$line" | wc -l) times"
echo "$line" | grep -Eq '^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:.]+ warning \[scenario\] ' || fail "warning format: $line"
[ "${#line}" -le 200 ] || fail "the warning is ${#line} characters long (short form wanted): $line"
echo "log format: $line"

out=$(setpriv --bounding-set -sys_nice --inh-caps -sys_nice "$bin/plexus" latency loop --json --no-cyclictest \
      --duration 0.3 --rate 100 --priority 10 2>/tmp/one_style_loop.$$) || fail "latency loop exited $?"
err=$(cat /tmp/one_style_loop.$$); rm -f /tmp/one_style_loop.$$
[ "$(echo "$out" | wc -l)" -eq 1 ] && echo "$out" | grep -Eq '^\{.*\}$' || fail "stdout is not one JSON object: $out"
echo "$err" | grep -q 'SCHED_FIFO priority 10 refused (Operation not permitted)' || fail "no refusal warning on stderr: $err"
echo "$err" | grep -q 'CAP_SYS_NICE' || fail "the advice does not name CAP_SYS_NICE"
err=$("$bin/plexus" latency loop --cpu 4096 --duration 0.3 --no-cyclictest 2>&1 >/dev/null); rc=$?
[ $rc -eq 2 ] || fail "--cpu 4096: exit $rc, expected 2"
echo "$err" | grep -q 'no such CPU' || fail "--cpu 4096: $err"
if echo "$err" | grep -q CAP_SYS_NICE; then fail "--cpu 4096 advises capabilities: $err"; fi
echo "json: stdout is JSON alone; a CPU that does not exist is bad input: $err"
echo "one style: all checks passed"
