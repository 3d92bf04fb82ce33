#!/usr/bin/env bash
# deploy_units.sh PLEXUS OUT DOMAIN: `plexus deploy units` for host h2 of the closed loop
# (observer and controller there, with a restart policy, realtime priority and a CPU), then
#   - `systemd-analyze verify` accepts every unit and the target (ExecStart points at the
#     built executables);
#   - the units carry the scenario's restart policy, priority, affinity and the process's part;
#   - the target wants every service;
#   - a service started exactly as its unit's ExecStart line says runs from its part (for a
#     deployment without hosts, on loopback) until SIGTERM, and exits 0.
set -u
plexus=$(readlink -f "$1") out=$2 domain=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=$(dirname "$plexus")
fail() { echo "FAIL: $*"; exit 1; }
command -v systemd-analyze > /dev/null || { echo "needs systemd-analyze (package systemd)"; exit 77; }
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
scenario=$root/deploy/scenarios/path_following_circle.yaml
place=(--set hosts.h1.address=10.117.0.1 --set hosts.h2.address=10.117.0.2 --set robots.r1.host=h1
       --set services.path.host=h1 --set services.observer.host=h2 --set services.controller.host=h2
       --set services.controller.restart=always --set services.controller.restart_delay=0.5
       --set services.controller.priority=20 --set services.controller.cpu=1 --set services.observer.restart=never)
"$plexus" deploy units "$scenario" --host h2 --out "$out/h2" --bin "$bin" --config-dir "$out/h2/config" \
  --domain "$domain" "${place[@]}" || fail "deploy units exited $?"
ls "$out/h2"
units=("$out"/h2/*.service "$out"/h2/*.target)
[ ${#units[@]} -eq 3 ] || fail "expected 2 services and a target, got ${#units[@]} files"
# systemd-analyze verify: on the unit files as written (it resolves each ExecStart binary).
SYSTEMD_LOG_LEVEL=notice systemd-analyze verify "${units[@]}" > "$out/verify.txt" 2>&1
rc=$?
cat "$out/verify.txt"
[ $rc -eq 0 ] || fail "systemd-analyze verify exited $rc"
grep -v -e "^$" "$out/verify.txt" | grep -q . && fail "systemd-analyze verify printed warnings"

ctl=$out/h2/plexus-path_following_circle-h2-controller.service
obs=$out/h2/plexus-path_following_circle-h2-observer.service
tgt=$out/h2/plexus-path_following_circle-h2.target
for f in "$ctl" "$obs" "$tgt"; do [ -f "$f" ] || fail "missing $f"; done
grep -qx "Restart=always" "$ctl" || fail "controller: Restart=always expected"
grep -qx "RestartSec=0.5s" "$ctl" || fail "controller: RestartSec=0.5s expected"
grep -qx "LimitRTPRIO=20" "$ctl" || fail "controller: LimitRTPRIO=20 expected"
grep -qx "CPUAffinity=1" "$ctl" || fail "controller: CPUAffinity=1 expected"
grep -q "^ExecStart=$bin/motion_controller --part $out/h2/config/controller.yaml --service \"motion_controller controller\" --mode realtime --priority 20 --cpu 1 --dds fast --domain $domain --qos-file $out/h2/config/qos.yaml --interface 10.117.0.2 --peers 10.117.0.1,10.117.0.2$" "$ctl" \
  || fail "controller: ExecStart is not the expected command line: $(grep ExecStart "$ctl")"
grep -qx "Restart=no" "$obs" || fail "observer: Restart=no expected (restart: never)"
grep -q "LimitRTPRIO" "$obs" && fail "observer: no priority was given"
grep -qx "Wants=$(basename "$ctl") $(basename "$obs")" "$tgt" || grep -qx "Wants=$(basename "$obs") $(basename "$ctl")" "$tgt" \
  || fail "the target does not want both services: $(grep Wants= "$tgt")"
grep -qx "WantedBy=$(basename "$tgt")" "$ctl" || fail "controller: not wanted by the target"
grep -q "^duration:" "$out/h2/config/controller.yaml" && fail "the part keeps a duration (a unit runs until stopped)"
cmp -s "$out/h2/config/qos.yaml" "$root/deploy/qos.yaml" || fail "config/qos.yaml is not the QoS file in use"

# Run one unit's ExecStart (a deployment without hosts: loopback) for 3 s: it must start from
# its part and keep running until SIGTERM (timeout's 124), not stop on bad configuration (2).
"$plexus" deploy units "$scenario" --out "$out/local" --bin "$bin" --config-dir "$out/local/config" --domain "$domain" \
  > /dev/null || fail "deploy units without hosts exited $?"
exec_line=$(sed -n 's/^ExecStart=//p' "$out/local/plexus-path_following_circle-observer.service")
eval "set -- $exec_line"
timeout -s TERM 3 "$@" > "$out/observer.log" 2>&1
rc=$?
[ $rc -eq 124 ] || { cat "$out/observer.log"; fail "the observer started from its unit's command line exited $rc before SIGTERM"; }
echo "PASS: 3 units verified; the observer ran from its unit's command line until stopped"
