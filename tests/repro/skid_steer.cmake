# Paper reproductions of the skid-steer family (paper 001) through `plexus sim`.
# The check is each scenario's own `expectations:` (exit 1 when one fails). Variants run the
# same scenarios with other terrains, ICRs, schedules, sensor rates and noise levels via
# --set; where a variant changes what the paper's figure means, its expectations are
# overridden on the command line with the reason next to it. Every run takes < 1 s.
# docs/algorithms/skid_steer.md has the measured figures and the targets missed.
set(SKID_SCENARIOS ${PROJECT_SOURCE_DIR}/deploy/scenarios)
set(SKID_RUNS ${CMAKE_BINARY_DIR}/test-runs/skid_steer)
set(SKID_TRAINING ${PROJECT_SOURCE_DIR}/deploy/training/icr_terrain_psd.txt)

# skid_repro(<test suffix> <scenario> [--set key=value ...])
function(skid_repro suffix scenario)
  add_test(NAME repro.${suffix}
           COMMAND $<TARGET_FILE:plexus> sim ${SKID_SCENARIOS}/${scenario}.yaml --quiet --out ${SKID_RUNS}/${suffix} ${ARGN})
  set_tests_properties(repro.${suffix} PROPERTIES LABELS "repro")
endfunction()

# ---- section 4.1, one terrain: rise time <= 0.5 s, final error <= 0.02 m, ICR odometry < 0.1 m
skid_repro(icr_single_terrain icr_single_terrain)
skid_repro(icr_single_terrain.tile icr_single_terrain --set "robots.r1.plant.schedule=[[0, tile]]")
skid_repro(icr_single_terrain.grass icr_single_terrain --set "robots.r1.plant.schedule=[[0, grass]]")
skid_repro(icr_single_terrain.wheel_noise icr_single_terrain --set robots.r1.sensors.wheels.noise_std=0.01)
skid_repro(icr_single_terrain.200Hz icr_single_terrain --set step=0.005 --set robots.r1.sensors.wheels.rate=200)
# Half the GPS rate and twice its noise: 8x less information per second, so a slower rise
# (measured 0.9 s); the accuracy targets stay.
skid_repro(icr_single_terrain.gps_10Hz_noisy icr_single_terrain --set robots.r1.sensors.gps.rate=10
           --set robots.r1.sensors.gps.position_std=0.02 --set robots.r1.sensors.gps.heading_std_deg=2
           --set "expectations.convergence_time_s='<= 2'")
# A user's terrain with other ICRs (x_G > 0, asymmetric tracks): measured rise 0.6 s.
skid_repro(icr_single_terrain.custom_icr icr_single_terrain
           --set "robots.r1.plant.terrains={sand: {y_l: 0.6, y_r: -0.45, x_G: 0.15, floor_rms: 0.2}}"
           --set "robots.r1.plant.schedule=[[0, sand]]" --set "expectations.convergence_time_s='<= 1'")
# Circles at 1 rad/s: the no-slip model errs mostly in turn rate, which a circle partly
# cancels in position, so its error is smaller than on the figure-eight; still >> ICR's.
skid_repro(icr_single_terrain.circle icr_single_terrain --set services.driver.pattern=circle
           --set services.driver.turn_rate=1.0 --set "expectations.odometry_error_noslip_m='>= 0.2'")

# ---- section 4.2, plain EKF: re-convergence > 100 s
skid_repro(icr_terrain_switch_ekf icr_terrain_switch_ekf)
skid_repro(icr_terrain_switch_ekf.second_switch_200s icr_terrain_switch_ekf
           --set "robots.r1.plant.schedule=[[0, concrete], [50, tile], [200, grass]]")

# ---- section 4.2, classifier + reset. Two known misses, kept at the paper's values (the
# scenario's comment and docs/algorithms/skid_steer.md give the measurements and reasons):
# reconvergence_time_s (measured 5.5 s vs <= 3: 2 s to confirm the new terrain in two 1 s
# windows, then 3.5 s until the estimates stay within 0.02 m) and odometry_ratio_akf_ekf
# (measured 7.25 vs < 1: on this slalom the heading error made before the reset is frozen,
# while the plain EKF's swings back). Exactly these two must fail (classifier accuracy and
# the ratio to no-slip hold), each within ~10 % of today's figure, with one reset per
# terrain switch (2): without the reset (services.ekf.adaptive_reset=false) the run gives
# 250 s and 1.0, and this pin fails.
plexus_pin(repro.icr_terrain_switch_akf ${SKID_SCENARIOS}/icr_terrain_switch_akf.yaml
           MISSES reconvergence_time_s odometry_ratio_akf_ekf
           CHECKS "reconvergence_time_s >= 5" "reconvergence_time_s <= 6"
                  "odometry_ratio_akf_ekf >= 6.5" "odometry_ratio_akf_ekf <= 8"
                  "classifier_accuracy >= 0.95" "resets == 2")
