# A lockstep `plexus launch` with DDS Security on gives the digest and metrics of `plexus sim`
# (tests/lockstep/digest_equal.cmake), and every participant ran with its own identity:
# launch.json names the PKI, and the launcher and each of PROCESSES with a certificate subject
# of the PKI's CA; each process's log shows it was started with --security and its identity.
# Arguments: those of digest_equal.cmake, PKI, PROCESSES ("|"-separated process names).
include(${CMAKE_CURRENT_LIST_DIR}/../lockstep/digest_equal.cmake)
file(READ ${OUT}/launch/launch.json launch_json)
string(JSON pki ERROR_VARIABLE missing GET "${launch_json}" security pki)
if(missing OR NOT pki STREQUAL PKI)
  message(FATAL_ERROR "launch.json: security.pki should be ${PKI}, found '${pki}' (${missing})")
endif()
string(REPLACE "|" ";" processes "plexus_launch|${PROCESSES}")
file(GLOB log_files ${OUT}/launch/logs/*.log)
set(logs "")
foreach(f ${log_files})
  file(READ ${f} text)
  string(APPEND logs "${text}")
endforeach()
foreach(p ${processes})
  string(JSON subject ERROR_VARIABLE missing GET "${launch_json}" security identities ${p} subject)
  string(JSON identity ERROR_VARIABLE missing_id GET "${launch_json}" security identities ${p} identity)
  if(missing OR missing_id OR NOT subject MATCHES "CN=${identity}")
    message(FATAL_ERROR "launch.json: no identity for ${p} (${missing}${missing_id}), subject '${subject}'")
  endif()
  if(NOT p STREQUAL "plexus_launch" AND NOT logs MATCHES "started pid [0-9]+: [^\n]* --security ${PKI} --identity ${identity}")
    message(FATAL_ERROR "${p} was not started with --security ${PKI} --identity ${identity}")
  endif()
  message(STATUS "${p}: identity ${identity}, ${subject}")
endforeach()
