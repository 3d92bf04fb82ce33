# A user's first hour (issue 19), the CLI basics: an unknown command is named, every error
# line has one prefix ("plexus <command>: "), a run too long for the machine is refused up
# front naming `duration` (exit 2, not std::bad_alloc and exit 1), and a zero or negative
# wait or timeout is refused (exit 2).
set(FH_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml)
add_test(NAME first_hour.unknown_command
         COMMAND ${EXPECT} 2 "^plexus: unknown command 'bogus' \\(commands: demo, qos, launch, sim, report"
         $<TARGET_FILE:plexus> bogus)
add_test(NAME first_hour.error_prefix_names_the_command
         COMMAND ${EXPECT} 2 "^plexus sim: error: .*unicycle_circle.yaml: --set seed=-1: seed: must be >= 0"
         $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set seed=-1)
add_test(NAME first_hour.duration_beyond_the_step_limit
         COMMAND ${EXPECT} 2 "duration: 1e\\+12 s at a step of 0.01 s is more than the 1e9 steps a run can hold"
         $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set duration=1e12)
add_test(NAME first_hour.duration_beyond_memory
         COMMAND ${EXPECT} 2 "^plexus sim: error: .*unicycle_circle.yaml: duration: 1e\\+07 s of [0-9]+ signals needs [0-9.]+ GB to record, more than half of this machine's"
         $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set duration=1e7)
add_test(NAME first_hour.negative_timeout
         COMMAND ${EXPECT} 2 "^plexus launch: error: --timeout: must be > 0 s \\(got -1\\)"
         $<TARGET_FILE:plexus> launch ${FH_SCENARIO} --timeout -1)
add_test(NAME first_hour.zero_wait
         COMMAND ${EXPECT} 2 "--wait: must be > 0 s \\(got 0\\)"
         $<TARGET_FILE:plexus> topic list --wait 0)
add_test(NAME first_hour.service_zero_timeout
         COMMAND ${EXPECT} 2 "^plant_simulator: error: --timeout: must be > 0 s \\(got 0\\)"
         $<TARGET_FILE:plant_simulator> --timeout 0)
set_tests_properties(first_hour.unknown_command first_hour.error_prefix_names_the_command
                     first_hour.duration_beyond_the_step_limit first_hour.duration_beyond_memory
                     first_hour.negative_timeout first_hour.zero_wait first_hour.service_zero_timeout
                     PROPERTIES LABELS "cli")
# --join: the values the help lists are the values the parser takes (origin_time was refused).
add_test(NAME first_hour.latency_join_origin_time
         COMMAND ${EXPECT} 2 "/nonexistent/run.sqlite: no such file"
         $<TARGET_FILE:plexus> latency pipeline /nonexistent/run.sqlite --join origin_time)
add_test(NAME first_hour.latency_join_lists_the_values
         COMMAND ${EXPECT} 2 "--join: origin not in \\{auto,origin_time,data_time\\}"
         $<TARGET_FILE:plexus> latency pipeline /nonexistent/run.sqlite --join origin)
set_tests_properties(first_hour.latency_join_origin_time first_hour.latency_join_lists_the_values PROPERTIES LABELS "cli")
