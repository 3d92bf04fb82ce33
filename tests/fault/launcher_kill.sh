#!/usr/bin/env bash
# launcher_kill.sh PLEXUS SCENARIO OUT DOMAIN
# Issue 14, process faults: killing `plexus launch` itself (SIGKILL, which it cannot catch)
# leaves no orphan. For each case the launcher starts a realtime run; once all its children
# are up, the test lists their pids, kills the launcher with SIGKILL and requires every child
# to be gone within 10 s (they get SIGTERM from the kernel when it dies: PR_SET_PDEATHSIG,
# set by the launcher between fork and exec, and by the services themselves), on Fast DDS
# and on Cyclone DDS. Any survivor is listed, then killed by the test.
set -u
plexus=$1 scenario=$2 out=$3 domain=$4
rm -rf "$out" && mkdir -p "$out"
launcher=
survivors=()
cleanup() {
  [ -n "$launcher" ] && kill -9 "$launcher" 2>/dev/null
  [ ${#survivors[@]} -gt 0 ] && kill -9 "${survivors[@]}" 2>/dev/null
  return 0
}
trap cleanup EXIT
fail=0
children_of() { ps -o pid= --ppid "$1" | tr -d ' '; }  # procps (tools/setup/install_deps.sh)
alive() {  # running, not a zombie waiting to be reaped
  local state
  state=$(sed 's/^.*) \([A-Za-z]\) .*/\1/' "/proc/$1/stat" 2>/dev/null) || return 1
  [ -n "$state" ] && [ "$state" != Z ]
}
# run_case NAME EXPECTED_CHILDREN launch args...
run_case() {
  local name=$1 expected=$2
  shift 2
  "$plexus" launch "$@" --domain "$domain" --quiet --out "$out/$name" > "$out/$name.log" 2>&1 &
  launcher=$!
  local kids=() waited=0
  while :; do
    mapfile -t kids < <(children_of "$launcher")
    [ ${#kids[@]} -ge "$expected" ] && break
    if ! kill -0 "$launcher" 2>/dev/null || [ $waited -ge 300 ]; then
      echo "FAIL $name: the launcher has ${#kids[@]} of $expected children after $((waited / 10)) s"; tail -5 "$out/$name.log"
      fail=1; cleanup; launcher=; return
    fi
    sleep 0.1
    waited=$((waited + 1))
  done
  sleep 1  # into the run: every child has loaded its part and created its participant
  mapfile -t kids < <(children_of "$launcher")
  local names=""
  for k in "${kids[@]}"; do names+=" $k:$(tr -d '\0' < "/proc/$k/comm" 2>/dev/null)"; done
  echo "$name: launcher $launcher, children$names"
  kill -9 "$launcher"
  wait "$launcher" 2>/dev/null
  launcher=
  local left=("${kids[@]}") i
  for i in $(seq 100); do
    local still=()
    for k in "${left[@]}"; do alive "$k" && still+=("$k"); done
    left=("${still[@]}")
    [ ${#left[@]} -eq 0 ] && break
    sleep 0.1
  done
  if [ ${#left[@]} -gt 0 ]; then
    echo "FAIL $name: ${#left[@]} orphan(s) 10 s after the launcher's SIGKILL:"
    for k in "${left[@]}"; do echo "  $k $(tr '\0' ' ' < "/proc/$k/cmdline" 2>/dev/null | cut -c1-160)"; done
    survivors+=("${left[@]}")
    fail=1
  else
    echo "$name: all ${#kids[@]} children gone after the launcher's SIGKILL"
  fi
}
long=(--set duration=60 --set metrics.0.from=0 --set metrics.1.from=0 --set clock.mode=realtime)
run_case services_fast 4 "$scenario" "${long[@]}" --dds fast
run_case services_cyclone 4 "$scenario" "${long[@]}" --dds cyclone
exit $fail
