#!/usr/bin/env bash
# stop_summary.sh PLANT_SIMULATOR PARAMS DOMAIN: a service running alone prints its stop
# summary (docs/services.md: "ran N ticks: ...") on SIGTERM at the default log level; it
# printed it only at --log-level info.
set -u
plant=$1 params=$2 domain=$3
err=$(timeout --preserve-status -s TERM 2 "$plant" --params "$params" --domain "$domain" 2>&1 > /dev/null)
rc=$?
echo "$err" | tail -3
[ "$rc" -eq 0 ] || { echo "exit $rc, expected 0 after SIGTERM"; exit 1; }
echo "$err" | grep -Eq '^plant_simulator( [^:]*)?: ran [0-9]+ ticks: [0-9]+ holds' || { echo "no stop summary"; exit 1; }
