#!/usr/bin/env bash
# expect_exit.sh CODE REGEX CMD ARGS...: passes if CMD exits with CODE and its stderr,
# a single line, matches REGEX.
set -u
want=$1 regex=$2
shift 2
err=$("$@" 2>&1 >/dev/null)
rc=$?
echo "exit $rc: $err"
[ "$rc" -eq "$want" ] || { echo "expected exit $want"; exit 1; }
echo "$err" | grep -Eq -- "$regex" || { echo "stderr does not match: $regex"; exit 1; }
[ "$(printf '%s\n' "$err" | grep -c .)" -eq 1 ] || { echo "expected a one-line error"; exit 1; }
