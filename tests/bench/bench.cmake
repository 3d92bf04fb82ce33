# plexus bench (issue 32, docs/qos-bench.md): the quick matrix with every cell and measure and
# its report rendered in headless Chromium; --baseline flagging a planted regression and
# nothing else; loss on a two-namespace link reported as given; bad input. DDS domains 21-23.
set(BENCH_RUNS ${CMAKE_BINARY_DIR}/test-runs/bench)
add_test(NAME bench.quick COMMAND ${CMAKE_CURRENT_LIST_DIR}/quick.sh $<TARGET_FILE:plexus> ${BENCH_RUNS}/quick 21)
add_test(NAME bench.baseline_flags_planted_delay
         COMMAND ${CMAKE_CURRENT_LIST_DIR}/baseline.sh $<TARGET_FILE:plexus> ${BENCH_RUNS}/baseline 22)
# Not beside each other: each is the other's load.
set_tests_properties(bench.quick bench.baseline_flags_planted_delay PROPERTIES LABELS "bench;multiprocess" TIMEOUT 300
                     RESOURCE_LOCK plexus_bench)
add_test(NAME bench.loss_two_ns COMMAND ${CMAKE_CURRENT_LIST_DIR}/loss.sh $<TARGET_FILE:plexus> ${BENCH_RUNS}/loss 23)
set_tests_properties(bench.loss_two_ns PROPERTIES LABELS "bench;netns;multiprocess" TIMEOUT 300 RUN_SERIAL TRUE
                     SKIP_RETURN_CODE 77)

# Bad input: one line naming the flag, file or key; exit 2; nothing run.
foreach(case "pairs;--pairs: unknown DDS vendor 'opensplice';--pairs;fast-opensplice"
             "sizes;plexus bench: sizes: each must be in 0..1048576 bytes;--sizes;64,2000000"
             "topology;plexus bench: topologies: unknown value 'three_hosts';--topologies;three_hosts"
             "matrix_key;bad_matrix.yaml:2: sizez: unknown key;--matrix;${CMAKE_CURRENT_LIST_DIR}/data/bad_matrix.yaml"
             "baseline;--baseline: cannot read /nonexistent/run;--baseline;/nonexistent/run"
             "plant;--plant-delay: expected CELL_ID=MICROSECONDS;--plant-delay;5000")
  list(GET case 0 name)
  list(GET case 1 message)
  list(GET case 2 flag)
  list(GET case 3 value)
  plexus_refusal_test(bench.bad_${name} LABELS bench cli TIMEOUT 60
                      ERROR "${message}"
                      COMMAND $<TARGET_FILE:plexus> bench ${flag} ${value} -o ${BENCH_RUNS}/bad_${name})
endforeach()
