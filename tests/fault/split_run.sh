# Sourced by the network fault tests, after netns_pair.sh and `pair_up`: runs a scenario
# split across the two namespaces, `plexus launch --host h2` in $NS2 and `--host h1` (the
# clock, the recording and the run folder) in $NS1, with the same arguments.
#
#   split_start OUT DOMAIN ARGS...   start both launchers; h1's stdout (--json) goes to
#                                    OUT/h1.json, its stderr to OUT/h1.log, the run folder
#                                    is OUT/launch; h2's output goes to OUT/h2.log
#   split_wait [SECONDS]             wait for both (up to SECONDS, default 300); sets SPLIT_RC
#                                    and SPLIT_H2_RC. A launcher still running then has hung:
#                                    what runs in the namespaces is described (threads and
#                                    where they wait; their stacks if gdb is installed), killed,
#                                    and its code is 124, as timeout(1) says
#   json_of FILE FILTER              a value from a JSON file (jq), "null" if absent
#   rfid_on_reference DURATION FROM [ARGS...]
#                                    RFID_STEADY (tests/scripts/rfid_on_reference.sh)
#   sim_digest OUT ARGS...           `plexus sim` of SCENARIO with ARGS (run folder OUT/sim):
#                                    sets SIM_DIGEST, or fails the test
#
# The placement flags (which host runs what) are the caller's, in ARGS; PLACE below is the
# RFID loop's split: plant and reference on h1, observer and controller on h2.

split_start() {
  local out=$1 domain=$2
  shift 2
  mkdir -p "$out"
  ip netns exec "$NS2" "$PLEXUS" launch "$SCENARIO" --host h2 --domain "$domain" --quiet "$@" > "$out/h2.log" 2>&1 &
  SPLIT_H2=$!
  ip netns exec "$NS1" "$PLEXUS" launch "$SCENARIO" --host h1 --domain "$domain" --quiet --json --out "$out/launch" "$@" \
    > "$out/h1.json" 2> "$out/h1.log" &
  SPLIT_H1=$!
}

split_wait() {
  local limit=${1:-300} waited=0 hung=0 pid
  while kill -0 "$SPLIT_H1" 2>/dev/null || kill -0 "$SPLIT_H2" 2>/dev/null; do
    if [ "$waited" -ge "$limit" ]; then
      hung=1
      echo "HUNG: a launcher still runs $limit s after the start; what runs in the namespaces:"
      split_describe
      for pid in $(split_pids); do kill -9 "$pid" 2>/dev/null; done
      break
    fi
    sleep 1
    waited=$((waited + 1))
  done
  wait "$SPLIT_H1"
  SPLIT_RC=$?
  wait "$SPLIT_H2"
  SPLIT_H2_RC=$?
  [ "$hung" = 1 ] && { SPLIT_RC=124 SPLIT_H2_RC=124; }
  SPLIT_H1= SPLIT_H2=
}

# The processes running in the two namespaces.
split_pids() { ip netns pids "$NS1" 2>/dev/null; ip netns pids "$NS2" 2>/dev/null; }

# Each process in the namespaces: its command, its threads by name and what they wait in
# (wchan), and with gdb, each thread's innermost frames.
split_describe() {
  local pid t
  for pid in $(split_pids); do
    echo "  $(ps -o pid=,stat=,etimes=,args= -p "$pid" | cut -c1-160)"
    for t in /proc/"$pid"/task/*; do echo "$(cat "$t/comm" 2>/dev/null)@$(cat "$t/wchan" 2>/dev/null)"; done |
      sort | uniq -c | awk '{ printf "    %s x%s\n", $2, $1 }'
    command -v gdb > /dev/null &&
      timeout 20 gdb -p "$pid" -batch -ex "thread apply all bt 6" 2>/dev/null | grep -E "^(Thread|#)" | head -60 | sed 's/^/    /'
  done
}

json_of() {  # an empty or missing file (a failed run prints no JSON) gives "null" too
  local v
  v=$(jq -r "$2 // \"null\"" "$1" 2>/dev/null)
  echo "${v:-null}"
}

# The two hosts' addresses (netns_pair.sh) as the scenario's hosts.
HOSTS=(--set hosts.h1.address=10.231.0.1 --set hosts.h2.address=10.231.0.2)
PLACE=(--set robots.r1.host=h1 --set services.reference.host=h1 --set services.observer.host=h2
       --set services.controller.host=h2)

. "$(dirname "${BASH_SOURCE[0]}")/../scripts/rfid_on_reference.sh"

sim_digest() {
  local out=$1 sim
  shift
  sim=$("$PLEXUS" sim "$SCENARIO" --json --quiet --out "$out/sim" "$@" 2> "$out/sim.log")
  SIM_DIGEST=$(echo "$sim" | jq -r .digest)
  [ -n "$SIM_DIGEST" ] && [ "$SIM_DIGEST" != null ] || { echo "FAIL: plexus sim gave no digest"; tail -3 "$out/sim.log"; exit 1; }
}
