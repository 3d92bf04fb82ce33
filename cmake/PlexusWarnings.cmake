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
    # In a unity build each .cpp is #included into a batch, and GCC then reports a class of
    # the file (a pimpl's Impl) holding a type of the file's anonymous namespace as if a
    # header did (-Wsubobject-linkage); each file is still compiled once.
    $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>,$<BOOL:${PLEXUS_UNITY_BUILD}>>:-Wno-subobject-linkage>
    $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra>)
endfunction()
