# A user's first hour (issue 19), YAML input: a duplicate key is an error naming the file,
# the line, the key and its first line (yaml-cpp silently kept the first); an oversized file
# is refused before parsing.
file(WRITE ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_seed.yaml
     "name: dup\nstep: 0.1\nduration: 1\nseed: 1\nseed: 2\n")
plexus_refusal_test(first_hour.duplicate_top_level_key LABELS cli
                    ERROR "^plexus sim: error: .*duplicate_seed.yaml:5: seed: duplicate key \\(first at line 4\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_seed.yaml
                            --quiet)
file(WRITE ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_x0.yaml
     "name: dup\nstep: 0.1\nduration: 1\nseed: 1\nrobots:\n  r1:\n    plant:\n      type: unicycle\n      x0: 0\n      x0: 9\n")
plexus_refusal_test(first_hour.duplicate_nested_key LABELS cli
                    ERROR "duplicate_x0.yaml:10: robots.r1.plant.x0: duplicate key \\(first at line 9\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_x0.yaml
                            --quiet)
file(WRITE ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_qos.yaml
     "profiles:\n  a:\n    reliability: reliable\n    reliability: best_effort\n")
plexus_refusal_test(first_hour.duplicate_qos_key LABELS cli
                    ERROR "duplicate_qos.yaml:4: profiles.a.reliability: duplicate key \\(first at line 3\\)"
                    COMMAND $<TARGET_FILE:plexus> qos
                            --qos-file ${CMAKE_BINARY_DIR}/test-runs/first_hour/duplicate_qos.yaml)
add_test(NAME first_hour.oversized_yaml
         COMMAND ${CMAKE_COMMAND} -DPLEXUS=$<TARGET_FILE:plexus> -DOUT=${CMAKE_BINARY_DIR}/test-runs/first_hour/big
                 -P ${PROJECT_SOURCE_DIR}/tests/scripts/big_yaml_rejected.cmake)
set_tests_properties(first_hour.oversized_yaml PROPERTIES LABELS "cli")
