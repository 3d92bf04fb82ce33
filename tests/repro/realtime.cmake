# Paper targets in realtime (issue 8): `plexus launch` on wall-clock loops, every service its
# own process. The unicycle RFID case (paper 000 section 6.3.2): the published steady-state
# maximum (0.05 m after 100 s) is kept; the mean bound is looser in realtime, 0.02 m instead
# of 0.01 m, because the processes' 100 Hz loops run at unrelated phases, so the command
# reaches the plant 0 to 2 periods after the measurement instead of exactly one (measured:
# mean 3.4 mm with 0.6 ms sensor-to-command latency, 9.2 mm with 8.9 ms; lockstep: 0.7 mm;
# docs/distributed.md). The run is shortened from 480 s to 101 s (the bounds' window starts
# at 100 s). RUN_SERIAL: a realtime run shares the machine with nothing else in the suite.
add_test(NAME repro.realtime.wmr_output_feedback_rfid
         COMMAND $<TARGET_FILE:plexus> launch ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml
                 --set clock.mode=realtime --set duration=101 --quiet --domain 179
                 "--set" "expectations.steady_mean_error_m=<= 0.02"
                 --out ${CMAKE_BINARY_DIR}/test-runs/realtime/wmr_output_feedback_rfid)
set_tests_properties(repro.realtime.wmr_output_feedback_rfid PROPERTIES
                     LABELS "repro;realtime;multiprocess;slow" TIMEOUT 300 RUN_SERIAL TRUE)
