#!/usr/bin/env bash
# run_pair.sh BIN_DIR PUB_VENDOR SUB_VENDOR DOMAIN [TYPES] [TRANSPORT]
# A plexus_test_peer publisher and subscriber in two processes; passes if the subscriber
# received every sample of every type intact. TRANSPORT: auto (default), udp or shm.
set -u
bin=$1 pub=$2 sub=$3 domain=$4 types=${5:-all} transport=${6:-auto}
"$bin/plexus_test_peer" sub --dds "$sub" --domain "$domain" --types "$types" --count 5 --timeout 40 --transport "$transport" &
sub_pid=$!
"$bin/plexus_test_peer" pub --dds "$pub" --domain "$domain" --types "$types" --count 5 --timeout 40 --transport "$transport"
pub_rc=$?
wait $sub_pid
sub_rc=$?
echo "pub($pub) rc=$pub_rc sub($sub) rc=$sub_rc"
[ $pub_rc -eq 0 ] && [ $sub_rc -eq 0 ]
