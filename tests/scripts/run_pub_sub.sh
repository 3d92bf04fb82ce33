#!/usr/bin/env bash
# run_pub_sub.sh "SUB COMMAND" "PUB COMMAND": starts the subscriber, then the publisher,
# each in its own process; passes if both exit 0 (the subscriber checks every sample).
set -u
bash -c "$1" &
sub_pid=$!
bash -c "$2"
pub_rc=$?
wait $sub_pid
sub_rc=$?
echo "publisher rc=$pub_rc subscriber rc=$sub_rc"
[ $pub_rc -eq 0 ] && [ $sub_rc -eq 0 ]
