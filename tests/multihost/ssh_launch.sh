#!/usr/bin/env bash
# ssh_launch.sh PLEXUS OUT DOMAIN CASE: `plexus launch SCENARIO` in the first of N network
# namespaces starts the other hosts' shares over ssh (tests/multihost/ssh_hosts.sh: an sshd
# per namespace, keys and known_hosts in OUT/ssh, ssh -F). Cases:
#   lockstep2, lockstep3   closed loop over 2 / 3 hosts: the digest of `plexus sim`, remote
#                          log lines relayed into the run folder, nothing left in any namespace;
#                          lockstep3's h3 runs an installed plexus (`plexus:` an install prefix)
#   realtime_rfid          paper 000's RFID case in realtime over 3 hosts: its steady bounds
#   teardown               Ctrl-C mid-run (realtime, 3 hosts): everything stops, nothing left
#   session_dies           the ssh session of h2 killed mid-run: h2's share stops, the run
#                          ends with an error naming h2, nothing left anywhere
#   launcher_killed        the launcher SIGKILLed mid-run: every host's share stops
#   host_killed            every process of h3 (its sshd too) killed mid-run: the run ends
#                          with an error naming h3, h1 and h2 stop, nothing left
#   preflight              unreachable host, scenario mismatch, another plexus version, an
#                          address on no interface: exit 2, one line naming the host, nothing started
#   clock_offset           an injected +50 ms offset on h2: realtime refused (exit 2) unless
#                          --allow-clock-offset, then latencies corrected by it; lockstep runs
# Needs root (network namespaces); exit 77 to skip without it or without sshd.
set -u
plexus=$(readlink -f "$1") out=$2 domain=$3 case=$4
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
if [ "$(id -u)" -ne 0 ]; then echo "needs root for network namespaces"; exit 77; fi
if [ ! -x /usr/sbin/sshd ] || ! command -v ssh >/dev/null; then echo "needs openssh-server and openssh-client"; exit 77; fi
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
. "$here/ssh_hosts.sh"
trap plexus_hosts_cleanup EXIT
fail() { echo "FAIL ($case): $*"; exit 1; }

n=3
case $case in lockstep2|session_dies|clock_offset) n=2 ;; esac
[ "$case" = preflight ] && NO_SSHD[3]=1  # h3: a namespace with no sshd (connection refused)
plexus_hosts_up "$out" "$n" || fail "could not set up the hosts"

# The scenario's hosts, through --set: h1 runs the command; the others by ssh, each in its own workdir.
HOSTSET=(--set "hosts.h1.address=${ADDR[1]}")
for i in $(seq 2 "$n"); do
  mkdir -p "$out/work_h$i"
  HOSTSET+=(--set "hosts.h$i.address=${ADDR[$i]}" --set "hosts.h$i.ssh=root@${ADDR[$i]}" --set "hosts.h$i.workdir=$out/work_h$i")
done
path=$root/deploy/scenarios/path_following_circle.yaml
rfid=$root/deploy/scenarios/wmr_output_feedback_rfid.yaml

launch() {  # launch SCENARIO ARGS...: in namespace 1, stdout -> $out/launch.out, stderr -> $out/launch.err
  local scenario=$1
  shift
  ip netns exec "${NS[1]}" "$plexus" launch "$scenario" --ssh-config "$SSH_CONFIG" --domain "$domain" ${QUIET---quiet} \
    --out "$out/launch" "${HOSTSET[@]}" "$@" > "$out/launch.out" 2> "$out/launch.err"
}

# Waits (up to $2 s) until every namespace is empty but its listening sshd; prints what is left.
wait_all_stopped() {
  local what=$1 limit=$2 t i left
  for t in $(seq 1 $((limit * 10))); do
    left=
    for i in $(seq 1 "$n"); do left="$left$(plexus_hosts_left "${NS[$i]}")"; done
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  for i in $(seq 1 "$n"); do
    left=$(plexus_hosts_left "${NS[$i]}")
    [ -n "$left" ] && echo "left in h$i after $what:" && plexus_describe $left
  done
  return 1
}

