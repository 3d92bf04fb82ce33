#!/usr/bin/env bash
# emulator_smoke.sh EMULATOR PARAMS OUTDIR
#
# Smoke test of tools/device_emulator, with no bridge and no DDS. PARAMS is the unicycle's
# robot section (deploy/params/unicycle_robot.yaml) or the folder that holds it.
#
# Run 1: the unicycle (truth/state 0x11 and position 0x10, both at 100 Hz with --step 0.01)
# on a pty in OUTDIR; the link is read for 2 s, then the emulator gets SIGTERM. Checks:
# exit 0 and one JSON line; frames_sent = 2 per step (every frame went out, nothing dropped)
# and >= 300; the bytes read are frames: every 0x00-delimited block is 31 or 39 bytes (the
# COBS encodings of the two frames' 30 and 38 raw bytes); no command was ever sent, so the
# watchdog (armed at start) tripped exactly once, 100 ms in, and the robot did not move
# (state y = y0 = -6); the symlink is gone after exit.
# Run 2: --fault garbage@0.5:bytes=100 --fault unplug@1:for=0.3 --duration 2: both faults
# reported applied, one reopen, the link back (a symlink to a pty) after the unplug, and
# about 0.3 s of frames (2 x 30) discarded while unplugged.
# Run 3: a bad option exits 2 with one line `device_emulator: error: ...`.
set -u
emu=$1 params=$2 out=$3
[ -d "$params" ] && params="$params/unicycle_robot.yaml"
rm -rf "$out" && mkdir -p "$out"
link="$out/tty"
pid=""
trap '[ -n "$pid" ] && kill -TERM $pid 2>/dev/null' EXIT

fail() { echo "FAIL: $*"; exit 1; }
field() { grep -o "\"$1\":[-0-9.e]*" "$2" | head -1 | cut -d: -f2; }
wait_link() { for _ in $(seq 1 100); do [ -L "$link" ] && [ -e "$link" ] && return 0; sleep 0.05; done; return 1; }

# --- run 1: frames on the pty, SIGTERM
"$emu" --params "$params" --step 0.01 --pty "$link" > "$out/run1.json" 2> "$out/run1.err" &
pid=$!
wait_link || { cat "$out/run1.err"; fail "the emulator created no pty link at $link"; }
stty -F "$link" raw -echo 2>/dev/null || true  # the emulator sets raw mode already; harmless
timeout 2 cat "$link" > "$out/bytes.bin"
kill -TERM $pid
wait $pid
rc=$?
pid=""
echo "run 1: exit $rc: $(cat "$out/run1.json")"
[ "$rc" -eq 0 ] || { tail -3 "$out/run1.err"; fail "the emulator exited $rc after SIGTERM (expected 0)"; }
[ "$(grep -c '^{.*}$' "$out/run1.json")" -eq 1 ] || fail "expected one JSON line on stdout"
sent=$(field frames_sent "$out/run1.json")
steps=$(field steps "$out/run1.json")
trips=$(field watchdog_trips "$out/run1.json")
dropped=$(field frames_dropped_tx "$out/run1.json")
[ -n "$sent" ] && [ -n "$steps" ] && [ -n "$trips" ] || fail "frames_sent, steps or watchdog_trips missing"
[ "$sent" -ge 300 ] || fail "frames_sent $sent < 300 (two signals at 100 Hz for over 2 s)"
[ "$sent" -le $((2 * steps)) ] && [ "$sent" -ge $((2 * steps - 4)) ] ||
  fail "frames_sent $sent for $steps steps (expected 2 per step)"
[ "$dropped" = 0 ] || fail "frames_dropped_tx $dropped (the line has room for 7.2 kB/s)"
[ "$trips" -eq 1 ] || fail "watchdog_trips $trips (expected 1: armed at start, no command ever)"
[ "$(field commands "$out/run1.json")" = 0 ] || fail "commands counted with no command sent"
grep -q '"state":{"x":0.0,"y":-6.0,"theta":0.0}' "$out/run1.json" || fail "the robot moved with no command"
[ -e "$link" ] || [ -L "$link" ] && fail "the pty link is still there after exit"
size=$(stat -c %s "$out/bytes.bin")
[ "$size" -gt 0 ] || fail "nothing read from the pty"
# Lengths of the 0x00-delimited blocks: all frames, so 31 or 39 bytes each.
read -r blocks good < <(od -An -v -tu1 "$out/bytes.bin" |
  awk '{ for (i = 1; i <= NF; ++i) if ($i == 0) { ++n; if (len == 31 || len == 39) ++g; len = 0 } else ++len }
       END { print n + 0, g + 0 }')
echo "run 1: read $size bytes, $blocks frames, $good of the expected lengths"
[ "$blocks" -ge 200 ] || fail "only $blocks 0x00 delimiters in 2 s (expected about 400)"
[ "$good" -eq "$blocks" ] || fail "$((blocks - good)) of $blocks blocks are not 31 or 39 bytes long"

# --- run 2: faults
"$emu" --params "$params" --step 0.01 --pty "$link" --duration 2 \
  --fault garbage@0.5:bytes=100 --fault unplug@1:for=0.3 > "$out/run2.json" 2> "$out/run2.err" &
pid=$!
wait_link || { cat "$out/run2.err"; fail "run 2: no pty link"; }
sleep 1.6
relinked=$(readlink "$link" 2>/dev/null)
wait $pid
rc=$?
pid=""
echo "run 2: exit $rc: $(cat "$out/run2.json")"
[ "$rc" -eq 0 ] || { tail -3 "$out/run2.err"; fail "run 2 exited $rc (expected 0 after --duration)"; }
grep -q '"kind":"garbage","at":0.5,"applied":true' "$out/run2.json" || fail "garbage@0.5 not reported applied"
grep -q '"kind":"unplug","at":1.0,"applied":true' "$out/run2.json" || fail "unplug@1 not reported applied"
[ "$(field reopens "$out/run2.json")" = 1 ] || fail "expected one reopen after the unplug"
case "$relinked" in /dev/pts/*) ;; *) fail "after the unplug $link points to '$relinked', not a pty" ;; esac
discarded=$(field frames_discarded "$out/run2.json")
[ "$discarded" -ge 40 ] && [ "$discarded" -le 80 ] || fail "frames_discarded $discarded while unplugged 0.3 s (expected ~60)"
steps=$(field steps "$out/run2.json")
[ "$steps" -ge 190 ] && [ "$steps" -le 200 ] || fail "run 2 ran $steps steps in --duration 2 at 100 Hz (expected 200)"

# --- run 3: a bad option
"$emu" --params "$params" --pty "$link" --fault bogus@1 > /dev/null 2> "$out/run3.err"
rc=$?
[ "$rc" -eq 2 ] || fail "a bad --fault exited $rc (expected 2)"
[ "$(wc -l < "$out/run3.err")" -eq 1 ] && grep -q '^device_emulator: error: --fault bogus@1' "$out/run3.err" ||
  fail "a bad --fault did not give one line naming it: $(cat "$out/run3.err")"

echo "PASS"
