# Issue 17: one command, many hosts. `plexus launch` in one network namespace starts the other
# hosts' shares over ssh (an sshd per namespace, keys made by the test; ssh_hosts.sh), checks
# them first (preflight) and stops them all. Domains 110-119. RUN_SERIAL: namespaces, sshd
# and realtime loops that need the CPU.
foreach(variant "lockstep2;110;90" "lockstep3;111;90" "teardown;113;120" "session_dies;114;120"
                "launcher_killed;118;120" "host_killed;115;120" "preflight;116;120" "clock_offset;117;120")
  list(POP_FRONT variant name domain timeout)
  add_test(NAME multihost.ssh_${name}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/ssh_launch.sh $<TARGET_FILE:plexus>
                   ${CMAKE_BINARY_DIR}/test-runs/multihost/ssh_${name} ${domain} ${name})
  set_tests_properties(multihost.ssh_${name} PROPERTIES LABELS "multihost;multiprocess" TIMEOUT ${timeout}
                       SKIP_RETURN_CODE 77 RUN_SERIAL TRUE)
endforeach()
# Paper 000's RFID case in realtime over three hosts, started on its reference: the paper's
# steady bounds over [20, 45] s.
add_test(NAME multihost.ssh_realtime_rfid
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/ssh_launch.sh $<TARGET_FILE:plexus>
                 ${CMAKE_BINARY_DIR}/test-runs/multihost/ssh_realtime_rfid 112 realtime_rfid)
set_tests_properties(multihost.ssh_realtime_rfid PROPERTIES LABELS "multihost;multiprocess;realtime;slow" TIMEOUT 300
                     SKIP_RETURN_CODE 77 RUN_SERIAL TRUE)
# plexus deploy units: systemd-analyze verify, the policy keys, and a unit's command line runs.
add_test(NAME multihost.deploy_units
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/deploy_units.sh $<TARGET_FILE:plexus>
                 ${CMAKE_BINARY_DIR}/test-runs/multihost/deploy_units 119)
set_tests_properties(multihost.deploy_units PROPERTIES LABELS "multihost;tools" TIMEOUT 60 SKIP_RETURN_CODE 77)
