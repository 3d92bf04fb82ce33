# Values that were accepted and should not have been (issue 31, "The rough edges"): each is
# one line "<program>: error: <option>: ..." and exit 2, the style of every command-line
# error (plexus/base/cli_style.hpp). Each failed before its fix: --step 0 and -0.01 ran,
# replay --rate 0 replayed at the recorded speed, CLI11's own errors had no "error:", and a
# recorder with nothing to record said it had recorded to a file it did not write.
plexus_refusal_test(first_hour.service_step_zero LABELS cli first_hour
                    ERROR "^plant_simulator: error: --step: must be > 0 s \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plant_simulator>
                            --params ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml --step 0)
plexus_refusal_test(first_hour.service_step_negative LABELS cli first_hour
                    ERROR "^localisation_observer: error: --step: must be > 0 s \\(got -0.01\\)"
                    COMMAND $<TARGET_FILE:localisation_observer> --step -0.01)
plexus_refusal_test(first_hour.bridge_step_negative LABELS cli first_hour
                    ERROR "^udp_bridge: error: --step: must be > 0 s \\(got -0.01\\)"
                    COMMAND $<TARGET_FILE:udp_bridge> --step -0.01)
plexus_refusal_test(first_hour.replay_rate_zero LABELS cli first_hour
                    ERROR "^plexus replay: error: --rate: must be > 0 Hz \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plexus> replay /nonexistent/run.mcap --rate 0)
plexus_refusal_test(first_hour.parser_error_style LABELS cli first_hour
                    ERROR "^plexus launch: error: --domain: Value 233 not in range 0 to 232 \\(--help lists the options\\)$"
                    COMMAND $<TARGET_FILE:plexus> launch ${FH_SCENARIO} --domain 233)
plexus_refusal_test(first_hour.record_nothing_writes_nothing EXIT 1 LABELS cli first_hour
                    ERROR "^plexus record: error: no topic with a writer was discovered on domain 155; .*/nothing.mcap not written$"
                    COMMAND $<TARGET_FILE:plexus> record -o ${CMAKE_BINARY_DIR}/test-runs/first_hour/nothing.mcap
                            --duration 0.5 --domain 155)
# A negative --cpu meant "no pinning" without a word, and a service took --priority 100 (2026-11-30).
plexus_refusal_test(first_hour.bridge_cpu_negative LABELS cli first_hour
                    ERROR "^udp_bridge: error: --cpu: Value -3 not in range 0 to [0-9]+"
                    COMMAND $<TARGET_FILE:udp_bridge> --cpu -3)
plexus_refusal_test(first_hour.service_priority_range LABELS cli first_hour
                    ERROR "^plant_simulator: error: --priority: Value 100 not in range 0 to 99"
                    COMMAND $<TARGET_FILE:plant_simulator>
                            --params ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml --priority 100)
plexus_refusal_test(first_hour.service_cpu_negative LABELS cli first_hour
                    ERROR "^motion_controller: error: --cpu: Value -1 not in range 0 to [0-9]+"
                    COMMAND $<TARGET_FILE:motion_controller> --cpu -1)
plexus_refusal_test(first_hour.emulator_cpu_negative LABELS cli first_hour
                    ERROR "^device_emulator: error: --cpu: Value -2 not in range 0 to [0-9]+"
                    COMMAND $<TARGET_FILE:device_emulator> --cpu -2)
add_test(NAME first_hour.udp_bind_busy
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/udp_bind_busy.sh $<TARGET_FILE:udp_bridge>
                 ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml 47991)
set_tests_properties(first_hour.udp_bind_busy PROPERTIES LABELS "cli;first_hour;light" TIMEOUT 60)
add_test(NAME first_hour.stop_summary_at_default_level
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/stop_summary.sh $<TARGET_FILE:plant_simulator>
                 ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml 150)
set_tests_properties(first_hour.stop_summary_at_default_level PROPERTIES LABELS "cli;first_hour" TIMEOUT 30)
# plexus topic and a topic's writers: a --type the writers do not publish (exit 2, both types
# named), and two processes writing one topic (a warning naming both). Domain 185.
add_test(NAME first_hour.topic_type_and_producers
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/topic_producers.sh ${CMAKE_BINARY_DIR}/bin
                 ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml 185)
set_tests_properties(first_hour.topic_type_and_producers PROPERTIES LABELS "cli;first_hour;multiprocess" TIMEOUT 60)
# A robot's params file may carry its base step (`step:`); a bad one names the file and line.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bad_step_robot.yaml "plant:\n  type: unicycle\nstep: -1\n")
plexus_refusal_test(first_hour.params_step_bad LABELS cli first_hour
                    ERROR "^plant_simulator: error: .*bad_step_robot.yaml:3: step: must be a number in \\(0, 1\\] s"
                    COMMAND $<TARGET_FILE:plant_simulator> --params ${CMAKE_CURRENT_BINARY_DIR}/bad_step_robot.yaml)
# The late-read count of services started alone means what it means under a launch (issue 31):
# the RFID loop by hand, four services, 4 s. Domain 186.
add_test(NAME first_hour.late_reads_alone
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/late_reads_alone.sh ${CMAKE_BINARY_DIR}/bin ${PROJECT_SOURCE_DIR}/deploy 186
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/late_reads_alone)
set_tests_properties(first_hour.late_reads_alone PROPERTIES LABELS "first_hour;multiprocess;realtime" TIMEOUT 60)
# An algorithm's own range check names the key's line, not its section's (line 4 of the file,
# not line 1): issue 31, "a range error names line 1 of a file where the key is on line 3".
plexus_refusal_test(first_hour.range_error_line LABELS cli first_hour
                    ERROR "^localisation_observer: error: .*/observer_gain_negative.yaml:4: services.localisation_observer.L: heading_observer: L must be finite and > 0 \\(got -3\\)$"
                    COMMAND $<TARGET_FILE:localisation_observer>
                            --params ${PROJECT_SOURCE_DIR}/tests/data/observer_gain_negative.yaml)
