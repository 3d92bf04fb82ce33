# Third-party readers check plexus's MCAP recordings (issue 28): a shortened main job
# (deploy/scenarios/four_robots.yaml) recorded with `plexus launch --record`, opened with
# @mcap/core's McapIndexedReader (and read again with its McapStreamReader, every CRC
# checked), every channel's schema parsed with @foxglove/omgidl-parser, every message
# decoded with @foxglove/omgidl-serialization; the counts must equal `plexus record info`'s
# and the first samples of every topic `plexus topic echo --recording`'s. Both vendors.
# Label `ecosystem`; the npm packages come from tools/setup/install_npm.sh. Domains 163-164.
foreach(variant "fast;163" "cyclone;164")
  list(POP_FRONT variant vendor domain)
  add_test(NAME ecosystem.mcap_main_job_${vendor}
           COMMAND ${CMAKE_CURRENT_LIST_DIR}/mcap_main_job.sh $<TARGET_FILE:plexus> ${vendor} ${domain}
                   ${CMAKE_BINARY_DIR}/test-runs/ecosystem/mcap_main_job_${vendor} 10)
  set_tests_properties(ecosystem.mcap_main_job_${vendor} PROPERTIES LABELS "ecosystem;lockstep;multiprocess" TIMEOUT 300)
endforeach()
