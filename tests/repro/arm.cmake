# Paper 004 (flexible-joint arm, VDC + EKF) reproductions through `plexus sim`. Each run
# checks its scenario's own expectations (exit 1 when one fails); see the scenario headers
# and docs/algorithms/arm.md for the Table 4 targets met and missed.
foreach(scenario arm_ct_pd arm_vdc_ekf_reference_sweep arm_vdc_ekf_payload arm_vdc_ekf_3dof arm_table4)
  add_test(NAME repro.${scenario}
           COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/${scenario}.yaml --quiet
                   --out ${CMAKE_BINARY_DIR}/test-runs/${scenario})
  set_tests_properties(repro.${scenario} PROPERTIES LABELS "repro" TIMEOUT 300)
endforeach()

# Table 4, VDC+EKF: the settling times are met (the scenario's expectations); the RMS and
# peak-torque targets are missed for the reasons in arm_vdc_ekf.yaml (the 14 mrad initial
# error over T = 5 s; (18)-(20) at t = 0). Those misses are bounded here within ~10 % of
# today's figures (5 kHz: RMS 1.286 / 1.129 / 1.711 mrad, peaks 452 / 163 N m; 1 kHz, the
# distributed controller's rate: 1.290 / 1.139 / 1.721 mrad, 590 / 164 N m), and so is the
# error after the transient (0.03 mrad, 30 / 8.5 N m), so that none can get worse unnoticed.
set(ARM_TABLE4_STEADY "rms_e1_steady_mrad <= 0.04" "rms_e2_steady_mrad <= 0.04"
                      "max_torque_1_steady_nm <= 33" "max_torque_2_steady_nm <= 9.4")
plexus_pin(repro.arm_vdc_ekf ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml MISSES none
           CHECKS "rms_e1_mrad >= 1.16" "rms_e1_mrad <= 1.42" "rms_e2_mrad >= 1.02" "rms_e2_mrad <= 1.25"
                  "rms_norm_mrad >= 1.54" "rms_norm_mrad <= 1.89"
                  "max_torque_1_nm >= 405" "max_torque_1_nm <= 500" "max_torque_2_nm >= 146" "max_torque_2_nm <= 180"
                  ${ARM_TABLE4_STEADY})
plexus_pin(repro.arm_vdc_ekf_1khz ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml MISSES none ARGS --set step=0.001
           CHECKS "rms_e1_mrad >= 1.16" "rms_e1_mrad <= 1.42" "rms_e2_mrad >= 1.02" "rms_e2_mrad <= 1.26"
                  "rms_norm_mrad >= 1.55" "rms_norm_mrad <= 1.9"
                  "max_torque_1_nm >= 530" "max_torque_1_nm <= 650" "max_torque_2_nm >= 147" "max_torque_2_nm <= 180"
                  ${ARM_TABLE4_STEADY})

# Bad arm parameters are input errors (exit 2) naming the file, line and key.
set(ARM_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml)
plexus_refusal_test(cli.arm_gain_list_size LABELS cli
                    ERROR "services.controller.k_p: needs 2 numbers \\(one per joint\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.controller.k_p=[350])
plexus_refusal_test(cli.arm_negative_gain LABELS cli
                    ERROR "arm_vdc_ekf.yaml:[0-9]+: services.controller: vdc_controller: k_tau\\[1\\] must be finite and > 0 \\(got -1\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.controller.k_tau=[0.5,-1])
plexus_refusal_test(cli.arm_bad_link_mass LABELS cli
                    ERROR "arm_vdc_ekf.yaml:[0-9]+: robots.arm.plant: arm_model: links\\[1\\].mass must be finite and > 0 \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set robots.arm.plant.mass=[10,0])
plexus_refusal_test(cli.arm_bad_jacobian LABELS cli
                    ERROR "services.observer.jacobian: expected one of full, paper, got 'exact'"
                    COMMAND $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set services.observer.jacobian=exact)
plexus_refusal_test(cli.arm_too_many_joints LABELS cli
                    ERROR "robots.arm.plant.dof: must be in 1..16"
                    COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf_3dof.yaml
                            --quiet --set robots.arm.plant.dof=17)
plexus_refusal_test(cli.arm_initial_velocity_list_size LABELS cli
                    ERROR "robots.arm.plant.dq0: needs 2 numbers \\(one per joint\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${ARM_SCENARIO} --quiet --set robots.arm.plant.dq0=[1,1,1])

# issue 29: table4_fit, the tool that fits Table 4's unstated set-up, runs the scenario runner's
# closed loop (its arm_table4 set-up gives plexus sim's figures) and refuses a bad argument.
add_test(NAME tools.table4_fit_matches_sim
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/table4_fit_check.sh $<TARGET_FILE:table4_fit> $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_table4.yaml ${CMAKE_BINARY_DIR}/test-runs/table4_fit)
set_tests_properties(tools.table4_fit_matches_sim PROPERTIES LABELS "unit")
