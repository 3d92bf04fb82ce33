# Paper 002 (two-wheeled balancing robot, UKF vs EKF attitude filters) reproductions
# through `plexus sim`. Each run checks its scenario's own expectations (paper figures:
# |UKF mean| <= 0.021 deg, UKF std <= 0.24 deg, robot upright; the saturation variant
# also UKF std < EKF std). docs/algorithms/balancing.md lists what is met and missed.
set(BAL_SCENARIO ${PROJECT_SOURCE_DIR}/deploy/scenarios/balance_ukf_ekf.yaml)
foreach(scenario balance_ukf_ekf balance_ukf_ekf_gyro_saturation)
  add_test(NAME repro.${scenario}
           COMMAND $<TARGET_FILE:plexus> sim ${PROJECT_SOURCE_DIR}/deploy/scenarios/${scenario}.yaml --quiet
                   --out ${CMAKE_BINARY_DIR}/test-runs/${scenario})
  set_tests_properties(repro.${scenario} PROPERTIES LABELS "repro" TIMEOUT 120)
endforeach()

# The claims that depend on the noise, as statistics over 30 seeds (2006..2035; `plexus sim
# --seeds`, about 0.3 s each): the paper's |mean error| <= 0.021 deg holds on average (one
# run's ranges 0.0001-0.038 deg), the run stays upright on every seed, and with the
# saturating gyro the UKF's error std is lower than the EKF's, significantly: Student's t
# of the per-seed differences <= -2.045, the two-sided 95 % critical value for 29 degrees of
# freedom (measured -6.8; mean -6.2e-4 deg; 4 of the 30 seeds go the other way).
add_test(NAME repro.balance_ukf_ekf.seeds30
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:plexus>|sim|${BAL_SCENARIO}|--seeds|30|--json|--quiet|--out|${CMAKE_BINARY_DIR}/test-runs/balance_ukf_ekf.seeds30"
                 -DMISSES=none
                 "-DCHECKS=ukf_error_abs_mean_deg.mean <= 0.021;ukf_error_std_deg.max <= 0.24;max_abs_tilt_deg.max <= 15"
                 -P ${PROJECT_SOURCE_DIR}/tests/scripts/json_checks.cmake)
add_test(NAME repro.balance_ukf_ekf_gyro_saturation.seeds30
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:plexus>|sim|${PROJECT_SOURCE_DIR}/deploy/scenarios/balance_ukf_ekf_gyro_saturation.yaml|--seeds|30|--json|--quiet|--out|${CMAKE_BINARY_DIR}/test-runs/balance_ukf_ekf_gyro_saturation.seeds30"
                 -DMISSES=none
                 "-DCHECKS=ukf_minus_ekf_error_std_deg.mean < 0;ukf_minus_ekf_error_std_deg.t <= -2.045;ukf_error_abs_mean_deg.mean <= 0.021;max_abs_tilt_deg.max <= 20"
                 -P ${PROJECT_SOURCE_DIR}/tests/scripts/json_checks.cmake)
set_tests_properties(repro.balance_ukf_ekf.seeds30 repro.balance_ukf_ekf_gyro_saturation.seeds30 PROPERTIES
                     LABELS "repro" TIMEOUT 120)

# The same experiment under other noise levels, rates and parameter sets (--set).
function(balance_variant name)
  add_test(NAME repro.balance_ukf_ekf.${name}
           COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet ${ARGN}
                   --out ${CMAKE_BINARY_DIR}/test-runs/balance_ukf_ekf.${name})
  set_tests_properties(repro.balance_ukf_ekf.${name} PROPERTIES LABELS "repro" TIMEOUT 120)
endfunction()
set(BAL_LINEAR_MODEL "")
foreach(f ukf ukf_additive ekf paper_ukf paper_ukf_additive paper_ekf)
  list(APPEND BAL_LINEAR_MODEL --set services.${f}.process_model=linear)
endforeach()
balance_variant(linear_model ${BAL_LINEAR_MODEL})  # the paper's Table 2 "linear model" row
balance_variant(rate_200hz --set step=0.005 --set robots.r1.sensors.imu.rate=200)
balance_variant(imu_50hz --set robots.r1.sensors.imu.rate=50)
balance_variant(noisier_sensors --set robots.r1.sensors.imu.gyro_noise_degps=1.0
                --set robots.r1.sensors.imu.accel_noise=0.05)
# Another robot: the filters and the controller carry the robot's model as their own
# parameters (a service runs alone), so the variant sets it on each of them as on the plant.
set(BAL_HEAVIER --set robots.r1.plant.body_mass=6 --set robots.r1.plant.com_height=0.25
                --set robots.r1.plant.body_inertia=0.1 --set robots.r1.sensors.imu.accel_height=0.25)
foreach(f ukf ukf_additive ekf paper_ukf paper_ukf_additive paper_ekf balance)
  list(APPEND BAL_HEAVIER --set services.${f}.body_mass=6 --set services.${f}.com_height=0.25
                          --set services.${f}.body_inertia=0.1)
endforeach()
foreach(f ukf ukf_additive ekf paper_ukf paper_ukf_additive paper_ekf)
  list(APPEND BAL_HEAVIER --set services.${f}.accel_height=0.25)
endforeach()
balance_variant(heavier_taller_robot ${BAL_HEAVIER})
balance_variant(small_alpha --set services.ukf.alpha=0.1 --set services.ukf_additive.alpha=0.1)

# Bad balancing parameters are input errors (exit 2) naming the file, line and key.
plexus_refusal_test(cli.balance_unknown_filter LABELS cli
                    ERROR "services.ukf.filter: expected one of ukf_augmented, ukf_additive, ekf, got 'kalman'"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet --set services.ukf.filter=kalman)
plexus_refusal_test(cli.balance_bad_noise LABELS cli
                    ERROR "services.ukf.r_tilt_deg: must be finite and > 0"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet --set services.ukf.r_tilt_deg=0)
plexus_refusal_test(cli.balance_bad_plant LABELS cli
                    ERROR "balance_ukf_ekf.yaml: --set robots.r1.plant.body_mass=-1: robots.r1.plant.body_mass: wheeled_inverted_pendulum: body_mass must be finite and > 0 \\(got -1\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet --set robots.r1.plant.body_mass=-1)
plexus_refusal_test(cli.balance_bad_poles LABELS cli
                    ERROR "balancing_controller: poles\\[3\\] must be distinct from the others \\(got -3\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet
                            --set services.balance.poles=[-1,-2,-3,-3])
plexus_refusal_test(cli.balance_bad_sigma LABELS cli
                    ERROR "--set services.ukf.alpha=0: services.ukf.alpha: augmented_ukf: alpha must be finite and > 0 \\(got 0\\)"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet --set services.ukf.alpha=0)
plexus_refusal_test(cli.balance_bad_stat LABELS cli
                    ERROR "metrics.0.stat: expected mean, abs_mean, std"
                    COMMAND $<TARGET_FILE:plexus> sim ${BAL_SCENARIO} --quiet --set metrics.0.stat=median)
