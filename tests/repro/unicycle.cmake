# Paper reproductions of the unicycle family (papers 000 and 003) through `plexus sim`.
# The check is each scenario's own `expectations:` (exit 1 when one fails); the variants
# run the same scenario with other parameters via --set and must converge too, with
# expectations that mean something for them (overridden with --set where they differ).
# Every run takes well under a second (docs/algorithms/unicycle.md has the figures).
set(UNICYCLE_SCENARIOS ${PROJECT_SOURCE_DIR}/deploy/scenarios)
set(UNICYCLE_RUNS ${CMAKE_BINARY_DIR}/test-runs/unicycle)

# unicycle_repro(<test suffix> <scenario> [--set key=value ...])
function(unicycle_repro suffix scenario)
  add_test(NAME repro.${suffix}
           COMMAND $<TARGET_FILE:plexus> sim ${UNICYCLE_SCENARIOS}/${scenario}.yaml --quiet
                   --out ${UNICYCLE_RUNS}/${suffix} ${ARGN})
  set_tests_properties(repro.${suffix} PROPERTIES LABELS "repro")
endfunction()

# ---- paper 000 section 6.1: heading observer alone; expectation observer_decay_ratio >= 1
unicycle_repro(wmr_observer wmr_observer)
unicycle_repro(wmr_observer.theta0_0_L3 wmr_observer --set robots.r1.plant.theta0=0 --set services.observer.L=3)
unicycle_repro(wmr_observer.eight_2m_fast_L0.5 wmr_observer --set services.reference.h1=2
               --set services.reference.h2=0.1 --set services.observer.L=0.5 --set robots.r1.plant.theta0=-2)

# ---- paper 000 section 6.2: state feedback; expectation final_error_m <= 1e-3
unicycle_repro(wmr_state_feedback wmr_state_feedback)
unicycle_repro(wmr_state_feedback.theta0_1.5 wmr_state_feedback --set robots.r1.plant.theta0=1.5)
unicycle_repro(wmr_state_feedback.theta0_pi wmr_state_feedback --set robots.r1.plant.theta0=3.14159265)
unicycle_repro(wmr_state_feedback.eight_3m_fast wmr_state_feedback --set services.reference.h1=3
               --set services.reference.h2=0.05)
unicycle_repro(wmr_state_feedback.eight_10m_slow wmr_state_feedback --set services.reference.h1=10
               --set services.reference.h2=0.01 --set robots.r1.plant.theta0=-1)
# A 10x faster reference (up to 2.2 m/s): the zero-order-hold residual at 100 Hz is 3e-3 m,
# so this variant runs at 1 kHz (residual 3e-4 m).
unicycle_repro(wmr_state_feedback.eight_fast_1kHz wmr_state_feedback --set services.reference.h2=0.2 --set step=0.001)
# Gains that satisfy condition (15) (|k| = 0.035 < 0.0399): slower, so 400 s.
unicycle_repro(wmr_state_feedback.gains_within_15 wmr_state_feedback --set services.controller.k1=0.025
               --set services.controller.k2=0.025 --set duration=400 --set robots.r1.plant.theta0=3)
set_tests_properties(repro.wmr_state_feedback.gains_within_15 PROPERTIES FAIL_REGULAR_EXPRESSION "gain condition")

# The paper's gains violate condition (15) for its reference: one warning, with the numbers.
add_test(NAME repro.wmr_gain_condition_warning
         COMMAND ${CMAKE_COMMAND}
                 "-DCOMMAND=$<TARGET_FILE:plexus>|sim|${UNICYCLE_SCENARIOS}/wmr_state_feedback.yaml|--quiet|--out|${UNICYCLE_RUNS}/gain_warning"
                 -DEXPECT_RC=0
                 "-DEXPECT_STDERR=^[^\n]*warning \\[scenario\\] controller: gain condition \\(15\\) of paper 000 not met against reference r1/reference \\(details: [^\n]*gain_warning/summary.md\\)\n$"
                 -P ${PROJECT_SOURCE_DIR}/common/scenario/tests/cli/expect_cli.cmake)
# The console gets that one short line; the run folder's summary.md the numbers.
add_test(NAME repro.wmr_gain_condition_details
         COMMAND grep -q "gain condition (15) of paper 000 violated: k1^2 + k2^2 = 0.0242 (k1 = 0.11, k2 = 0.11).*v_rm = 0.0695.*15.2[0-9]*x over"
                 ${UNICYCLE_RUNS}/gain_warning/summary.md)
set_tests_properties(repro.wmr_gain_condition_warning PROPERTIES LABELS "repro" FIXTURES_SETUP gain_warning_run)
set_tests_properties(repro.wmr_gain_condition_details PROPERTIES LABELS "repro" FIXTURES_REQUIRED gain_warning_run)
# ... and the check follows the controller's reference_min_speed (its own parameter: the
# reference runs in another process): the reference 10x faster, v_rm = 0.696 m/s, no warning.
unicycle_repro(wmr_gain_condition_follows_reference wmr_state_feedback --set services.reference.h2=0.2
               --set services.controller.reference_min_speed=0.696 --set step=0.001)
set_tests_properties(repro.wmr_gain_condition_follows_reference PROPERTIES FAIL_REGULAR_EXPRESSION "gain condition")

