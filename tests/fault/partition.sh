#!/usr/bin/env bash
# partition.sh PLEXUS SCENARIO OUT DOMAIN VENDOR
# Issue 14, network faults: a 2 s partition of the veth link on VENDOR, in lockstep
# (partition_lockstep.sh: shorter than --timeout completes with the sim's digest, longer
# fails naming the missing sample and its producer) and then in realtime
# (partition_realtime.sh: both sides hold, tracking resumes). One test, one domain: the two
# runs follow each other, each in namespaces of its own.
set -u
here=$(cd "$(dirname "$0")" && pwd)
fail=0
bash "$here/partition_lockstep.sh" "$1" "$2" "$3/lockstep" "$4" "$5"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail=1
bash "$here/partition_realtime.sh" "$1" "$2" "$3/realtime" "$4" "$5" || fail=1
exit $fail