# ---- issue 16: the learned-prior reset (docs/algorithms/skid_steer.md "Prior reset"). The
# paper's run with reset_mode prior and overlapping windows: each switch re-converges within
# the paper's 3 s (measured 1.0 / 0.5 s), classifier >= 0.95, one reset per switch.
skid_repro(icr_terrain_switch_prior icr_terrain_switch_prior)
# Four switches, back to a terrain already seen (measured 0.75 / 1.25 s), GPS at 5 Hz, circles.
set(PRIOR_CHECK "expectations={reconvergence_time_s: '<= 3', classifier_accuracy: '>= 0.95'}")
skid_repro(icr_terrain_switch_prior.four_switches icr_terrain_switch_prior --set duration=160
           --set "robots.r1.plant.schedule=[[0, grass], [40, concrete], [80, tile], [120, grass]]"
           --set "expectations={reconvergence_time_s: '<= 3', classifier_accuracy: '>= 0.95', resets: '== 3'}")
skid_repro(icr_terrain_switch_prior.gps_5Hz icr_terrain_switch_prior --set robots.r1.sensors.gps.rate=5 --set "${PRIOR_CHECK}")
skid_repro(icr_terrain_switch_prior.gps_10Hz icr_terrain_switch_prior --set robots.r1.sensors.gps.rate=10 --set "${PRIOR_CHECK}")
# The paper's pattern under its proper name: a slalom (sinusoidal turn rate), the same run.
skid_repro(icr_terrain_switch_prior.slalom icr_terrain_switch_prior --set services.driver.pattern=slalom)
skid_repro(icr_terrain_switch_prior.circle icr_terrain_switch_prior --set services.driver.pattern=circle
           --set services.driver.turn_rate=0.5 --set "${PRIOR_CHECK}")
# A deliberately wrong library (tile and grass swapped: what a misclassified terrain gives):
# the paper's covariance reset, run beside the prior as a second hypothesis (each at its own
# most likely switch time, the paper's widening the ICR block), fits the GPS better and takes
# over: re-convergence 5.0 / 5.8 s (measured; the paper's reset with the same windows at the
# confirmation, icr_terrain_switch_akf.hop_0_25: 5.05 / 4.45 s); bounds: those + 0.01 s. The
# 3 s target is missed, as the paper's method misses it; so is the odometry ratio to the plain
# EKF (1.47: the wrong prior is published for the first second after each switch).
plexus_pin(repro.icr_terrain_switch_prior.mislabelled ${SKID_SCENARIOS}/icr_terrain_switch_prior.yaml
           MISSES odometry_ratio_akf_ekf reconvergence_time_switch1_s reconvergence_time_switch2_s
           CHECKS "reconvergence_time_switch1_s <= 5.01" "reconvergence_time_switch2_s <= 5.81" "resets == 2"
                  "odometry_ratio_akf_ekf <= 1.48"
           ARGS --set services.ekf.icr_library=${PROJECT_SOURCE_DIR}/tests/data/icr_terrain_library_swapped.txt)
# A user's terrains: the paper's vibration signatures with other ICRs, their own library
# recorded first, then the switching run with it (measured 1.0 / 0.5 s).
add_test(NAME repro.icr_terrain_switch_prior.custom_icr
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/scripts/prior_custom_icr.sh $<TARGET_FILE:plexus> ${SKID_SCENARIOS}
                 ${SKID_RUNS}/prior_custom_icr)
set_tests_properties(repro.icr_terrain_switch_prior.custom_icr PROPERTIES LABELS "repro")
# Issue 29: a generated family of terrain sets unlike the paper's (ICR spreads 0.3-0.5 m,
# 3-5 terrains, 4-6 switches, GPS 5/10/20 Hz, 30 seeds; the user's workflow per set: record
# the training windows, learn the library, drive the switching run); every switch within 3 s
# (docs/algorithms/skid_steer.md "Other terrain sets"; measured: all 150 switches 0.5-1.25 s;
# ~15 s in all).
add_test(NAME repro.icr_terrain_switch_prior.terrain_family
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/scripts/prior_terrain_family.sh $<TARGET_FILE:plexus> ${SKID_SCENARIOS}
                 ${SKID_RUNS}/prior_terrain_family 1 30)