# Waits (up to 60 s) until namespace i runs $2 service processes (started with --part).
wait_services() {
  local i=$1 want=$2 t p count
  for t in $(seq 1 600); do
    count=0
    for p in $(ip netns pids "${NS[$i]}" 2>/dev/null); do
      tr '\0' ' ' < /proc/$p/cmdline 2>/dev/null | grep -q -- "--part " && count=$((count + 1))
    done
    [ "$count" -ge "$want" ] && return 0
    sleep 0.1
  done
  return 1
}

digest_of() { sed -n 's/.*"digest":"\([0-9a-f]*\)".*/\1/p' "$1"; }
json_get() { jq -r "$2" "$1"; }  # json_get FILE FILTER
since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }'; }

case $case in
lockstep2|lockstep3)
  # Closed loop (paper 003): plant and path on h1, the observer on h2, the controller on h2 or h3.
  place=(--set robots.r1.host=h1 --set services.path.host=h1 --set services.observer.host=h2)
  if [ "$n" -eq 3 ]; then place+=(--set services.controller.host=h3); vendors=(--dds cyclone --vendor observer=fast)
  else place+=(--set services.controller.host=h2); vendors=(--dds fast --vendor observer=cyclone); fi
  if [ "$n" -eq 3 ]; then
    # h3 runs an installed plexus, not this build tree: its `plexus:` is an install prefix
    # (cmake --install; the preflight checks its version as for a build tree).
    cmake --install "$(dirname "$plexus")/.." --prefix "$out/prefix_h3" > "$out/install_h3.log" || fail "cmake --install failed"
    HOSTSET+=(--set "hosts.h3.plexus=$out/prefix_h3")
  fi
  "$plexus" sim "$path" --json --quiet --out "$out/sim" "${HOSTSET[@]}" "${place[@]}" > "$out/sim.out" || fail "plexus sim failed"
  launch "$path" --json "${place[@]}" "${vendors[@]}"
  rc=$?
  sim=$(digest_of "$out/sim.out") got=$(digest_of "$out/launch.out")
  echo "sim digest $sim, launch over $n hosts $got (rc $rc)"
  [ $rc -eq 0 ] || { tail -5 "$out/launch.err"; fail "launch exited $rc"; }
  [ -n "$sim" ] && [ "$sim" = "$got" ] || fail "digest differs"
  # Every remote share's lines reached this run folder, prefixed by host: its launcher's closing line.
  for i in $(seq 2 "$n"); do
    grep -q "^plexus launch --host h$i: " "$out/launch/logs/h${i}_launch.log" 2>/dev/null || fail "h$i's log lines are not in $out/launch/logs"
    [ -f "$out/launch-h$i/logs/localisation_observer_observer.log" ] || [ -d "$out/launch-h$i/logs" ] || fail "no run folder on h$i"
    [ "$(json_get "$out/launch/launch.json" ".hosts.h$i.state")" = done ] || fail "launch.json: h$i not done"
  done
  if [ "$n" -eq 3 ]; then
    # h3's launcher was the installed one: it started the controller with its own share's
    # QoS file (a build tree's launcher gives deploy/qos.yaml).
    grep -q -- "--qos-file $out/prefix_h3/share/plexus/qos.yaml" "$out/launch-h3/logs/motion_controller_controller.log" \
      || fail "h3 did not run the installed plexus ($out/prefix_h3): $(head -1 "$out/launch-h3/logs/motion_controller_controller.log")"
  fi
  json_get "$out/launch/launch.json" '"startup \(.startup_s) s, teardown \(.teardown_s) s"'
  json_get "$out/launch/launch.json" '.hosts | to_entries[] | "\(.key): clock offset \(.value.clock_offset_ms) ms +- \(.value.clock_uncertainty_ms) ms"'
  wait_all_stopped "the run" 10 || fail "processes left after the run"
  ;;
