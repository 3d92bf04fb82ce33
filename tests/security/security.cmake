# DDS Security (issue 14, docs/security.md): secure closed loops on each vendor, the mixed
# vendor handshake, intruders without an identity or from another CA, and a capture of the
# secure traffic. Label `security`; DDS domains 100-109.
add_executable(security_probe ${CMAKE_CURRENT_LIST_DIR}/security_probe.cpp)
target_link_libraries(security_probe PRIVATE plexus_runtime CLI11::CLI11)
plexus_warnings(security_probe)
