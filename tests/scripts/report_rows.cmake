# plexus report's rows and exit code: a run with an unmet expectation reports exit 1 (as
# `plexus sim` does), a met one 0, and an expectation whose metric metrics.json lacks is a
# row that says "missing" and FAIL, not a dropped row.
#   cmake -DPLEXUS=... -DSCENARIO=... -DOUT=dir -DMETRIC=name -P report_rows.cmake
function(run expect_rc)
  execute_process(COMMAND ${PLEXUS} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "plexus ${ARGN}: exit ${rc}, expected ${expect_rc}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
file(REMOVE_RECURSE ${OUT})
run(0 sim ${SCENARIO} --quiet --out ${OUT}/met)
run(0 report ${OUT}/met)
run(1 sim ${SCENARIO} --quiet --out ${OUT}/unmet --set "expectations.${METRIC}=< 0")
run(1 report ${OUT}/unmet)
if(NOT out MATCHES "\\| ${METRIC} \\| [^|]+ \\| < 0 \\| FAIL \\|")
  message(FATAL_ERROR "no FAIL row for ${METRIC}:\n${out}")
endif()
# The metric removed from metrics.json: its row says missing, and the report fails.
file(READ ${OUT}/met/metrics.json json)
string(JSON json REMOVE "${json}" ${METRIC})
file(WRITE ${OUT}/met/metrics.json "${json}")
run(1 report ${OUT}/met)
if(NOT out MATCHES "\\| ${METRIC} \\| missing \\| [^|]+ \\| FAIL \\|")
  message(FATAL_ERROR "no 'missing' row for ${METRIC}:\n${out}")
endif()
