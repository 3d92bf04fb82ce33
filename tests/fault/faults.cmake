# Issue 14, the reliability campaign's network faults, process faults and soak (tests/fault/;
# what each measures, and the figures: docs/distributed.md, "Faults"). Domains 120-129.
# Everything here runs realtime loops or several processes whose behaviour under the fault
# is checked, so each test is RUN_SERIAL; those over ~30 s are labelled slow.
set(FAULT_DIR ${CMAKE_CURRENT_LIST_DIR})
set(FAULT_RUNS ${CMAKE_BINARY_DIR}/test-runs/fault)

# SIGKILL of every service executable in turn, in realtime (kill_each.sh): the safe output,
# the restart within 1 s, the loop resuming; the plant simulator's death makes every feedback
# controller hold. Per vendor, two tests: the three robots' seven cases (about 1.3 min, in
# the realtime lanes) and the arm's two (its 1 kHz loop across processes, labelled `alone`
# as every such test: in four lanes beside the soak its restarted controller diverged,
# docs/testing.md, "Known flakiness").
foreach(variant "fast;125;174" "cyclone;126;176")
  list(POP_FRONT variant vendor domain arm_domain)
  add_test(NAME fault.kill_each_service_${vendor}
           COMMAND bash ${FAULT_DIR}/kill_each.sh $<TARGET_FILE:plexus> ${FAULT_DIR}/three_robots.yaml
                   ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml ${FAULT_RUNS}/kill_each_${vendor} ${domain} ${vendor}
                   component_host localisation_observer motion_controller terrain_classifier icr_estimator
                   attitude_filter plant_simulator)
  set_tests_properties(fault.kill_each_service_${vendor} PROPERTIES
                       LABELS "fault;realtime;multiprocess;slow;heavy" TIMEOUT 600 RUN_SERIAL TRUE)
  add_test(NAME fault.kill_each_service_arm_${vendor}
           COMMAND bash ${FAULT_DIR}/kill_each.sh $<TARGET_FILE:plexus> ${FAULT_DIR}/three_robots.yaml
                   ${PROJECT_SOURCE_DIR}/deploy/scenarios/arm_vdc_ekf.yaml ${FAULT_RUNS}/kill_each_arm_${vendor}
                   ${arm_domain} ${vendor} joint_controller plant_simulator_arm)
  set_tests_properties(fault.kill_each_service_arm_${vendor} PROPERTIES
                       LABELS "fault;realtime;multiprocess;alone" TIMEOUT 300 RUN_SERIAL TRUE)
endforeach()

# SIGKILL of `plexus launch` itself leaves no child behind, on both vendors. `light`: it waits
# on the launch and on the children's exits (in CI's realtime lanes).
add_test(NAME fault.launcher_killed_leaves_no_orphan
         COMMAND bash ${FAULT_DIR}/launcher_kill.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml ${FAULT_RUNS}/launcher_kill 127)
set_tests_properties(fault.launcher_killed_leaves_no_orphan PROPERTIES LABELS "fault;multiprocess;light" TIMEOUT 120
                     RUN_SERIAL TRUE)

# A lockstep run stopped on one frozen service (SIGSTOP) fails naming that service's sample,
# whichever process waiting on it times out first (lockstep_stall.sh). `light`: a second of
# lockstep, then it waits on the timeouts.
foreach(variant "fast;34" "cyclone;35")
  list(POP_FRONT variant vendor domain)
  add_test(NAME fault.lockstep_stall_names_cause_${vendor}
           COMMAND bash ${FAULT_DIR}/lockstep_stall.sh $<TARGET_FILE:plexus>
                   ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml ${FAULT_RUNS}/lockstep_stall_${vendor}
                   ${domain} ${vendor})
  set_tests_properties(fault.lockstep_stall_names_cause_${vendor} PROPERTIES LABELS "fault;multiprocess;light" TIMEOUT 180
                       RUN_SERIAL TRUE)
endforeach()

