# Paper 004 (flexible-joint arm, VDC + EKF) reproductions through `plexus sim`. Each run
# checks its scenario's own expectations (exit 1 when one fails); see the scenario headers
# and docs/algorithms/arm.md for the Table 4 targets met and missed.
foreach(scenario arm_vdc_ekf arm_ct_pd)
  add_test(NAME repro.${scenario}
           COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/${scenario}.yaml --quiet
                   --out ${CMAKE_BINARY_DIR}/test-runs/${scenario})
  set_tests_properties(repro.${scenario} PROPERTIES LABELS "repro" TIMEOUT 300)
endforeach()
