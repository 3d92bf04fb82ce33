# plexus_discover_tests(<target> LABELS <label>... [TEST_FILTER <filter>] [TEST_PREFIX <prefix>]
#                       [PROPERTIES <name> <value>...])
#
# gtest_discover_tests with several labels. gtest_discover_tests flattens its PROPERTIES into
# one list, so `LABELS "unit;runtime"` there keeps "unit" only and shifts every property
# after it ("runtime" is read as a property name, and a TIMEOUT or RESOURCE_LOCK that follows
# is lost). Here the other properties go to gtest_discover_tests, and the labels are set
# once ctest has discovered the tests, by a file that runs after the discovery
# (TEST_INCLUDE_FILES of this directory).
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
  gtest_discover_tests(${target} ${extra} TEST_LIST ${list})
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
