#!/usr/bin/env bash
# with_peers.sh REGEX "BACKGROUND CMD" ... -- CMD ARGS...: starts the background commands,
# runs CMD, stops the background commands; passes if CMD exits 0 and its output (stdout and
# stderr) matches REGEX.
set -u
regex=$1
shift
pids=()
while [ "$#" -gt 0 ] && [ "$1" != "--" ]; do
  $1 &
  pids+=($!)
  shift
done
shift
sleep 0.5
out=$("$@" 2>&1)
rc=$?
for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
echo "$out"
[ "$rc" -eq 0 ] || { echo "exit $rc (expected 0)"; exit 1; }
echo "$out" | grep -Eq -- "$regex" || { echo "output does not match: $regex"; exit 1; }
