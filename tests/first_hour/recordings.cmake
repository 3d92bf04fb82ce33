# A user's first hour (issue 19), recordings: a truncated one is refused on open; every
# program in build/bin, the ones a user runs, has --version (tests/first_hour/programs.sh; the
# test programs are in build/bin/tests).
add_test(NAME first_hour.truncated_recording
         COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/truncated_recording.sh $<TARGET_FILE:plexus> 149
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/truncated_recording)
set_tests_properties(first_hour.truncated_recording PROPERTIES LABELS "cli;multiprocess" TIMEOUT 120
                     RESOURCE_LOCK plexus_dds_domain_149)
add_test(NAME first_hour.programs_have_version
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/programs.sh ${CMAKE_BINARY_DIR}/bin)
set_tests_properties(first_hour.programs_have_version PROPERTIES LABELS "cli")
add_test(NAME first_hour.record_keeps_existing_file
         COMMAND ${PROJECT_SOURCE_DIR}/tests/scripts/record_keeps_file.sh $<TARGET_FILE:plexus> 149
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/record_keeps_file)
set_tests_properties(first_hour.record_keeps_existing_file PROPERTIES LABELS "cli;multiprocess" TIMEOUT 60
                     RESOURCE_LOCK plexus_dds_domain_149)
