# A user's first hour (issue 19), the CLI basics: an unknown command is named, every error
# line has one prefix ("plexus <command>: "), a run too long for the machine is refused up
# front naming `duration` (exit 2, not std::bad_alloc and exit 1), and a zero or negative
# wait or timeout is refused (exit 2).
set(FH_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml)
plexus_refusal_test(first_hour.unknown_command LABELS cli
                    ERROR "^plexus: unknown command 'bogus' \\(commands: demo, qos, launch, sim, report"
                    COMMAND $<TARGET_FILE:plexus> bogus)
plexus_refusal_test(first_hour.error_prefix_names_the_command LABELS cli
                    ERROR "^plexus sim: error: .*unicycle_circle.yaml: --set seed=-1: seed: must be >= 0"
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set seed=-1)
plexus_refusal_test(first_hour.duration_beyond_the_step_limit LABELS cli
                    ERROR "duration: 1e\\+12 s at a step of 0.01 s is more than the 1e9 steps a run can hold"
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set duration=1e12)
plexus_refusal_test(first_hour.duration_beyond_memory LABELS cli
                    ERROR "^plexus sim: error: .*unicycle_circle.yaml: duration: 1e\\+07 s of [0-9]+ signals needs [0-9.]+ GB to record, more than half of this machine's"
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set duration=1e7)
plexus_refusal_test(first_hour.negative_timeout LABELS cli
                    ERROR "^plexus launch: error: --timeout: must be > 0 s \\(got -1\\)"
                    COMMAND $<TARGET_FILE:plexus> launch ${FH_SCENARIO} --timeout -1)
plexus_refusal_test(first_hour.zero_wait LABELS cli
                    ERROR "--wait: must be > 0 s \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plexus> topic list --wait 0)
plexus_refusal_test(first_hour.service_zero_timeout LABELS cli
                    ERROR "^plant_simulator: error: --timeout: must be > 0 s \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plant_simulator> --timeout 0)
# --join: the values the help lists are the values the parser takes (origin_time was refused).
plexus_refusal_test(first_hour.latency_join_origin_time LABELS cli
                    ERROR "/nonexistent/run.sqlite: no such file"
                    COMMAND $<TARGET_FILE:plexus> latency pipeline /nonexistent/run.sqlite --join origin_time)
plexus_refusal_test(first_hour.latency_join_lists_the_values LABELS cli
                    ERROR "--join: origin not in \\{auto,origin_time,data_time\\}"
                    COMMAND $<TARGET_FILE:plexus> latency pipeline /nonexistent/run.sqlite --join origin)
