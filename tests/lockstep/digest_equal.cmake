# Runs `plexus sim` and `plexus launch` on the same scenario and checks that the digests are
# identical, that every metric of the sim run has the same value under launch, and that both
# exit with EXPECT_RC (default 0: every expectation of the scenario, i.e. the paper targets,
# met in lockstep; a launch run whose expectations fail exits 1 and fails this test).
# Arguments: PLEXUS, SCENARIO, OUT, DOMAIN, LAUNCH_ARGS (launch only), ARGS (both runs, e.g.
# `--set|duration=1.2`), both "|"-separated; EXPECT_RC (optional); PROCESS (optional): a
# process launch.json must list, as "NAME=PROGRAM" (a `process` group, for one).
if(NOT DEFINED EXPECT_RC)
  set(EXPECT_RC 0)
endif()
string(REPLACE "|" ";" both_args "${ARGS}")
string(REPLACE "|" ";" launch_args "${LAUNCH_ARGS}")
execute_process(COMMAND ${PLEXUS} sim ${SCENARIO} --json --quiet --out ${OUT}/sim ${both_args}
                OUTPUT_VARIABLE sim_out ERROR_VARIABLE sim_err RESULT_VARIABLE sim_rc)
execute_process(COMMAND ${PLEXUS} launch ${SCENARIO} --json --quiet --domain ${DOMAIN} --out ${OUT}/launch ${both_args}
                        ${launch_args}
                OUTPUT_VARIABLE launch_out ERROR_VARIABLE launch_err RESULT_VARIABLE launch_rc)
string(REGEX MATCH "\"digest\":\"([0-9a-f]+)\"" _ "${sim_out}")
set(sim_digest "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"digest\":\"([0-9a-f]+)\"" _ "${launch_out}")
set(launch_digest "${CMAKE_MATCH_1}")
string(REGEX MATCH "\"steps_per_s\":([0-9.e+]+)" _ "${launch_out}")
message(STATUS "sim rc=${sim_rc} digest=${sim_digest}; launch rc=${launch_rc} digest=${launch_digest} steps/s=${CMAKE_MATCH_1}")
if(NOT sim_digest OR NOT sim_digest STREQUAL launch_digest)
  message(FATAL_ERROR "digests differ (sim stderr: ${sim_err}) (launch stderr: ${launch_err})")
endif()
# Same metric names and values (the digest covers the signals; this covers the evaluation).
string(JSON n_members LENGTH "${sim_out}")
math(EXPR last "${n_members} - 1")
foreach(i RANGE ${last})
  string(JSON key MEMBER "${sim_out}" ${i})
  string(JSON sim_value GET "${sim_out}" "${key}")
  string(JSON launch_value ERROR_VARIABLE missing GET "${launch_out}" "${key}")
  if(missing)
    message(FATAL_ERROR "metric '${key}' of plexus sim is missing under plexus launch")
  endif()
  if(NOT sim_value STREQUAL launch_value)
    message(FATAL_ERROR "metric '${key}' differs: sim ${sim_value}, launch ${launch_value}")
  endif()
endforeach()
if(NOT sim_rc EQUAL launch_rc)
  message(FATAL_ERROR "exit codes differ: sim ${sim_rc}, launch ${launch_rc} (launch stderr: ${launch_err})")
endif()
if(NOT launch_rc EQUAL EXPECT_RC)
  message(FATAL_ERROR "plexus launch exited ${launch_rc}, expected ${EXPECT_RC} (1: an expectation failed): ${launch_err}")
endif()
message(STATUS "${n_members} results equal, exit code ${launch_rc} as expected")
if(DEFINED PROCESS)
  string(REPLACE "=" ";" expected_process "${PROCESS}")
  list(GET expected_process 0 process_name)
  list(GET expected_process 1 process_program)
  file(READ ${OUT}/launch/launch.json launch_json)
  string(JSON program ERROR_VARIABLE missing GET "${launch_json}" processes ${process_name} program)
  if(missing OR NOT program STREQUAL process_program)
    message(FATAL_ERROR "launch.json: process '${process_name}' should run ${process_program}, found '${program}'")
  endif()
  message(STATUS "process ${process_name} ran ${program}")
endif()