realtime_rfid)
  # Paper 000 section 6.3.2 in realtime, the robot started on its reference: the paper's
  # steady bounds over [20, 45] s (tests/scripts/rfid_on_reference.sh): the plant on h1, the
  # observer on h2, the reference and the controller on h3. Not --quiet: the status line
  # (every 10 s off a terminal) must show each host's processes.
  . "$root/tests/scripts/rfid_on_reference.sh"
  rfid_on_reference 45 20
  QUIET= launch "$rfid" --json --set clock.mode=realtime "${RFID_STEADY[@]}" --set robots.r1.host=h1 \
    --set services.observer.host=h2 --set services.reference.host=h3 --set services.controller.host=h3
  rc=$?
  cat "$out/launch.out"
  grep -E "latency|hosts:" "$out/launch.err" | tail -3
  [ $rc -eq 0 ] || { tail -5 "$out/launch.err"; fail "launch exited $rc (1: a bound of the paper missed)"; }
  grep "| hosts: " "$out/launch.err" | tail -1
  grep -Eq "\| hosts: h1 1/1, h2 1/1 \([0-9.]+ ms\), h3 2/2 \([0-9.]+ ms\)$" "$out/launch.err" \
    || fail "no status line shows every host's processes running (hosts: h1 1/1, h2 1/1 (..), h3 2/2 (..))"
  json_get "$out/launch/launch.json" '"startup \(.startup_s) s, teardown \(.teardown_s) s"'
  wait_all_stopped "the run" 10 || fail "processes left after the run"
  ;;
teardown|session_dies|launcher_killed|host_killed)
  # Realtime, 60 s of the closed loop (stopped well before): plant and path on h1, observer on
  # h2, controller on h3 (h2 with two hosts).
  ctl=h3; [ "$n" -eq 2 ] && ctl=h2
  # setsid: the launcher leads its own process group, as a terminal's foreground job, so the
  # Ctrl-C below reaches the whole group as a terminal's would.
  setsid ip netns exec "${NS[1]}" "$plexus" launch "$path" --ssh-config "$SSH_CONFIG" --domain "$domain" --quiet \
    --out "$out/launch" "${HOSTSET[@]}" --set clock.mode=realtime --set duration=60 --set robots.r1.host=h1 \
    --set services.path.host=h1 --set services.observer.host=h2 --set services.controller.host=$ctl \
    > "$out/launch.out" 2> "$out/launch.err" &
  launcher=$!
  t0=$(date +%s.%N)
  wait_services 1 2 && wait_services 2 1 && { [ "$n" -eq 2 ] || wait_services 3 1; } || { tail -5 "$out/launch.err"; fail "the processes did not all start"; }
  echo "every service process running $(since "$t0") s after the command"
  sleep 2
  kill -0 "$launcher" 2>/dev/null || { tail -5 "$out/launch.err"; fail "the launcher ended early"; }
  t1=$(date +%s.%N)
  case $case in
  teardown) kill -INT -- "-$launcher" ;;  # Ctrl-C: SIGINT to the foreground process group
  launcher_killed) kill -9 "$launcher" ;;
  session_dies)
    for p in $(ip netns pids "${NS[1]}"); do
      tr '\0' ' ' < /proc/$p/cmdline 2>/dev/null | grep -q "^ssh .*${ADDR[2]} " && kill -9 "$p" && echo "killed the ssh session of h2 (pid $p)"
    done ;;
  host_killed)
    plexus_describe $(ip netns pids "${NS[3]}") > "$out/h3_killed.txt"
    for p in $(ip netns pids "${NS[3]}"); do kill -9 "$p" 2>/dev/null; done
    SSHD_PID[3]= ;;
  esac
  # The run must end soon after the event, not at its 60 s end (bounded wait, not a timing goal).
  for t in $(seq 1 200); do kill -0 "$launcher" 2>/dev/null || break; sleep 0.1; done
  kill -0 "$launcher" 2>/dev/null && fail "the launcher still runs 20 s after the $case event"
  wait "$launcher"
  rc=$?
  echo "launcher exit code $rc, $(since "$t1") s after the $case event"
  wait_all_stopped "$case" 15 || fail "processes left"
  echo "every namespace empty $(since "$t1") s after the $case event"
  last=$(tail -1 "$out/launch.err")
  echo "launcher's last line: $last"
  case $case in
  teardown)  # its own exit (130, saying so: not a death by the signal), and Ctrl-C is not a lost host
             # (ssh runs in its own process group)
    [ $rc -eq 130 ] && echo "$last" | grep -q '^plexus launch: interrupted (SIGINT)' ||
      fail "Ctrl-C ended the launcher with $rc and '$last' (expected 130 and 'interrupted (SIGINT)')"
    grep -q "^plexus launch: host .* lost" "$out/launch.err" && fail "Ctrl-C was taken for a lost host: $(grep "^plexus launch: host" "$out/launch.err")" ;;
  session_dies) [ $rc -eq 1 ] && echo "$last" | grep -q "host h2 .*lost" || fail "expected exit 1 and 'host h2 ... lost'" ;;
  host_killed) [ $rc -eq 1 ] && echo "$last" | grep -q "host h3 .*lost" || fail "expected exit 1 and 'host h3 ... lost'" ;;
  esac
  ;;
