# Same seed -> same digest; another seed -> another digest (through the CLI, --json).
# The plant gets actuation noise, so the seed reaches the plant-state trajectory; the
# expectations of the open-loop scenario no longer hold then, so exit code 1 is accepted.
#   cmake -DPLEXUS=... -DSCENARIO=... -DOUT=dir -P determinism.cmake
function(digest_of out_var name)
  execute_process(COMMAND ${PLEXUS} sim ${SCENARIO} --json --quiet --out ${OUT}/${name}
                          --set robots.r1.plant.omega_noise_std=0.01 ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
    message(FATAL_ERROR "plexus sim ${ARGN}: exit ${rc}: ${err}")
  endif()
  string(JSON d GET "${json}" digest)
  if(NOT d MATCHES "^[0-9a-f]+$")
    message(FATAL_ERROR "no digest in: ${json}")
  endif()
  string(LENGTH "${d}" len)
  if(NOT len EQUAL 16)
    message(FATAL_ERROR "digest '${d}' is not 16 hex digits")
  endif()
  set(${out_var} "${d}" PARENT_SCOPE)
endfunction()

digest_of(a run_a)
digest_of(b run_b)
digest_of(c run_c --set seed=7)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "same scenario and seed, different digests: ${a} ${b}")
endif()
if(a STREQUAL c)
  message(FATAL_ERROR "different seed, same digest ${a}")
endif()
file(READ ${OUT}/run_a/metrics.json ma)
file(READ ${OUT}/run_b/metrics.json mb)
if(NOT ma STREQUAL mb)
  message(FATAL_ERROR "metrics.json differ between identical runs")
endif()
