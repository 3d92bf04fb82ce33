# ROS 2 names (issue 28, docs/ros2.md): the main job under --naming ros2 in realtime; the wire
# names, the generated ROS 2 interface package (@foxglove/rosmsg) and the samples decoded as
# ROS 2 CDR (@foxglove/rosmsg2-serialization) against plexus topic echo. Domains 165-166.
foreach(variant "fast;165" "cyclone;166")
  list(POP_FRONT variant vendor domain)
  add_test(NAME ecosystem.ros2_names_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/ros2_names.sh $<TARGET_FILE:plexus> ${vendor} ${domain}
                   ${CMAKE_BINARY_DIR}/test-runs/ecosystem/ros2_names_${vendor} ${PROJECT_BINARY_DIR}/ros2/plexus_msgs)
  set_tests_properties(ecosystem.ros2_names_${vendor} PROPERTIES LABELS "ecosystem;realtime;multiprocess" TIMEOUT 180)
endforeach()
# Bad naming: one line naming where it came from, exit 2 (a tool, a service, a scenario, launch).
plexus_refusal_test(ecosystem.naming_bad_tool LABELS cli ecosystem
                    ERROR "--naming: unknown naming 'ros' \\(expected plexus or ros2\\)"
                    COMMAND $<TARGET_FILE:plexus> topic list --naming ros --domain 214 --wait 0.1)
plexus_refusal_test(ecosystem.naming_bad_service LABELS cli ecosystem
                    ERROR "--naming: unknown naming 'ros1'"
                    COMMAND ${CMAKE_BINARY_DIR}/bin/plant_simulator
                            --params ${PROJECT_SOURCE_DIR}/deploy/params/unicycle_robot.yaml --naming ros1
                            --domain 214)
plexus_refusal_test(ecosystem.naming_bad_scenario LABELS cli ecosystem
                    ERROR "dds.naming: expected plexus or ros2, got 'dds'"
                    COMMAND $<TARGET_FILE:plexus> sim
                            ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml --quiet
                            --set dds.naming=dds)
plexus_refusal_test(ecosystem.naming_bad_launch LABELS cli ecosystem
                    ERROR "--naming: unknown naming 'x'"
                    COMMAND $<TARGET_FILE:plexus> launch
                            ${PROJECT_SOURCE_DIR}/deploy/scenarios/path_following_circle.yaml --naming x --domain 214)
