# Fails when the committed file FILE differs from the generated GENERATED, naming the target
# that rewrites it (TARGET).
file(READ ${FILE} committed)
file(READ ${GENERATED} generated)
if(NOT committed STREQUAL generated)
  message(FATAL_ERROR "${FILE} differs from what the IDL generates (${GENERATED}); "
                      "run `cmake --build build --target ${TARGET}` and commit it")
endif()
message(STATUS "${FILE} matches ${GENERATED}")
