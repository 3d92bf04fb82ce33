#!/usr/bin/env bash
# The SDK as a user meets it (docs/sdk.md, followed step by step): plexus installed into a
# prefix with `cmake --install`, the example project (examples/tilt_filter: its own message, one
# estimator) copied out of the tree and built against that prefix alone, then
#   1. `plexus sim` loads the user's components from the scenario's plugins;
#   2. `plexus launch` runs the user's executable beside the built-in services, in lockstep, on
#      Fast DDS and on Cyclone DDS, each with the same digest and metrics as plexus sim;
#   3. `plexus topic echo` reads the user's own message type from a realtime launch;
#   4. the user's service runs on its own, stops on SIGTERM with exit 0, and refuses a bad
#      parameter with one line and exit 2.
# Every plexus program used is the installed one.
# Usage: example_project.sh BUILD_DIR SOURCE_DIR OUT_DIR DOMAIN
set -euo pipefail
build=$(realpath "$1") src=$(realpath "$2") out=$3 domain=$4
rm -rf "$out" && mkdir -p "$out" && out=$(realpath "$out")
step() { echo "== $*"; }

step "cmake --install into $out/prefix"
cmake --install "$build" --prefix "$out/prefix" > "$out/install.log"
plexus=$out/prefix/bin/plexus
test -x "$plexus"

step "the example, built against the prefix only"
cp -r "$src/examples/tilt_filter" "$out/tilt_filter"
cd "$out/tilt_filter"
cmake -S . -B build -DCMAKE_PREFIX_PATH="$out/prefix" > "$out/configure.log"
cmake --build build -j2 > "$out/build.log"
# The project must not have reached into plexus's source or build tree.
# (The output folder itself may lie in the build tree: its own paths are left out.)
if grep -rh -e "$build" -e "$src/common" build/CMakeCache.txt build/CMakeFiles/*.dir/flags.make 2>/dev/null |
   sed "s|$out||g" | grep -q -e "$build" -e "$src/common"; then
  echo "FAIL: the example's build refers to plexus's build or source tree" >&2; exit 1
fi
test -x build/tilt_filter

step "plexus sim, plexus launch (lockstep) on both vendors: same digest"
for vendor in fast cyclone; do
  cmake -DPLEXUS="$plexus" -DSCENARIO=tilt_beside_ukf.yaml -DOUT="$out/run_$vendor" -DDOMAIN="$domain" \
        "-DLAUNCH_ARGS=--dds|$vendor" -DPROCESS=tilt=tilt_filter -P "$src/tests/lockstep/digest_equal.cmake"
done

step "plexus topic echo of mylab::msg::TiltEstimate from a realtime launch"
"$plexus" launch tilt_beside_ukf.yaml --quiet --domain "$domain" --out "$out/realtime" \
  --set clock.mode=realtime --set duration=6 > "$out/realtime.log" 2>&1 &
launch=$!
echo_out=$("$plexus" topic echo r1/tilt --domain "$domain" --count 3 --json --wait 10 \
           --plugin build/libmylab_msgs.so 2> "$out/echo.err") || { cat "$out/echo.err" >&2; kill $launch; exit 1; }
wait $launch || { echo "FAIL: the realtime launch failed" >&2; cat "$out/realtime.log" >&2; exit 1; }
echo "$echo_out" | head -3
[ "$(echo "$echo_out" | grep -c '"tilt"')" -eq 3 ] || { echo "FAIL: 3 TiltEstimate samples expected" >&2; exit 1; }
echo "$echo_out" | jq -e 'select(.tau != 0.5) | halt_error(1)' > /dev/null 2>&1 && { echo "FAIL: tau is not 0.5" >&2; exit 1; }

step "the user's type through topic hz and info, record, echo from the recording and replay"
plug=(--plugin build/libmylab_msgs.so)
"$plexus" launch tilt_beside_ukf.yaml --quiet --domain "$domain" --out "$out/realtime2" \
  --set clock.mode=realtime --set duration=8 > "$out/realtime2.log" 2>&1 &
launch=$!
"$plexus" record "${plug[@]}" -o "$out/tilt.mcap" --topics r1/tilt --duration 4 --wait 10 --domain "$domain" \
  > "$out/record.log" 2>&1 &
record=$!
"$plexus" topic hz r1/tilt "${plug[@]}" --domain "$domain" --duration 3 --wait 10 --json > "$out/hz.json" 2> "$out/hz.err" ||
  { cat "$out/hz.err" >&2; kill $launch $record; exit 1; }
"$plexus" topic info r1/tilt "${plug[@]}" --domain "$domain" --json > "$out/info.json" 2> "$out/info.err" ||
  { cat "$out/info.err" >&2; kill $launch $record; exit 1; }
wait $record || { echo "FAIL: plexus record failed" >&2; cat "$out/record.log" >&2; kill $launch; exit 1; }
wait $launch || { echo "FAIL: the second realtime launch failed" >&2; cat "$out/realtime2.log" >&2; exit 1; }
jq -e '.type == "mylab::msg::TiltEstimate" and .rate_hz > 50' "$out/hz.json" > /dev/null || { echo "FAIL: topic hz: $(cat "$out/hz.json")" >&2; exit 1; }
grep -q "mylab::msg::TiltEstimate" "$out/info.json" || { echo "FAIL: topic info does not name the type" >&2; cat "$out/info.json" >&2; exit 1; }
rec=$("$plexus" topic echo r1/tilt --recording "$out/tilt.mcap" "${plug[@]}" --json --count 3 2> "$out/echo_rec.err") ||
  { cat "$out/echo_rec.err" >&2; exit 1; }
[ "$(echo "$rec" | grep -c '"tilt"')" -eq 3 ] || { echo "FAIL: 3 recorded TiltEstimate samples expected: $rec" >&2; exit 1; }
replay_domain=187  # the replay on a domain of its own (tests/CMakeLists.txt)
"$plexus" replay "$out/tilt.mcap" "${plug[@]}" --domain "$replay_domain" --rate 50 > "$out/replay.log" 2>&1 &
replay=$!
replayed=$("$plexus" topic echo r1/tilt "${plug[@]}" --domain "$replay_domain" --count 3 --json --wait 10 2> "$out/echo_replay.err")
kill $replay 2> /dev/null; wait $replay 2> /dev/null
[ "$(echo "$replayed" | grep -c '"tilt"')" -eq 3 ] || { echo "FAIL: 3 replayed TiltEstimate samples expected" >&2; cat "$out/echo_replay.err" "$out/replay.log" >&2; exit 1; }

step "the user's service alone: SIGTERM -> exit 0; a bad parameter -> one line, exit 2"
build/tilt_filter --robot r1 --domain "$domain" --set tau=0.2 > "$out/alone.log" 2>&1 &
alone=$!
sleep 2
kill -TERM $alone
rc=0; wait $alone || rc=$?
[ "$rc" -eq 0 ] || { echo "FAIL: tilt_filter exited $rc on SIGTERM" >&2; cat "$out/alone.log" >&2; exit 1; }
rc=0; err=$(build/tilt_filter --robot r1 --domain "$domain" --set tau=-1 2>&1 >/dev/null) || rc=$?
[ "$rc" -eq 2 ] || { echo "FAIL: a bad tau gave exit $rc" >&2; exit 1; }
[ "$(echo "$err" | wc -l)" -eq 1 ] && echo "$err" | grep -q "tau: must be a time constant > 0 s" ||
  { echo "FAIL: expected one line naming tau, got: $err" >&2; exit 1; }
echo "PASS"
