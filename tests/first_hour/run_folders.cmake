# A user's first hour (issue 19), run folders and waits: unique run folders, --out reuse
# (an earlier run's folder emptied, a foreign folder refused), Ctrl-C on launch (exit 130,
# "interrupted", the folder marked so), and every wait bounded with a message: a service's
# start signal, a lockstep service with no clock, replay --lockstep with no clock. DDS
# domains 72-73.
add_test(NAME first_hour.run_folders
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/run_folders.sh $<TARGET_FILE:plexus> ${FH_SCENARIO}
                 ${CMAKE_BINARY_DIR}/test-runs/first_hour/run_folders 73)
add_test(NAME first_hour.waits_are_bounded
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/waits.sh $<TARGET_FILE_DIR:plexus> ${CMAKE_BINARY_DIR}/test-runs/first_hour/waits 72)
set_tests_properties(first_hour.run_folders first_hour.waits_are_bounded PROPERTIES LABELS "cli;multiprocess" TIMEOUT 180)
set_tests_properties(first_hour.waits_are_bounded PROPERTIES LABELS "cli;multiprocess;light")
set_tests_properties(first_hour.run_folders PROPERTIES RESOURCE_LOCK plexus_dds_domain_73)
set_tests_properties(first_hour.waits_are_bounded PROPERTIES RESOURCE_LOCK plexus_dds_domain_72)
