# The flexible-joint arm (paper 003 section 5, arm_vdc_ekf) at 1 kHz in realtime, with the
# reference, the EKF and the VDC controller in one process (`process: control`) beside the
# plant simulator: the loop must stay stable, rms tracking error under 100 mrad (`plexus sim`
# at 1 kHz: 1.72 mrad). With observer and controller in separate processes this loop diverged
# on this 2-core machine (non-finite torques). Table 4's settling times (<= 0.36 / 0.37 s)
# are met by the runs in which every hop keeps its deadline (such a run equals `plexus sim`:
# 7 of 14 runs here); a pause at start-up or a few late samples push the error past the
# 1.15 mrad band for a while (rms 1.8-45 mrad), so the settling times and the rms are printed
# and reported in docs/distributed.md, not asserted (timing goals live in measured reports,
# not in tests on a shared machine). The input deadline is 20 periods: a hold (zero torque)
# answers a dead producer, not a few milliseconds of scheduling delay on a shared machine.
# Arguments: PLEXUS, SCENARIO, OUT, DOMAIN, VENDOR.
execute_process(COMMAND ${PLEXUS} launch ${SCENARIO} --json --quiet --domain ${DOMAIN} --out ${OUT} --dds ${VENDOR}
                        --set step=0.001 --set clock.mode=realtime --set clock.input_deadline_periods=20
                        --set services.reference.process=control
                        --set services.observer.process=control --set services.controller.process=control
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
# Exit 1 is an unmet expectation (the settling times, see above); anything else is a failure.
if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
  message(FATAL_ERROR "launch exited ${rc}: ${err}")
endif()
string(JSON rms GET "${out}" rms_norm_mrad)
string(JSON settle1 GET "${out}" settling_time_1_s)
string(JSON settle2 GET "${out}" settling_time_2_s)
file(READ ${OUT}/launch.json j)
string(JSON program GET "${j}" processes control program)
string(JSON late GET "${j}" services "component_host reference,observer,controller" late_input_reads)
message(STATUS "rms ${rms} mrad, settling ${settle1} / ${settle2} s (Table 4: 0.36 / 0.37), "
               "control process ${program}, ${late} late input reads")
if(NOT program STREQUAL "component_host")
  message(FATAL_ERROR "the control group did not run in one component_host process (${program})")
endif()
if(NOT rms MATCHES "^[0-9.e+-]+$" OR rms GREATER_EQUAL 100)
  message(FATAL_ERROR "the realtime arm did not stay stable: rms tracking error ${rms} mrad (bound 100)")
endif()
