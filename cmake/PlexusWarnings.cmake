# plexus_warnings(target): our own code builds clean under -Wall -Wextra.
# Generated code (fastddsgen, idlc) is compiled without them: it is not ours to fix.
function(plexus_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor>
    $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra>)
endfunction()