preflight)
  expect_refusal() {  # expect_refusal WHAT PATTERN: exit 2, one line naming the host, nothing started
    local what=$1 pattern=$2 rc
    launch "$path" "${@:3}" --set robots.r1.host=h1 --set services.observer.host=h2 --set services.controller.host=h2
    rc=$?
    echo "$what: exit $rc: $(cat "$out/launch.err")"
    [ $rc -eq 2 ] || fail "$what: exit $rc, expected 2"
    [ "$(wc -l < "$out/launch.err")" -eq 1 ] || fail "$what: more than one line on stderr"
    grep -q -- "$pattern" "$out/launch.err" || fail "$what: the error does not say '$pattern'"
    [ ! -e "$out/launch" ] || fail "$what: a run folder was created (something started)"
    wait_all_stopped "$what" 10 || fail "$what: processes left"
  }
  # Scenario keys: an ssh destination that ssh would read as an option, a workdir without ssh.
  "$plexus" launch "$path" --set hosts.h1.address=${ADDR[1]} --set "hosts.h2.ssh=-oProxyCommand=touch_$$" > /dev/null 2> "$out/key.err"
  rc=$?
  echo "ssh: -oProxyCommand=...: exit $rc: $(cat "$out/key.err")"
  [ $rc -eq 2 ] && grep -q "hosts.h2.ssh: expected \[user@\]host" "$out/key.err" || fail "a leading '-' in hosts.h2.ssh was not refused"
  "$plexus" launch "$path" --set hosts.h1.address=${ADDR[1]} --set hosts.h2.workdir=/tmp > /dev/null 2> "$out/key.err"
  rc=$?
  [ $rc -eq 2 ] && grep -q "hosts.h2.workdir: only for a host reached over ssh" "$out/key.err" || fail "workdir without ssh was not refused"
  # h3 has no sshd: connection refused.
  expect_refusal "unreachable host" "host h3 (root@${ADDR[3]}): unreachable over ssh"
  # h2's QoS profiles differ (its sshd sets PLEXUS_QOS_FILE for the session): another digest.
  sed 's/depth: 64/depth: 63/' "$root/deploy/qos.yaml" > "$out/qos_h2.yaml"
  cmp -s "$root/deploy/qos.yaml" "$out/qos_h2.yaml" && fail "the QoS copy did not change"
  plexus_sshd_stop 2
  plexus_sshd_start 2 "SetEnv PLEXUS_QOS_FILE=$out/qos_h2.yaml" || fail "sshd h2 restart"
  NO_SSHD[3]=
  plexus_sshd_start 3 || fail "sshd h3 start"
  expect_refusal "scenario mismatch" "host h2 (root@${ADDR[2]}): the scenario resolves differently there"
  plexus_sshd_stop 2
  plexus_sshd_start 2 || fail "sshd h2 restart"
  # Another plexus on h2: it answers with another version.
  printf '#!/bin/sh\necho "plexus-remote 1 0.0.0-other"\ncat > /dev/null\n' > "$out/other_plexus.sh"
  chmod +x "$out/other_plexus.sh"
  expect_refusal "another version" "host h2 (root@${ADDR[2]}): plexus 0.0.0-other there" --set "hosts.h2.plexus=$out/other_plexus.sh"
  # h2's scenario address is not one of its interfaces (ssh reaches it at its real one).
  expect_refusal "address on no interface" "host h2 (root@${ADDR[2]}): address 10.117.0.99" --set hosts.h2.address=10.117.0.99
  ;;
