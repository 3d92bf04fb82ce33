# Sourced by the lockstep fault tests: waiting until a run is under way, as seen by a listener
# that prints the clock's steps (`plexus topic echo lockstep/clock --csv`, one row per step).
#
#   await_clock_steps FILE COUNT PID   waits until FILE has COUNT rows after its header, up to
#                                      60 s, or until process PID (the launcher) has ended;
#                                      sets SEEN to the rows seen

await_clock_steps() {
  local file=$1 count=$2 pid=$3 i
  SEEN=0
  for ((i = 0; i < 600 && SEEN < count; ++i)); do
    sleep 0.1
    SEEN=$(($(wc -l < "$file") - 1))
    kill -0 "$pid" 2>/dev/null || break
  done
}
