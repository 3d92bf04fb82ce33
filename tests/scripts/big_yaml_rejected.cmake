# A YAML file beyond the 4 MB limit is refused before it is parsed, naming the file and its
# size (exit 2, one line, promptly). The file is generated here: a scenario with a 5 MB list
# under an unknown key.
#   cmake -DPLEXUS=... -DOUT=dir -P big_yaml_rejected.cmake
file(MAKE_DIRECTORY ${OUT})
set(f ${OUT}/big.yaml)
string(REPEAT "0, " 65536 chunk)  # 192 kB
file(WRITE ${f} "name: big\nstep: 0.1\nduration: 1\nseed: 1\njunk: [")
foreach(i RANGE 27)
  file(APPEND ${f} "${chunk}")
endforeach()
file(APPEND ${f} "0]\n")
execute_process(COMMAND ${PLEXUS} sim ${f} --quiet RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 20)
file(REMOVE ${f})
if(NOT rc EQUAL 2 OR NOT err MATCHES "big.yaml: 5 MB, larger than the 4 MB limit for a plexus YAML file")
  message(FATAL_ERROR "exit ${rc}: ${err}")
endif()