# ---- paper 000 section 6.3.1: output feedback, exact positions; final_error_m <= 1e-3
unicycle_repro(wmr_output_feedback wmr_output_feedback)
unicycle_repro(wmr_output_feedback.theta0_1.5 wmr_output_feedback --set robots.r1.plant.theta0=1.5)
unicycle_repro(wmr_output_feedback.theta0_-2_L1 wmr_output_feedback --set robots.r1.plant.theta0=-2
               --set services.observer.L=1)
unicycle_repro(wmr_output_feedback.eight_3m_fast wmr_output_feedback --set services.reference.h1=3
               --set services.reference.h2=0.05)

# ---- paper 000 section 6.3.2: RFID grid; published max 0.05 m, mean 0.01 m after 100 s
unicycle_repro(wmr_output_feedback_rfid wmr_output_feedback_rfid)
unicycle_repro(wmr_output_feedback_rfid.theta0_1.5 wmr_output_feedback_rfid --set robots.r1.plant.theta0=1.5)
unicycle_repro(wmr_output_feedback_rfid.eight_8m wmr_output_feedback_rfid --set services.reference.h1=8
               --set services.reference.h2=0.015)
unicycle_repro(wmr_output_feedback_rfid.eight_3m wmr_output_feedback_rfid --set services.reference.h1=3
               --set services.reference.h2=0.03)
unicycle_repro(wmr_output_feedback_rfid.sensor_20Hz wmr_output_feedback_rfid
               --set robots.r1.sensors.position.rate=20)
# Other grids: the published bounds scaled to the grid s (mean <= s / 10 as published for
# s = 0.1; max <= s / sqrt(2), half a cell diagonal, the largest error of one reading).
unicycle_repro(wmr_output_feedback_rfid.grid_0.05 wmr_output_feedback_rfid
               --set robots.r1.sensors.position.grid_spacing=0.05
               "--set" "expectations.steady_max_error_m=<= 0.0354" "--set" "expectations.steady_mean_error_m=<= 0.005")
unicycle_repro(wmr_output_feedback_rfid.grid_0.2 wmr_output_feedback_rfid
               --set robots.r1.sensors.position.grid_spacing=0.2
               "--set" "expectations.steady_max_error_m=<= 0.1414" "--set" "expectations.steady_mean_error_m=<= 0.02")

# ---- paper 003 section 5: observer-based path following; |h|, |(e2, e4)| -> 0
unicycle_repro(path_following_circle path_following_circle)
unicycle_repro(path_following_circle.radius_2_outside path_following_circle --set services.path.radius=2
               --set robots.r1.plant.x0=2.3)
unicycle_repro(path_following_circle.radius_2_inside path_following_circle --set services.path.radius=2)
unicycle_repro(path_following_circle.u1_0.5_offset path_following_circle --set services.controller.u1=0.5
               --set services.path.center_x=0.5 --set services.path.center_y=-0.3)
unicycle_repro(path_following_circle.state_feedback path_following_circle --set services.controller.feedback=state)
# Another shape (variant file): a rotated ellipse; with u2 held over a step, h settles to an
# O(step) residual, so at 1 kHz the bound is 10x tighter.
unicycle_repro(path_following_ellipse path_following_ellipse)
unicycle_repro(path_following_ellipse.state_feedback path_following_ellipse --set services.controller.feedback=state)
unicycle_repro(path_following_ellipse.1kHz path_following_ellipse --set step=0.001
               "--set" "expectations.final_path_error=<= 1e-3")

# ---- bad configuration is exit 2 with the file, the section and the parameter
function(unicycle_bad_config name scenario stderr)
  list(JOIN ARGN "|" sets)
  add_test(NAME unicycle_cli.${name}
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=$<TARGET_FILE:plexus>|sim|${UNICYCLE_SCENARIOS}/${scenario}.yaml|--quiet|--out|${UNICYCLE_RUNS}/bad|${sets}"
                   -DEXPECT_RC=2 "-DEXPECT_STDERR=${stderr}"
                   -P ${PROJECT_SOURCE_DIR}/common/scenario/tests/cli/expect_cli.cmake)
  set_tests_properties(unicycle_cli.${name} PROPERTIES LABELS "cli")
endfunction()
unicycle_bad_config(observer_gain wmr_observer "wmr_observer.yaml: --set services.observer.L=-1: services.observer.L: heading_observer: L must be finite and > 0 \\(got -1\\)"
                    --set services.observer.L=-1)
unicycle_bad_config(sensor_kind wmr_output_feedback_rfid "robots.r1.sensors.position.kind: expected exact, gaussian or rfid_grid, got 'laser'"
                    --set robots.r1.sensors.position.kind=laser)
unicycle_bad_config(sensor_key_of_other_kind wmr_output_feedback "robots.r1.sensors.position.grid_spacing: unknown key"
                    --set robots.r1.sensors.position.grid_spacing=0.1)
unicycle_bad_config(feedback wmr_state_feedback "services.controller.feedback: expected state or output, got 'magic'"
                    --set services.controller.feedback=magic)
unicycle_bad_config(path_shape path_following_circle "services.path.shape: expected circle, line, ellipse or polynomial, got 'square'"
                    --set services.path.shape=square)
unicycle_bad_config(path_speed path_following_circle "services.controller.u1: must be finite and != 0 m/s"
                    --set services.controller.u1=0)
