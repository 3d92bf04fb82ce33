# Issue 15 section 5: the fleet generator (tools/scenarios/fleet_unicycles.sh) writes
# scenarios `plexus sim` accepts, whose every robot meets the paper's bounds (exit 0), in each
# grouping (the `process` keys change processes, not results: one digest for the three);
# deploy/scenarios/fleet_unicycles.yaml is its N = 50 output, unedited; bad arguments exit 2.
# Leaves OUT/fleet_3_<grouping>.yaml, OUT/fleet_20_type.yaml and OUT/fleet_35_robot.yaml for
# the lockstep tests (fixture fleet_scenarios).
# Arguments: PLEXUS, GEN, COMMITTED, OUT.
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND sh ${GEN} 50 type OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
file(READ ${COMMITTED} committed)
if(NOT rc EQUAL 0 OR NOT generated STREQUAL committed)
  message(FATAL_ERROR "${COMMITTED} is not `fleet_unicycles.sh 50 type` (rc ${rc}): regenerate it")
endif()
set(first_digest "")
foreach(grouping type robot service)
  set(scenario ${OUT}/fleet_3_${grouping}.yaml)
  execute_process(COMMAND sh ${GEN} 3 ${grouping} OUTPUT_FILE ${scenario} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fleet_unicycles.sh 3 ${grouping}: exit ${rc}")
  endif()
  execute_process(COMMAND ${PLEXUS} sim ${scenario} --json --quiet --out ${OUT}/sim_${grouping}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "plexus sim of fleet_unicycles.sh 3 ${grouping}: exit ${rc}: ${err}")
  endif()
  string(JSON digest GET "${out}" digest)
  foreach(r 1 2 3)  # every robot has its metrics
    string(JSON v ERROR_VARIABLE missing GET "${out}" r${r}_steady_max_error_m)
    if(missing OR v STREQUAL "null")
      message(FATAL_ERROR "fleet_unicycles.sh 3 ${grouping}: no r${r}_steady_max_error_m in ${out}")
    endif()
  endforeach()
  if(first_digest STREQUAL "")
    set(first_digest ${digest})
  elseif(NOT digest STREQUAL first_digest)
    message(FATAL_ERROR "grouping ${grouping} changed the sim's digest: ${digest}, not ${first_digest}")
  endif()
  message(STATUS "fleet 3 by ${grouping}: plexus sim exit 0, digest ${digest}")
endforeach()
# And OUT/fleet_20_type.yaml (5 s) for lockstep.fleet20_type_fast: process names over 251 bytes.
execute_process(COMMAND sh ${GEN} 20 type 5 OUTPUT_FILE ${OUT}/fleet_20_type.yaml RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fleet_unicycles.sh 20 type 5: exit ${rc}")
endif()
# And OUT/fleet_35_robot.yaml (2 s) for lockstep.fleet35_robot_*: 36 processes on one host.
execute_process(COMMAND sh ${GEN} 35 robot 2 OUTPUT_FILE ${OUT}/fleet_35_robot.yaml RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fleet_unicycles.sh 35 robot 2: exit ${rc}")
endif()
foreach(bad "0;type" "x;type" "3;bogus" "1000;type")
  execute_process(COMMAND sh ${GEN} ${bad} OUTPUT_QUIET ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "fleet_unicycles.sh ${bad}: exit ${rc}, expected 2")
  endif()
endforeach()