set_tests_properties(repro.icr_terrain_switch_prior.terrain_family PROPERTIES LABELS "repro")
# The same with the paper's 1 s windows: 5.0 / 3.3 s (measured; the covariance reset with
# them: 5.5 / 4.5 s).
plexus_pin(repro.icr_terrain_switch_prior.mislabelled_1s_windows ${SKID_SCENARIOS}/icr_terrain_switch_prior.yaml
           MISSES reconvergence_time_switch1_s reconvergence_time_switch2_s
           CHECKS "reconvergence_time_switch1_s <= 5.01" "reconvergence_time_switch2_s <= 3.31" "resets == 2"
           ARGS --set services.classifier.hop_s=1.0
                --set services.ekf.icr_library=${PROJECT_SOURCE_DIR}/tests/data/icr_terrain_library_swapped.txt)
# The library is learned by a recorded run (deploy/training/icr_terrain_library.txt).
skid_repro(icr_record_library icr_record_library --set services.library.output=${SKID_RUNS}/icr_terrain_library.txt)

# Variants: the classifier stays >= 95 % accurate, the reset fires exactly once per switch,
# and re-convergence stays an order of magnitude below the plain EKF's (> 100 s).
set(AKF_CHECK "expectations={classifier_accuracy: '>= 0.95', reconvergence_time_s: '< 10'}")
skid_repro(icr_terrain_switch_akf.second_switch_200s icr_terrain_switch_akf
           --set "robots.r1.plant.schedule=[[0, concrete], [50, tile], [200, grass]]" --set "${AKF_CHECK}")
skid_repro(icr_terrain_switch_akf.four_switches icr_terrain_switch_akf --set duration=160
           --set "robots.r1.plant.schedule=[[0, grass], [40, concrete], [80, tile], [120, grass]]"
           --set "expectations={classifier_accuracy: '>= 0.95', reconvergence_time_s: '< 10', resets: '== 3'}")
skid_repro(icr_terrain_switch_akf.noisy_sensors icr_terrain_switch_akf --set robots.r1.sensors.imu.noise_std=0.1
           --set robots.r1.sensors.wheels.noise_std=0.01 --set "${AKF_CHECK}")
skid_repro(icr_terrain_switch_akf.k1_unscaled icr_terrain_switch_akf --set services.classifier.k=1
           --set services.classifier.scaling=none --set "${AKF_CHECK}")
# Circles (1 s^-1 commanded turn rate): the turn rate no longer averages out, so the plain
# EKF's biased ICRs accumulate heading error and the paper's Fig. 7 ordering holds (measured
# AKF 0.52 m, EKF 2.8 m, no-slip 2.5 m); re-convergence 8.8 s (less excitation than the slalom).
skid_repro(icr_terrain_switch_akf.circle icr_terrain_switch_akf --set services.driver.pattern=circle
           --set services.driver.turn_rate=0.5
           --set "expectations={classifier_accuracy: '>= 0.95', reconvergence_time_s: '< 10', odometry_ratio_akf_ekf: '< 1', odometry_ratio_akf_noslip: '< 0.5'}")
# Overlapping classifier windows (hop 0.25 s; the paper does not give the hop): the change is
# confirmed after 1.0 s (B) and 0.5 s (C) instead of 2.0 s, re-convergence 5.05 s (measured).
skid_repro(icr_terrain_switch_akf.hop_0_25 icr_terrain_switch_akf --set services.classifier.hop_s=0.25
           --set "${AKF_CHECK}")
skid_repro(icr_terrain_switch_akf.k7_shrink_minmax icr_terrain_switch_akf --set services.classifier.k=7
           --set services.classifier.tie_rule=shrink_k --set services.classifier.scaling=min_max --set "${AKF_CHECK}")

# ---- training data: re-recording reproduces the committed file byte for byte
skid_repro(icr_record_training icr_record_training --set services.recorder.output=${SKID_RUNS}/icr_terrain_psd.txt)
add_test(NAME repro.icr_record_training.matches_committed
         COMMAND ${CMAKE_COMMAND} -E compare_files ${SKID_RUNS}/icr_terrain_psd.txt ${SKID_TRAINING})
set_tests_properties(repro.icr_record_training PROPERTIES LABELS "repro" FIXTURES_SETUP skid_training)
set_tests_properties(repro.icr_record_training.matches_committed PROPERTIES LABELS "repro" FIXTURES_REQUIRED skid_training)

