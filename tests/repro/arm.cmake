# Paper 004 (flexible-joint arm, VDC + EKF) reproductions through `plexus sim`. Each run
# checks its scenario's own expectations (exit 1 when one fails); see the scenario headers
# and docs/algorithms/arm.md for the Table 4 targets met and missed.
foreach(scenario arm_vdc_ekf arm_ct_pd arm_vdc_ekf_reference_sweep arm_vdc_ekf_payload arm_vdc_ekf_3dof)
  add_test(NAME repro.${scenario}
           COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/${scenario}.yaml --quiet
                   --out ${CMAKE_BINARY_DIR}/test-runs/${scenario})
  set_tests_properties(repro.${scenario} PROPERTIES LABELS "repro" TIMEOUT 300)
endforeach()

# The Table 4 run at 1 kHz, the distributed joint controller's rate: same expectations.
add_test(NAME repro.arm_vdc_ekf_1khz
         COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml --quiet --set step=0.001
                 --out ${CMAKE_BINARY_DIR}/test-runs/arm_vdc_ekf_1khz)
set_tests_properties(repro.arm_vdc_ekf_1khz PROPERTIES LABELS "repro" TIMEOUT 300)

# Bad arm parameters are input errors (exit 2) naming the file, line and key.
set(ARM_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml)
add_test(NAME cli.arm_gain_list_size
         COMMAND ${EXPECT} 2 "services.controller.k_p: needs 2 numbers \\(one per joint\\)"
                 $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.controller.k_p=[350])
add_test(NAME cli.arm_negative_gain
         COMMAND ${EXPECT} 2 "arm_vdc_ekf.yaml:[0-9]+: services.controller: vdc_controller: k_tau\\[1\\] must be finite and > 0 \\(got -1\\)"
                 $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.controller.k_tau=[0.5,-1])
add_test(NAME cli.arm_bad_link_mass
         COMMAND ${EXPECT} 2 "arm_vdc_ekf.yaml:[0-9]+: robots.arm.plant: arm_model: links\\[1\\].mass must be finite and > 0 \\(got 0\\)"
                 $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set robots.arm.plant.mass=[10,0])
add_test(NAME cli.arm_bad_jacobian
         COMMAND ${EXPECT} 2 "services.observer.jacobian: must be full or paper"
                 $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.observer.jacobian=exact)
add_test(NAME cli.arm_too_many_joints
         COMMAND ${EXPECT} 2 "robots.arm.plant.dof: must be in 1..16"
                 $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf_3dof.yaml --quiet
                 --set robots.arm.plant.dof=17)
add_test(NAME cli.arm_initial_velocity_list_size
         COMMAND ${EXPECT} 2 "robots.arm.plant.dq0: needs 2 numbers \\(one per joint\\)"
                 $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set robots.arm.plant.dq0=[1,1,1])
set_tests_properties(cli.arm_gain_list_size cli.arm_negative_gain cli.arm_bad_link_mass cli.arm_bad_jacobian
                     cli.arm_too_many_joints cli.arm_initial_velocity_list_size PROPERTIES LABELS "cli")
