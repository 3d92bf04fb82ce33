# Sourced by the ssh multi-host tests: N network namespaces joined by a bridge (in a namespace
# of its own), host i at 10.117.0.i, and an sshd (Debian's openssh-server) in every namespace
# but the first, listening on that namespace's address only, with a host key and a user key
# the test generates into its folder. The launcher's ssh uses -F "$SSH_CONFIG" (known_hosts
# and the key in the test's folder). Nothing touches /root/.ssh or the system's sshd; every
# namespace and sshd is removed by plexus_hosts_cleanup (call it from an EXIT trap).
#
#   plexus_hosts_up DIR N          -> NS[1..N], ADDR[1..N], SSHD_PID[2..N], SSH_CONFIG
#   plexus_hosts_left NS           -> pids in namespace NS other than its listening sshd
#   plexus_hosts_cleanup

plexus_hosts_up() {
  local dir=$1 n=$2 i tag=$$
  HOSTS_DIR=$dir
  HOSTS_N=$n
  mkdir -p "$dir/ssh"
  BRIDGE_NS=plxbr_$tag
  ip netns add "$BRIDGE_NS" || return 1
  ip -n "$BRIDGE_NS" link add plxbr type bridge || return 1
  ip -n "$BRIDGE_NS" link set plxbr up
  ssh-keygen -q -t ed25519 -N '' -f "$dir/ssh/user_key" -C plexus-test || return 1
  : > "$dir/ssh/known_hosts"
  {
    echo "# written by tests/multihost/ssh_hosts.sh for this test only"
    echo "Host *"
    echo "  User root"
    echo "  IdentityFile $dir/ssh/user_key"
    echo "  IdentitiesOnly yes"
    echo "  UserKnownHostsFile $dir/ssh/known_hosts"
    echo "  GlobalKnownHostsFile /dev/null"
    echo "  StrictHostKeyChecking yes"
    echo "  LogLevel ERROR"
  } > "$dir/ssh/config"
  SSH_CONFIG=$dir/ssh/config
  # sshd needs its privilege separation folder (Debian's service creates it at boot).
  mkdir -p /run/sshd
  for i in $(seq 1 "$n"); do
    NS[$i]=plx${i}_$tag
    ADDR[$i]=10.117.0.$i
    ip netns add "${NS[$i]}" || return 1
    ip link add "plxh${i}_$tag" type veth peer name "plxb${i}_$tag" || return 1
    ip link set "plxh${i}_$tag" netns "${NS[$i]}"
    ip link set "plxb${i}_$tag" netns "$BRIDGE_NS"
    ip -n "$BRIDGE_NS" link set "plxb${i}_$tag" master plxbr
    ip -n "$BRIDGE_NS" link set "plxb${i}_$tag" up
    ip -n "${NS[$i]}" addr add "${ADDR[$i]}/24" dev "plxh${i}_$tag"
    ip -n "${NS[$i]}" link set lo up
    ip -n "${NS[$i]}" link set "plxh${i}_$tag" up
    [ "$i" -eq 1 ] && continue
    [ -n "${NO_SSHD[$i]:-}" ] && continue
    plexus_sshd_start "$i" || return 1
  done
}

# plexus_sshd_start I [extra sshd_config lines]: an sshd on host I's address.
plexus_sshd_start() {
  local i=$1 extra=${2:-} dir=$HOSTS_DIR
  [ -f "$dir/ssh/host_key_$i" ] || ssh-keygen -q -t ed25519 -N '' -f "$dir/ssh/host_key_$i" -C "plexus-test-h$i" || return 1
  cp "$dir/ssh/user_key.pub" "$dir/ssh/authorized_keys"
  {
    echo "ListenAddress ${ADDR[$i]}"
    echo "HostKey $dir/ssh/host_key_$i"
    echo "PidFile $dir/ssh/sshd_$i.pid"
    echo "AuthorizedKeysFile $dir/ssh/authorized_keys"
    echo "PasswordAuthentication no"
    echo "KbdInteractiveAuthentication no"
    echo "PermitRootLogin prohibit-password"
    echo "UsePAM no"
    echo "StrictModes no"
    echo "PrintMotd no"
    echo "MaxStartups 50"
    [ -n "$extra" ] && echo "$extra"
  } > "$dir/ssh/sshd_config_$i"
  grep -q "^${ADDR[$i]} " "$dir/ssh/known_hosts" || echo "${ADDR[$i]} $(cut -d' ' -f1,2 "$dir/ssh/host_key_$i.pub")" >> "$dir/ssh/known_hosts"
  ip netns exec "${NS[$i]}" /usr/sbin/sshd -D -f "$dir/ssh/sshd_config_$i" -E "$dir/ssh/sshd_$i.log" &
  SSHD_PID[$i]=$!
  # Ready when it accepts a connection (bounded wait).
  local k
  for k in $(seq 1 100); do
    ip netns exec "${NS[1]}" ssh -F "$SSH_CONFIG" -o BatchMode=yes -o ConnectTimeout=2 "${ADDR[$i]}" true 2>/dev/null && return 0
    sleep 0.1
  done
  echo "sshd on ${ADDR[$i]} did not come up: $(tail -3 "$dir/ssh/sshd_$i.log")"
  return 1
}

plexus_sshd_stop() {
  local i=$1
  [ -n "${SSHD_PID[$i]:-}" ] && kill "${SSHD_PID[$i]}" 2>/dev/null && wait "${SSHD_PID[$i]}" 2>/dev/null
  SSHD_PID[$i]=
}

# Pids in namespace $1 other than its listening sshd (an sshd serving a session counts).
plexus_hosts_left() {
  local ns=$1 i p out=
  for p in $(ip netns pids "$ns" 2>/dev/null); do
    local keep=1
    for i in "${!SSHD_PID[@]}"; do [ "$p" = "${SSHD_PID[$i]}" ] && keep=0; done
    [ $keep -eq 1 ] && out="$out $p"
  done
  echo $out
}

# Describes the pids given (for a failure message).
plexus_describe() {
  local p
  for p in "$@"; do echo "  $p: $(tr '\0' ' ' < /proc/$p/cmdline 2>/dev/null | cut -c1-150)"; done
}

plexus_hosts_cleanup() {
  local i p
  for i in $(seq 1 "${HOSTS_N:-0}"); do
    for p in $(ip netns pids "${NS[$i]}" 2>/dev/null); do kill -9 "$p" 2>/dev/null; done
  done
  for i in "${!SSHD_PID[@]}"; do [ -n "${SSHD_PID[$i]}" ] && kill "${SSHD_PID[$i]}" 2>/dev/null; done
  for i in $(seq 1 "${HOSTS_N:-0}"); do ip netns del "${NS[$i]}" 2>/dev/null; done
  [ -n "${BRIDGE_NS:-}" ] && ip netns del "$BRIDGE_NS" 2>/dev/null
  return 0
}
