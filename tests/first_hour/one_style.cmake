# A user's first hour (issue 19), one CLI style and messages that name their cause:
# one flag name per meaning, services' help with their topics, one log format, a short
# warning once, JSON alone on stdout (one_style.sh); a scenario `sim` accepts also launches
# (its QoS profile names are checked the same way); a bad remap is blamed, not the component
# it starves; a realtime run ends without liveliness warnings or empty latency lines and
# says its configuration warning once (quiet_runs.sh, domains 74-75).
add_test(NAME first_hour.one_style COMMAND ${CMAKE_CURRENT_LIST_DIR}/one_style.sh $<TARGET_FILE_DIR:plexus>)
plexus_refusal_test(first_hour.sim_checks_qos_profile_names LABELS cli
                    ERROR "^plexus sim: error: .*unicycle_circle.yaml:[0-9]+: services.driver.qos: unknown QoS profile 'bogus' in "
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set services.driver.qos=bogus)
plexus_refusal_test(first_hour.remap_that_starves_an_input LABELS cli
                    ERROR "services.driver.remap.cmd: sends driver's output 'cmd' to 'r1/cmd2', so nothing produces 'r1/cmd', read by .*robots.r1.plant"
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet --set services.driver.remap.cmd=r1/cmd2)
plexus_refusal_test(first_hour.remap_onto_a_produced_signal LABELS cli
                    ERROR "services.circle.remap.reference: sends circle's output 'reference' to 'r1/cmd', which driver produces"
                    COMMAND $<TARGET_FILE:plexus> sim ${FH_SCENARIO} --quiet
                            --set services.circle.remap.reference=r1/cmd)
set_tests_properties(first_hour.one_style PROPERTIES LABELS "cli")
set(FH_DOMAIN 74)
foreach(vendor fast cyclone)
  add_test(NAME first_hour.quiet_realtime_run_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/quiet_runs.sh $<TARGET_FILE:plexus> ${PROJECT_SOURCE_DIR}/deploy/scenarios
                   ${CMAKE_BINARY_DIR}/test-runs/first_hour/quiet_${vendor} ${FH_DOMAIN} ${vendor})
  set_tests_properties(first_hour.quiet_realtime_run_${vendor} PROPERTIES LABELS "cli;realtime;multiprocess"
                       RESOURCE_LOCK plexus_dds_domain_${FH_DOMAIN} TIMEOUT 120)
  math(EXPR FH_DOMAIN "${FH_DOMAIN} + 1")
endforeach()
