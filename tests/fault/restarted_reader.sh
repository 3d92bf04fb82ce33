#!/bin/bash
# A reader killed with SIGKILL and started again, as `plexus launch` restarts a service, gets
# the samples of a writer that never stopped (100 Hz, the `state` profile: reliable, volatile,
# keep_last 1). Five kill/restart rounds; each new reader must take at least 100 samples in
# 4 s (it ends once it has them), so it may spend up to 3 s on discovery. On Fast DDS, a
# reader whose max_samples was its depth could refuse every sample for the rest of its life
# after such a restart (each reported lost); a restarted observer then never saw its inputs
# again.
# Usage: restarted_reader.sh BIN VENDOR DOMAIN [TRANSPORT] [TYPE]  (TRANSPORT: auto, udp or
# shm; TYPE: pose (Pose2D) or probe (LatencyProbe, a bounded sequence). Over the SHM
# transport's ports (shm on Fast DDS), Fast DDS 2.9 failed 4 of 10 rounds until
# plexus chose the restarted participant's id itself: common/runtime/src/fastdds/shm_ports.hpp,
# docs/runtime.md, Transports)
set -u
bin=$1 vendor=$2 domain=$3 transport=${4:-auto} type=${5:-pose}
peer=("$bin/topic_peer" --dds "$vendor" --domain "$domain" --topic fault/restarted --profile state --transport "$transport" --type "$type")
"${peer[@]}" pub --rate 100 --duration 60 &
writer=$!
trap 'kill $writer 2>/dev/null' EXIT
failures=0
for round in 1 2 3 4 5; do
  "${peer[@]}" sub --duration 30 &
  victim=$!
  sleep 1
  kill -9 $victim
  wait $victim 2>/dev/null
  if ! "${peer[@]}" sub --duration 4 --expect 100; then
    echo "round $round: the restarted reader got too few samples"
    failures=$((failures + 1))
  fi
done
echo "$vendor: $failures of 5 restarted readers got too few samples"
[ $failures -eq 0 ]
