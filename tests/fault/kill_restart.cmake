# Realtime fault test: kill a service mid-run with `plexus launch --kill`; the launcher
# restarts it RESTART_DELAY seconds later (the scenario's `restart_delay`, systemd's
# RestartSec), so its output always pauses for longer than the input deadline. Then check
# from the run's launch.json and signals that the pause happened, that the controller applied
# its safe (all-zero) command, that the launcher restarted the service, and that tracking
# resumed (the scenario's expectations, passed in EXPECT as --set arguments). How fast the
# safe command came is reported, not asserted here: timing goals live in measured reports.
# Arguments: PLEXUS, SCENARIO, OUT, DOMAIN, KILL (PROCESS@SECONDS), SERVICE, RESTART_DELAY,
# OUTPUT_SIGNAL (the killed service's output, as its file in signals/), EXPECT and VENDORS
# (launch arguments choosing the vendors), both "|"-separated.
string(REPLACE "|" ";" expect "${EXPECT}")
string(REPLACE "|" ";" vendors "${VENDORS}")
execute_process(COMMAND ${PLEXUS} launch ${SCENARIO} --quiet --domain ${DOMAIN} --out ${OUT} --kill ${KILL} ${vendors}
                        --set clock.mode=realtime --set services.${SERVICE}.restart_delay=${RESTART_DELAY} ${expect}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "launch exited ${rc}: tracking did not resume within the expectations")
endif()
file(READ ${OUT}/launch.json j)
string(JSON safe GET "${j}" fault safe_command_after_s)
# restarts: {"<executable> <service>": count}; the executable depends on the service's type.
string(JSON restarted_process MEMBER "${j}" restarts 0)
string(JSON restarts GET "${j}" restarts "${restarted_process}")
if(NOT restarted_process MATCHES " ${SERVICE}$")
  message(FATAL_ERROR "restarted '${restarted_process}', expected the process of ${SERVICE}")
endif()
# How long the service's output stopped (the largest step gap in its recorded signal): the
# controller must hold only if that outage outlasted the input deadline. A Cyclone DDS
# observer can be back within the default three periods; then no hold is due.
file(STRINGS ${OUT}/signals/${OUTPUT_SIGNAL}.csv rows)
list(POP_FRONT rows)
set(prev -1)
set(gap 0)
foreach(row IN LISTS rows)
  string(REGEX MATCH "^[^,]*,([0-9]+)," _ "${row}")
  set(step ${CMAKE_MATCH_1})
  if(prev GREATER_EQUAL 0)
    math(EXPR d "${step} - ${prev}")
    if(d GREATER gap)
      set(gap ${d})
    endif()
  endif()
  set(prev ${step})
endforeach()
string(JSON deadline GET "${j}" fault input_deadline_periods)
message(STATUS "${OUTPUT_SIGNAL} paused for ${gap} steps (deadline ${deadline} periods); "
               "safe command ${safe} s after the kill; ${restarts} restart(s)")
# A gap of g steps: the estimate of step k is produced at (k + 1/4) periods and received d
# later; the controller ticks at (j + 1/2). At its tick (k + g - 1/2), the last one that may
# precede the next estimate, that input is (g - 3/4) periods old less d: stale past a
# deadline of D periods for certain once g >= D + 2 (d < 1.25 periods). The restart delay
# makes the gap far longer than that (0.5 s: 50 periods at 100 Hz), so the hold is always due.
string(REGEX REPLACE "\\..*$" "" deadline_whole "${deadline}")  # 3.0 -> 3 (a whole number of periods)
math(EXPR certain "${deadline_whole} + 1")
if(NOT gap GREATER certain)
  message(FATAL_ERROR "${OUTPUT_SIGNAL} paused for only ${gap} steps despite the ${RESTART_DELAY} s restart delay "
                      "(deadline ${deadline} periods): the fault was not exercised")
endif()
if(safe STREQUAL "null" OR safe STREQUAL "")
  message(FATAL_ERROR "${OUTPUT_SIGNAL} paused for ${gap} steps, past the deadline, but no safe (all-zero) command was observed")
endif()
if(NOT restarts GREATER_EQUAL 1)
  message(FATAL_ERROR "the launcher did not restart ${SERVICE}")
endif()
# The launcher collected the process's logs: its log file records both starts and the kill.
string(REPLACE " " "_" log_name "${restarted_process}")
file(STRINGS ${OUT}/logs/${log_name}.log log_lines REGEX "^-- ")
list(FILTER log_lines INCLUDE REGEX "^-- started pid|exited with code 137")
list(LENGTH log_lines n)
message(STATUS "logs/${log_name}.log: ${n} launcher lines (2 starts, 1 kill expected)")
if(n LESS 3)
  message(FATAL_ERROR "logs/${log_name}.log lacks the starts and the kill: ${log_lines}")
endif()
