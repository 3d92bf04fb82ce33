# The main job (README's first command, deploy/scenarios/four_robots.yaml), shortened: four
# robots and every service as separate processes over DDS; same digest as `plexus sim`, and
# the report compares every metric with the papers.
add_test(NAME main_job.four_robots
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/four_robots.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/four_robots.yaml ${CMAKE_BINARY_DIR}/test-runs/main_job 178)
set_tests_properties(main_job.four_robots PROPERTIES LABELS "lockstep;multiprocess;slow" TIMEOUT 300)
