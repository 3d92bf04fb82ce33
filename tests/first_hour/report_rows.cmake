# plexus report exits 1 on a FAIL row and lists a missing metric as a row (scripts/report_rows.cmake).
add_test(NAME first_hour.report_rows_and_exit_code
         COMMAND ${CMAKE_COMMAND} -DPLEXUS=$<TARGET_FILE:plexus>
                 -DSCENARIO=${PROJECT_SOURCE_DIR}/deploy/scenarios/unicycle_circle.yaml
                 -DOUT=${CMAKE_BINARY_DIR}/test-runs/first_hour/report_rows -DMETRIC=max_error_m
                 -P ${PROJECT_SOURCE_DIR}/tests/scripts/report_rows.cmake)
set_tests_properties(first_hour.report_rows_and_exit_code PROPERTIES LABELS "cli" TIMEOUT 120)
