# The fuzz build (-DPLEXUS_FUZZ=ON, a build folder of its own; tests/fuzz, docs/testing.md).
#
# Every file of this build is compiled by clang with AddressSanitizer, UndefinedBehaviorSanitizer
# and libFuzzer's coverage instrumentation, so the libraries under test report their own
# memory errors and undefined behaviour and guide the fuzzer with their own coverage. An
# undefined-behaviour report stops the run like a crash (-fno-sanitize-recover). Only the fuzz
# executables link the libFuzzer driver (-fsanitize=fuzzer, tests/fuzz/CMakeLists.txt).
#
# System libraries (yaml-cpp, SQLite, Fast CDR, spdlog) are Debian's, not instrumented: their
# heap use is still checked (ASan replaces malloc), their inner code is not.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "PLEXUS_FUZZ needs clang (libFuzzer), and ${CMAKE_CXX_COMPILER} is ${CMAKE_CXX_COMPILER_ID}: "
                      "configure a new build folder, e.g. cmake -S . -B build-fuzz -DPLEXUS_FUZZ=ON "
                      "(tools/setup/install_deps.sh installs clang and libclang-rt-14-dev)")
endif()

# libFuzzer's runtime is a package of its own (libclang-rt-14-dev): say so now, not at the
# first link.
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_LINK_OPTIONS -fsanitize=fuzzer,address,undefined)
check_cxx_source_compiles(
  "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const uint8_t*, std::size_t) { return 0; }"
  PLEXUS_LIBFUZZER_LINKS)
unset(CMAKE_REQUIRED_LINK_OPTIONS)
if(NOT PLEXUS_LIBFUZZER_LINKS)
  message(FATAL_ERROR "PLEXUS_FUZZ: ${CMAKE_CXX_COMPILER} cannot link a libFuzzer target "
                      "(tools/setup/install_deps.sh installs libclang-rt-14-dev)")
endif()

# PLEXUS_FUZZ_OPT: -O1 (default) is libFuzzer's recommendation, for long runs by hand; CI's smoke
# builds -O0 (tools/setup/fuzz_smoke.sh), which halves the build (a 2-DoF EKF file: 22 s at
# -O1 -g, 11 s at -O0) for 20 s of fuzzing per target. -gline-tables-only: stack traces with
# file and line, without the full debug info (a fifth of the compile time at -O1). NDEBUG as shipped.
set(PLEXUS_FUZZ_OPT "-O1" CACHE STRING "optimisation of the fuzz build (-O1 for long runs, -O0 for a smoke)")
add_compile_options(${PLEXUS_FUZZ_OPT} -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined
                    -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link)
add_link_options(-fsanitize=address,undefined)