# ---- a user's own terrains: four classes with other ICRs and spectra, recorded, then used
set(FOUR_TERRAINS "robots.r1.plant.terrains={\
sand: {y_l: 0.6, y_r: -0.45, x_G: 0.15, floor_rms: 0.3, resonances: [[3, 0.5, 0.6]]},\
gravel: {y_l: 0.35, y_r: -0.4, x_G: 0.0, floor_rms: 0.4, resonances: [[28, 0.2, 0.8], [42, 0.1, 0.3]]},\
carpet: {y_l: 0.25, y_r: -0.3, x_G: -0.05, floor_rms: 0.02, resonances: [[15, 0.3, 0.2]]},\
mud: {y_l: 0.8, y_r: -0.9, x_G: 0.3, floor_rms: 0.1, resonances: [[6, 0.1, 0.5], [20, 0.3, 0.2]]}}")
skid_repro(icr_record_training.four_terrains icr_record_training --set "${FOUR_TERRAINS}" --set duration=80
           --set "robots.r1.plant.schedule=[[0, sand], [20, gravel], [40, carpet], [60, mud]]"
           --set "services.recorder.class_names=[sand, gravel, carpet, mud]"
           --set services.recorder.output=${SKID_RUNS}/four_terrains.txt --set "expectations.windows_written='== 60'")
skid_repro(icr_terrain_switch_akf.four_terrains icr_terrain_switch_akf --set "${FOUR_TERRAINS}" --set duration=200
           --set "robots.r1.plant.schedule=[[0, gravel], [50, mud], [100, carpet], [150, sand]]"
           --set services.classifier.training_file=${SKID_RUNS}/four_terrains.txt
           --set "expectations={classifier_accuracy: '>= 0.95', reconvergence_time_s: '< 20', resets: '== 3'}")
# (< 20 s here: the mud -> carpet switch moves y_r by 0.6 m and takes 11.7 s, measured; the
# other two switches take ~6 s. Still far below the plain EKF's > 100 s.)
set_tests_properties(repro.icr_record_training.four_terrains PROPERTIES FIXTURES_SETUP skid_four_terrains)
set_tests_properties(repro.icr_terrain_switch_akf.four_terrains PROPERTIES FIXTURES_REQUIRED skid_four_terrains)

# ---- bad inputs are exit 2 with file and line: a broken training file, a mismatched one, a bad key
file(WRITE ${SKID_RUNS}/bad_training.txt "plexus-terrain-training 1\nsample_rate_hz 100\nwindow_samples 100\nfeatures fifty\n")
function(skid_bad_input suffix regex)
  add_test(NAME cli.${suffix}
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=$<TARGET_FILE:plexus>|sim|${SKID_SCENARIOS}/icr_terrain_switch_akf.yaml|--quiet|--out|${SKID_RUNS}/${suffix}|${ARGN}"
                   -DEXPECT_RC=2 "-DEXPECT_STDERR=${regex}" -P ${PROJECT_SOURCE_DIR}/common/scenario/tests/cli/expect_cli.cmake)
  set_tests_properties(cli.${suffix} PROPERTIES LABELS "cli")
endfunction()
skid_bad_input(icr_bad_training_file
               "icr_terrain_switch_akf.yaml[^\n]*: services.classifier.training_file: [^\n]*bad_training.txt:4: features: expected an integer, got 'fifty'"
               --set services.classifier.training_file=${SKID_RUNS}/bad_training.txt)
skid_bad_input(icr_training_layout_mismatch
               "services.classifier.training_file: [^\n]*icr_terrain_psd.txt: its features were computed differently from this classifier's \\(band_hz 1 50 vs 1 40"
               --set services.classifier.max_hz=40)
skid_bad_input(icr_missing_training_file "services.classifier.training_file: [^\n]*nope.txt:0: cannot open the training file"
               --set services.classifier.training_file=nope.txt)
skid_bad_input(icr_bad_k "services.classifier.k: knn_classifier: k must be in 1..45 \\(the training samples\\) \\(got 46\\)"
               --set services.classifier.k=46)
skid_bad_input(icr_bad_schedule "robots.r1.plant.schedule: unknown terrain 'ice'" "--set|robots.r1.plant.schedule=[[0, ice]]")
skid_bad_input(icr_bad_q "services.ekf: icr_ekf: q_diag\\[3\\] must be finite and >= 0 \\(got -1\\)"
               "--set|services.ekf.q_diag=[1, 1, 1, -1, 1, 1]")
