# Recordings (issue 28): MCAP by default, a recorder killed mid-recording, SQLite still read
# and converted. Included from tools.cmake; domains 213, 215, 218, 219, 227 (of its 180-229).
foreach(variant "fast;213" "cyclone;215")
  list(POP_FRONT variant vendor domain)
  # SIGKILL during `plexus record`: the file replays up to the cut, with one line saying so.
  add_test(NAME tools.record_killed_${vendor}
           COMMAND ${TOOLS_DIR}/record_killed.sh ${BIN_DIR} ${vendor} ${domain}
                   ${CMAKE_BINARY_DIR}/test-runs/tools/record_killed_${vendor})
  set_tests_properties(tools.record_killed_${vendor} PROPERTIES LABELS "tools;multiprocess;fault" TIMEOUT 180)
endforeach()
# SIGKILL of `plexus launch --record` mid-run: the recording is readable up to the cut.
add_test(NAME tools.launch_record_killed_cyclone
         COMMAND ${TOOLS_DIR}/launch_record_killed.sh ${PLEXUS_CLI} ${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml
                 cyclone 218 ${CMAKE_BINARY_DIR}/test-runs/tools/launch_record_killed_cyclone)
set_tests_properties(tools.launch_record_killed_cyclone PROPERTIES LABELS "tools;multiprocess;fault;lockstep" TIMEOUT 180)
# SQLite recordings are still written (--format sqlite, *.sqlite) and read by replay.
add_test(NAME tools.record_replay_sqlite_fast
         COMMAND ${CMAKE_COMMAND} -E env EXT=sqlite ${TOOLS_DIR}/record_replay.sh ${BIN_DIR} fast 219
                 ${CMAKE_BINARY_DIR}/test-runs/tools/record_replay_sqlite_fast)
set_tests_properties(tools.record_replay_sqlite_fast PROPERTIES LABELS "tools;multiprocess" TIMEOUT 120)
# A SQLite recording converted to MCAP holds the same samples; topic echo --recording reads both.
add_test(NAME tools.record_convert_sqlite_to_mcap
         COMMAND ${TOOLS_DIR}/record_convert.sh ${PLEXUS_CLI} ${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml 227
                 ${CMAKE_BINARY_DIR}/test-runs/tools/record_convert)
set_tests_properties(tools.record_convert_sqlite_to_mcap PROPERTIES LABELS "tools;multiprocess;lockstep" TIMEOUT 120)
# Bad input of the recording commands: one line, exit 2.
plexus_refusal_test(tools.record_bad_format LABELS cli tools
                    ERROR "--format: 'bag' is not a recording format \\(mcap or sqlite\\)"
                    COMMAND ${PLEXUS_CLI} record -o /tmp/x.bag --format bag --domain 214)
plexus_refusal_test(tools.record_bad_compression LABELS cli tools
                    ERROR "--compression: 'bz2' is not a chunk compression"
                    COMMAND ${PLEXUS_CLI} record -o /tmp/x.mcap --compression bz2 --domain 214)
plexus_refusal_test(tools.record_info_not_a_recording LABELS cli tools
                    ERROR "qos.yaml: truncated or corrupt recording"
                    COMMAND ${PLEXUS_CLI} record info ${PROJECT_SOURCE_DIR}/deploy/qos.yaml)
