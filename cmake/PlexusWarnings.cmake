# plexus_warnings(target): our own code builds clean under -Wall -Wextra.
# Generated code (fastddsgen, idlc) is compiled without them: it is not ours to fix.
function(plexus_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wnon-virtual-dtor>
    # -Wshadow=local is GCC's (clang, for the fuzz build, does not know it).
    $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wshadow=local>
    # GCC 12 reports a false -Wrestrict inside libstdc++ for `"literal" + std::string`
    # at -O2 (GCC bug 105329); it is not in our code.
    $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wno-restrict>
    $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra>)
endfunction()
