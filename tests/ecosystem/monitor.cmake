# A web monitor of a launch (issue 28, docs/viewing.md): `plexus launch --monitor PORT` on the
# RFID scenario in realtime, checked in Debian's chromium driven by puppeteer-core (a SIGKILLed
# controller turns red within 2 s and comes back; live heartbeats; the plot grows). Fast DDS
# alone; Cyclone DDS with the observer on Fast DDS (mixed). Domains 181-182, ports 18768-18771 (18770-18771: monitor_refused).
foreach(variant "fast;181;18768;" "cyclone;182;18769;--vendor=observer=fast")
  list(POP_FRONT variant vendor domain port extra)
  add_test(NAME ecosystem.monitor_rfid_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/monitor_rfid.sh $<TARGET_FILE:plexus> ${vendor} ${domain} ${port}
                   ${CMAKE_BINARY_DIR}/test-runs/ecosystem/monitor_rfid_${vendor} ${extra})
  set_tests_properties(ecosystem.monitor_rfid_${vendor} PROPERTIES LABELS "ecosystem;realtime;multiprocess;browser"
                                                                   TIMEOUT 150)
endforeach()
add_test(NAME ecosystem.monitor_refused
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/monitor_refused.sh $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml 18770
                 ${CMAKE_BINARY_DIR}/test-runs/ecosystem/monitor_refused)
set_tests_properties(ecosystem.monitor_refused PROPERTIES LABELS "cli;ecosystem")
