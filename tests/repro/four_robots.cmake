# The main job (README's first command, deploy/scenarios/four_robots.yaml): four robots and
# every service as separate processes over DDS. The full 120 s run on Cyclone DDS (about
# 1 min; Fast DDS takes 1.5 min): same digest as `plexus sim`, the report compares every
# metric with the papers, and exactly the known misses fail, each bounded. The same job
# shortened to 6 s on Fast DDS: same digest and exit code as `plexus sim`.
add_test(NAME main_job.four_robots
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/four_robots.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/four_robots.yaml ${CMAKE_BINARY_DIR}/test-runs/main_job 178 cyclone)
add_test(NAME main_job.four_robots_fast_6s
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/four_robots.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/four_robots.yaml ${CMAKE_BINARY_DIR}/test-runs/main_job_fast_6s 177 fast --short)
set_tests_properties(main_job.four_robots main_job.four_robots_fast_6s PROPERTIES LABELS "lockstep;multiprocess;slow" TIMEOUT 600)
