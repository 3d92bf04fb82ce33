# A user's first hour (issue 19), recordings: a truncated one is refused on open; every
# executable a user runs has --version (the test peers and probes under tests/ are not for users).
add_test(NAME first_hour.truncated_recording
         COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/truncated_recording.sh $<TARGET_FILE:plexus> 149
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/truncated_recording)
set_tests_properties(first_hour.truncated_recording PROPERTIES LABELS "cli;multiprocess" TIMEOUT 120
                     RESOURCE_LOCK plexus_dds_domain_149)
foreach(exe plexus plant_simulator localisation_observer motion_controller terrain_classifier icr_estimator
            attitude_filter joint_controller component_host serial_bridge udp_bridge device_emulator demo_node
            pingpong_node raw_fast_pingpong)
  add_test(NAME first_hour.version_${exe}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:${exe}>|--version" -DEXPECT_RC=0
                   "-DEXPECT_STDOUT=^${exe} [0-9]+\\.[0-9]+\\.[0-9]+\n$"
                   -P ${PROJECT_SOURCE_DIR}/common/scenario/tests/cli/expect_cli.cmake)
  set_tests_properties(first_hour.version_${exe} PROPERTIES LABELS "cli")
endforeach()
add_test(NAME first_hour.record_keeps_existing_file
         COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/record_keeps_file.sh $<TARGET_FILE:plexus> 149
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/record_keeps_file)
set_tests_properties(first_hour.record_keeps_existing_file PROPERTIES LABELS "cli;multiprocess" TIMEOUT 60
                     RESOURCE_LOCK plexus_dds_domain_149)