# RUN_SERIAL, all of them: sharing the machine with other tests was tried, and a partition
# run beside the bridges' contract tests failed both (a 12 s partition for a 2 s one, gaps
# of 0.9-1.4 s in a 100 Hz serial stream) in a CI run.
#
# Network faults (netns_pair.sh: two network namespaces joined by a veth pair, nftables rules
# inside them; created and removed by each test). The unicycle RFID loop split across the
# pair: plant and reference on h1, observer and controller on h2. Root needed (skipped
# otherwise: exit 77).
set(FAULT_RFID ${PROJECT_SOURCE_DIR}/deploy/scenarios/wmr_output_feedback_rfid.yaml)
# Lockstep over 10 % and 30 % loss both ways gives the sim's digest (fast also runs mixed at 10 %).
foreach(variant "fast;120;fast;mixed" "cyclone;121;cyclone")
  list(POP_FRONT variant vendor domain)
  add_test(NAME fault.loss_lockstep_${vendor}
           COMMAND bash ${FAULT_DIR}/loss_lockstep.sh $<TARGET_FILE:plexus> ${FAULT_RFID} ${FAULT_RUNS}/loss_lockstep_${vendor} ${domain} ${variant})
  set_tests_properties(fault.loss_lockstep_${vendor} PROPERTIES LABELS "fault;netns;slow;light" TIMEOUT 300 RUN_SERIAL TRUE SKIP_RETURN_CODE 77)
endforeach()
# Realtime at 0, 10 and 30 % loss, the three runs side by side (each in namespaces of its
# own, so that they meet the same CPU stalls): at 10 % the loop still tracks (steady mean
# under 0.1 m); the issue's 2x and the paper's 10 mm reported (STRICT_TIMING=1 enforces);
# 30 % reported.
foreach(variant "fast;123" "cyclone;124")
  list(POP_FRONT variant vendor domain)
  add_test(NAME fault.loss_realtime_${vendor}
           COMMAND bash ${FAULT_DIR}/loss_realtime.sh $<TARGET_FILE:plexus> ${FAULT_RFID} ${FAULT_RUNS}/loss_realtime_${vendor} ${domain} ${vendor})
  set_tests_properties(fault.loss_realtime_${vendor} PROPERTIES LABELS "fault;netns;realtime;slow" TIMEOUT 400 RUN_SERIAL TRUE SKIP_RETURN_CODE 77)
endforeach()
# A 2 s partition: lockstep within and beyond --timeout, then realtime (both sides hold, tracking resumes).
foreach(variant "fast;128" "cyclone;129")
  list(POP_FRONT variant vendor domain)
  add_test(NAME fault.partition_${vendor}
           COMMAND bash ${FAULT_DIR}/partition.sh $<TARGET_FILE:plexus> ${FAULT_RFID} ${FAULT_RUNS}/partition_${vendor} ${domain} ${vendor})
  set_tests_properties(fault.partition_${vendor} PROPERTIES LABELS "fault;netns;realtime;slow" TIMEOUT 300 RUN_SERIAL TRUE SKIP_RETURN_CODE 77)
endforeach()

# Soak (soak.sh): the main job's 11 processes in realtime for 101 s (its shortest valid run:
# the wmr metrics' window starts at 100 s), /proc of every child sampled every 5 s; after a
# 25 s warm-up no child may open more file descriptors or grow its RSS by more than 1 % or
# 256 kB. The 30-minute form is run by hand (docs/distributed.md, Faults).
add_test(NAME fault.soak_fast
         COMMAND bash ${FAULT_DIR}/soak.sh $<TARGET_FILE:plexus> ${PROJECT_SOURCE_DIR}/deploy/scenarios/four_robots.yaml
                 ${FAULT_RUNS}/soak_fast 122 fast 101 25)
set_tests_properties(fault.soak_fast PROPERTIES LABELS "fault;realtime;multiprocess;slow;heavy" TIMEOUT 400 RUN_SERIAL TRUE)
