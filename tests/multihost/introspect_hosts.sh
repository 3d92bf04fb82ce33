#!/usr/bin/env bash
# introspect_hosts.sh BIN DEPLOY DOMAIN OUT: `plexus service list` and `plexus param` across two
# hosts (issue 31), with no launcher. Two network namespaces joined by a veth pair
# (10.231.0.1 <-> 10.231.0.2, addresses that exist only inside them), each with a host name of
# its own (a UTS namespace: h1, h2). Paper 000's closed loop runs as services started alone:
# on h1 the plant (Fast DDS) and the controller (Cyclone DDS), on h2 the reference (Fast DDS)
# and the observer (Cyclone DDS). From each host, on each vendor:
#  - service list shows the four processes with the host each runs on, running;
#  - param set changes a service on the other host (h1 -> the observer's L on h2, h2 -> the
#    controller's k1 on h1), acknowledged with a step, and param get reads it back.
# The namespaces and the veth pair are removed on exit. Needs root (CI runs as root).
set -u
bin=$1 deploy=$2 domain=$3 out=$4
rm -rf "$out" && mkdir -p "$out"
. "$(dirname "$0")/netns_pair.sh"
pids=()
cleanup() {
  kill "${pids[@]}" 2> /dev/null
  wait 2> /dev/null
  netns_pair_down
}
trap cleanup EXIT
netns_pair_up
peers=10.231.0.1,10.231.0.2
on() {  # on h1|h2 PROGRAM ARGS...: run on that host (its namespace, its host name, its address)
  local host=$1 ns address
  shift
  if [ "$host" = h1 ]; then ns=$ns1 address=10.231.0.1; else ns=$ns2 address=10.231.0.2; fi
  ip netns exec "$ns" unshare --uts sh -c 'hostname "$0"; exec "$@"' "$host" "$@" \
    --interface "$address" --peers "$peers" --domain "$domain"
}
service() {  # service HOST LOG PROGRAM ARGS...
  local host=$1 log=$2
  shift 2
  on "$host" "$@" > /dev/null 2> "$out/$log.log" &
  pids+=($!)
}
service h1 plant "$bin/plant_simulator" --params "$deploy/params/unicycle_robot.yaml" --dds fast
service h1 controller "$bin/motion_controller" --name controller --params "$deploy/params/trajectory_tracking.yaml" --dds cyclone
service h2 reference "$bin/component_host" --name reference --params "$deploy/params/figure_eight_reference.yaml" --dds fast
service h2 observer "$bin/localisation_observer" --name observer --params "$deploy/params/heading_observer.yaml" --dds cyclone
fail=0
bad() { echo "FAIL: $*"; fail=1; }
sleep 1
for from in h1 h2; do
  for vendor in fast cyclone; do
    on "$from" "$bin/plexus" service list --dds "$vendor" --wait 4 --json > "$out/list_${from}_$vendor.json" 2> "$out/list.err"
    jq -c '[.[] | {name, host, state}]' "$out/list_${from}_$vendor.json"
    jq -e '
      def on(name; host): any(.[]; .name == name and .host == host and (.state == "running" or .state == "degraded"));
      on("plant_simulator r1"; "h1") and on("motion_controller controller"; "h1")
      and on("component_host reference"; "h2") and on("localisation_observer observer"; "h2")' \
      "$out/list_${from}_$vendor.json" > /dev/null ||
      bad "service list from $from on $vendor does not show the four services on their hosts"
  done
done
# A parameter of a service on the other host, each way, each vendor.
on h1 "$bin/plexus" param set "localisation_observer observer" L 2.5 --dds fast --timeout 20 > "$out/set_L.txt" 2>&1 ||
  bad "param set L from h1: $(cat "$out/set_L.txt")"
grep -Eq "^localisation_observer observer: observer.L 0.6 -> 2.5 at step [0-9]+$" "$out/set_L.txt" || bad "set L: $(cat "$out/set_L.txt")"
on h2 "$bin/plexus" param set "motion_controller controller" k1 0.05 --dds cyclone --timeout 20 > "$out/set_k1.txt" 2>&1 ||
  bad "param set k1 from h2: $(cat "$out/set_k1.txt")"
grep -Eq "^motion_controller controller: controller.k1 0.11 -> 0.05 at step [0-9]+$" "$out/set_k1.txt" ||
  bad "set k1: $(cat "$out/set_k1.txt")"
cat "$out/set_L.txt" "$out/set_k1.txt"
on h2 "$bin/plexus" param get "localisation_observer observer" L --dds cyclone --timeout 20 > "$out/get_L.txt" 2>&1
grep -qx "observer.L = 2.5" "$out/get_L.txt" || bad "param get L from h2: $(cat "$out/get_L.txt")"
on h1 "$bin/plexus" param get "motion_controller controller" k1 --dds fast --timeout 20 > "$out/get_k1.txt" 2>&1
grep -qx "controller.k1 = 0.05" "$out/get_k1.txt" || bad "param get k1 from h1: $(cat "$out/get_k1.txt")"
exit $fail
