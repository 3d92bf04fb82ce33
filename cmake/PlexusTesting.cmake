# plexus_discover_tests(<target> LABELS <label>... [TEST_FILTER <filter>] [TEST_PREFIX <prefix>]
#                       [PROPERTIES <name> <value>...])
#
# gtest_discover_tests with several labels. gtest_discover_tests flattens its PROPERTIES into
# one list, so `LABELS "unit;runtime"` there keeps "unit" only and shifts every property
# after it ("runtime" is read as a property name, and a TIMEOUT or RESOURCE_LOCK that follows
# is lost). Here the other properties go to gtest_discover_tests, and the labels are set
# once ctest has discovered the tests, by a file that runs after the discovery
# (TEST_INCLUDE_FILES of this directory). Every GoogleTest program is discovered through it.
#
# NO_PRETTY_VALUES: a value-parameterised test is named <suite>.<test>/<parameter's name>. With
# CMake 3.25's pretty values, a parameter named by a name generator (rather than its index)
# kept gtest's "  # GetParam() = 72-byte object <92-67 ...>" in the ctest name: the bytes of a
# pointer, a different name in every build (118 tests until 2026-11-30).
function(plexus_discover_tests target)
  cmake_parse_arguments(PDT "" "TEST_FILTER;TEST_PREFIX" "LABELS;PROPERTIES" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}_${PDT_TEST_FILTER}" list)
  set(extra "")
  if(PDT_TEST_FILTER)
    list(APPEND extra TEST_FILTER "${PDT_TEST_FILTER}")
  endif()
  if(PDT_TEST_PREFIX)
    list(APPEND extra TEST_PREFIX "${PDT_TEST_PREFIX}")
  endif()
  if(PDT_PROPERTIES)
    list(APPEND extra PROPERTIES ${PDT_PROPERTIES})
  endif()
  gtest_discover_tests(${target} ${extra} TEST_LIST ${list} NO_PRETTY_VALUES)
  if(PDT_LABELS)
    set(file ${CMAKE_CURRENT_BINARY_DIR}/${list}_labels.cmake)
    file(WRITE ${file} "if(DEFINED ${list})\n  set_tests_properties(\${${list}} PROPERTIES LABELS \"${PDT_LABELS}\")\nendif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${file})
  endif()
endfunction()

# plexus_place_test_programs(): every test program in build/bin/tests/, apart from the
# programs a user runs (build/bin/): an executable named *_tests (the GoogleTest binaries) or
# defined under tests/ (peers, probes, helpers of the test scripts). Called once, after every
# target is defined; nothing is listed by name, so a new test program lands there by itself.
function(plexus_place_test_programs)
  set(dirs ${PROJECT_SOURCE_DIR})
  while(dirs)
    list(POP_FRONT dirs dir)
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    list(APPEND dirs ${subdirs})
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(t IN LISTS targets)
      get_target_property(type ${t} TYPE)
      get_target_property(source_dir ${t} SOURCE_DIR)
      string(FIND "${source_dir}/" "${PROJECT_SOURCE_DIR}/tests/" under_tests)
      if(type STREQUAL "EXECUTABLE" AND (t MATCHES "_tests$" OR under_tests EQUAL 0))
        set_target_properties(${t} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin/tests)
      endif()
    endforeach()
  endwhile()
endfunction()

# plexus_realtime_lanes(): called once, at the end of tests/CMakeLists.txt (the directory that
# defines the tests it changes). CI's first phase runs the tests that need the CPU free of
# CPU-bound work, several at a time (docs/testing.md, "Realtime lanes"):
#   - a test labelled `realtime` and RUN_SERIAL checks wall-clock figures, so by default it runs
#     with nothing beside it; most are light: a 100 Hz loop over a few processes takes 1-25 %
#     of this 2-core machine (measured 2026-11-28);
#   - a test labelled `light` spends its time waiting on the wall clock (discovery, timeouts,
#     realtime loops whose timing it does not judge) and takes under ~15 % of the machine
#     (measured): run beside CPU-bound tests, it holds a `ctest -j2` slot while idle.
# With PLEXUS_REALTIME_LANES=N (N >= 2) in ctest's environment these tests are no longer
# RUN_SERIAL, and `ctest -jN` over them alone runs N at once. Decided when ctest runs, so the
# canonical build serves both; without the variable nothing changes. Tests on the host's
# network share it: two DDS deployments on different domains of one host do not see each
# other (the cross-domain leak, issue 33 item 1, fixed; docs/runtime.md, "Domains on one
# host"). In lanes:
#   - a test labelled `alone` (the 1 kHz arm across processes, its loops at SCHED_FIFO) takes
#     the heavy tests' lock below, so it never runs beside one of them or another `alone`
#     test, but runs beside the light ones (RUN_SERIAL until 2026-11-30: 60 s of the phase with
#     one lane busy; docs/testing.md, "Realtime lanes");
#   - the tests labelled `netns` or `multihost` (network namespaces, veth pairs, sshd) take
#     one lock, `plexus_netns_realtime`: creating and deleting namespaces holds the kernel's
#     network locks, which would stall another such test's `ip`/`nft` commands mid-fault.
#   - the tests labelled `heavy` (a dozen processes, or restarts that rediscover them all:
#     the soak, the kill-each runs, the 45 s main jobs) take one lock, `plexus_heavy_realtime`,
#     so that at most one runs at a time: two of them with the soak and a lossy split run
#     beside them left a restarted controller 1.0-1.5 s to come back, and a pty-based serial
#     loop beside the two main jobs missed its bound (clean-clone CI runs of 2026-11-29;
#     docs/testing.md). With the `alone` tests, a chain of about 415 s (355 + 60); not the
#     netns tests, whose own chain (about 410 s) it would join into one longer than the phase.
#     The two chains start first: COST, which orders ctest's queue when it has no times of
#     its own (a clean build); the others by their TIMEOUT.
# tools/setup/test.sh selects the same tests for the phase from `ctest --show-only=json-v1`.
function(plexus_realtime_lanes)
  get_property(tests DIRECTORY PROPERTY TESTS)
  set(changes "")
  foreach(test IN LISTS tests)
    get_test_property(${test} RUN_SERIAL serial)
    get_test_property(${test} LABELS labels)
    get_test_property(${test} TIMEOUT timeout)
    if(NOT ((serial AND "realtime" IN_LIST labels) OR "light" IN_LIST labels))
      continue()
    endif()
    if(NOT timeout)
      set(timeout 1500)  # ctest's default
    endif()
    get_test_property(${test} RESOURCE_LOCK locks)
    if(NOT locks)
      set(locks "")
    endif()
    set(cost ${timeout})
    if("netns" IN_LIST labels OR "multihost" IN_LIST labels)
      list(APPEND locks plexus_netns_realtime)
      math(EXPR cost "${timeout} + 10000")
    endif()
    if("heavy" IN_LIST labels OR "alone" IN_LIST labels)
      list(APPEND locks plexus_heavy_realtime)
      math(EXPR cost "${cost} + 5000")
    endif()
    if(locks)
      string(APPEND changes "    set_tests_properties([=[${test}]=] PROPERTIES RUN_SERIAL FALSE COST ${cost} RESOURCE_LOCK \"${locks}\")\n")
    else()
      string(APPEND changes "    set_tests_properties([=[${test}]=] PROPERTIES RUN_SERIAL FALSE COST ${cost})\n")
    endif()
  endforeach()
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/realtime_lanes/lanes.cmake
       "# Generated by plexus_realtime_lanes() (cmake/PlexusTesting.cmake).
set(plexus_lanes \"\$ENV{PLEXUS_REALTIME_LANES}\")
if(NOT plexus_lanes STREQUAL \"\")
  if(NOT plexus_lanes MATCHES \"^[1-9][0-9]?$\")
    message(FATAL_ERROR \"PLEXUS_REALTIME_LANES='\${plexus_lanes}' (environment): expected a number of lanes, 1-99\")
  endif()
  if(plexus_lanes GREATER 1)
${changes}  endif()
endif()
")
  # A directory of its own: ctest reads a directory's TEST_INCLUDE_FILES before its tests, and
  # this file changes tests that must exist by then (a subdirectory is read after its parent).
  add_subdirectory(${PROJECT_SOURCE_DIR}/tests/realtime_lanes ${CMAKE_CURRENT_BINARY_DIR}/realtime_lanes)
endfunction()
