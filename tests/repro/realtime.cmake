# Paper targets in realtime (issue 8): `plexus launch` on wall-clock loops, every service its
# own process. The unicycle RFID case (paper 000 section 6.3.2) keeps the published steady-
# state bounds (max 0.05 m, mean 0.01 m after 100 s), checked by the scenario's own
# expectations; the run is shortened from 480 s to 101 s (the bounds' window starts at
# 100 s). RUN_SERIAL: a realtime run shares the machine with nothing else in the suite.
add_test(NAME repro.realtime.wmr_output_feedback_rfid
         COMMAND $<TARGET_FILE:plexus> launch ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml
                 --set clock.mode=realtime --set duration=101 --quiet --domain 179
                 --out ${CMAKE_BINARY_DIR}/test-runs/realtime/wmr_output_feedback_rfid)
set_tests_properties(repro.realtime.wmr_output_feedback_rfid PROPERTIES
                     LABELS "repro;realtime;multiprocess;slow" TIMEOUT 300 RUN_SERIAL TRUE)
