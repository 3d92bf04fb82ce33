# Foxglove live view (issue 28, docs/viewing.md): foxglove_bridge beside the RFID scenario in
# realtime, read by @foxglove/ws-protocol's client; rates against plexus topic hz. Domains
# 171 and 175, ports 18765-18767.
# Fast DDS: the bridge started alone; Cyclone DDS: by plexus launch --foxglove PORT.
foreach(variant "fast;171;18765;alone" "cyclone;175;18766;launch")
  list(POP_FRONT variant vendor domain port mode)
  add_test(NAME ecosystem.foxglove_rfid_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/foxglove_rfid.sh $<TARGET_FILE:plexus> $<TARGET_FILE:foxglove_bridge> ${vendor}
                   ${domain} ${port} ${CMAKE_BINARY_DIR}/test-runs/ecosystem/foxglove_rfid_${vendor} ${mode})
  set_tests_properties(ecosystem.foxglove_rfid_${vendor} PROPERTIES LABELS "ecosystem;realtime;multiprocess;light" TIMEOUT 120)
endforeach()
add_test(NAME ecosystem.foxglove_port_in_use
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/foxglove_port_busy.sh $<TARGET_FILE:foxglove_bridge> $<TARGET_FILE:plexus>
                 ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml 18767
                 ${CMAKE_BINARY_DIR}/test-runs/ecosystem/foxglove_port_in_use)
set_tests_properties(ecosystem.foxglove_port_in_use PROPERTIES LABELS "cli;ecosystem")