clock_offset)
  # h2 reports its clock 50 ms ahead (injected in the exchange): beyond the 1 ms bound of a 100 Hz run.
  place=(--set robots.r1.host=h2 --set services.path.host=h1 --set services.observer.host=h1 --set services.controller.host=h1)
  launch "$path" --set clock.mode=realtime --set duration=4 "${place[@]}" --inject-clock-offset h2=0.05
  rc=$?
  echo "realtime, +50 ms: exit $rc: $(tail -1 "$out/launch.err")"
  [ $rc -eq 2 ] || fail "an offset beyond the bound was not refused"
  grep -Eq "host h2 \(root@${ADDR[2]}\): its clock is \+(49\.9|50\.0)[0-9]* ms from this one's, beyond the realtime bound of 1.000 ms" "$out/launch.err" || fail "the refusal does not name h2, its offset and the bound"
  [ ! -e "$out/launch" ] || fail "a run folder was created (something started)"
  grep -Eq "^plexus launch: clock of h2: \+(49\.9|50\.0)[0-9]* ms \+- " "$out/launch.err" || fail "the offset was not printed"
  launch "$path" --set clock.mode=realtime --set duration=4 "${place[@]}" --inject-clock-offset h2=0.05 --allow-clock-offset
  rc=$?
  echo "realtime, +50 ms, --allow-clock-offset: exit $rc"
  [ $rc -eq 0 ] || [ $rc -eq 1 ] || { tail -5 "$out/launch.err"; fail "exit $rc"; }
  off=$(json_get "$out/launch/launch.json" '.hosts.h2.clock_offset_ms')
  corr=$(json_get "$out/launch/launch.json" '.command_latency["r1/cmd"].clock_offset_corrected_us')
  echo "h2 offset $off ms, r1/cmd latency corrected by $corr us"
  awk -v o="$off" -v c="$corr" 'BEGIN { d = c - o * 1e3; exit !(o > 49 && o < 51 && d < 1 && d > -1) }' || fail "offset or correction wrong"
  # The correction is applied: a true latency is >= 0, so the corrected one is >= the 50 ms added.
  p50=$(json_get "$out/launch/launch.json" '.command_latency["r1/cmd"].p50_us')
  awk -v p="$p50" 'BEGIN { exit !(p >= 49900) }' || fail "r1/cmd p50 $p50 us: the offset was not added to the latencies"
  grep -Eq "latency sensor -> r1/cmd: .*, corrected by (49|50)[0-9]{3}\.[0-9]* us of clock offset" "$out/launch.out" || fail "the summary does not say the latency was corrected"
  wait_all_stopped "the realtime run" 10 || fail "processes left"
  rm -rf "$out/launch"
  launch "$path" --json --set duration=2 "${place[@]}" --inject-clock-offset h2=0.05
  rc=$?
  echo "lockstep, +50 ms: exit $rc"
  [ $rc -eq 0 ] || [ $rc -eq 1 ] || { tail -5 "$out/launch.err"; fail "lockstep refused or failed ($rc)"; }
  wait_all_stopped "the lockstep run" 10 || fail "processes left"
  ;;
*) fail "unknown case" ;;
esac
echo "PASS ($case)"
