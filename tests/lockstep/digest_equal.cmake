# Runs `plexus sim` and `plexus launch` on the same scenario and checks the digests are
# identical. Arguments: PLEXUS, SCENARIO, OUT, DOMAIN, LAUNCH_ARGS ("|"-separated).
execute_process(COMMAND ${PLEXUS} sim ${SCENARIO} --json --quiet --out ${OUT}/sim
                OUTPUT_VARIABLE sim_out RESULT_VARIABLE sim_rc)
string(REPLACE "|" ";" launch_args "${LAUNCH_ARGS}")
execute_process(COMMAND ${PLEXUS} launch ${SCENARIO} --json --quiet --domain ${DOMAIN} --out ${OUT}/launch ${launch_args}
                OUTPUT_VARIABLE launch_out ERROR_VARIABLE launch_err RESULT_VARIABLE launch_rc)
string(REGEX MATCH "\"digest\":\"([0-9a-f]+)\"" _ "${sim_out}")
set(sim_digest "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"digest\":\"([0-9a-f]+)\"" _ "${launch_out}")
set(launch_digest "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"steps_per_s\":([0-9.e+]+)" _ "${launch_out}")
message(STATUS "sim rc=${sim_rc} digest=${sim_digest}; launch rc=${launch_rc} digest=${launch_digest} steps/s=${CMAKE_MATCH_1}")
if(NOT sim_digest OR NOT sim_digest STREQUAL launch_digest)
  message(FATAL_ERROR "digests differ (launch stderr: ${launch_err})")
endif()
if(NOT sim_rc EQUAL launch_rc)
  message(FATAL_ERROR "exit codes differ: sim ${sim_rc}, launch ${launch_rc}")
endif()
