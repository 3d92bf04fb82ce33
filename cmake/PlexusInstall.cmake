# `cmake --install build --prefix P` and `cpack -G DEB` (docs/sdk.md, "Installing"):
#   P/bin/                    plexus, plexus_idlgen, the services, the bridges, the device emulator
#   P/lib/                    the SDK's libraries and each service's component library
#   P/include/plexus/         the public headers (each library's include/), the generated message
#                             headers; P/include/plexus/gen/{fast,cyclone} the vendors' generated code
#   P/share/plexus/           qos.yaml, params/, scenarios/, training/, sweeps/ (deploy/), idl/
#   P/lib/cmake/plexus/       plexusConfig.cmake: find_package(plexus) with plexus:: targets,
#                             plexus_add_messages() and plexus_add_service()
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PLEXUS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/plexus)
set(PLEXUS_GEN_INCLUDE ${CMAKE_INSTALL_INCLUDEDIR}/plexus/gen)

# The SDK's libraries, exported as plexus::<name without the plexus_ prefix>.
set(PLEXUS_SDK_LIBRARIES plexus_base plexus_msgs_core plexus_msgs plexus_runtime plexus_algorithms plexus_scenario
                         plexus_evaluation plexus_distributed plexus_service)
foreach(lib ${PLEXUS_SDK_LIBRARIES})
  string(REGEX REPLACE "^plexus_" "" export_name ${lib})
  set_target_properties(${lib} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
target_include_directories(plexus_msgs INTERFACE
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}> $<INSTALL_INTERFACE:${PLEXUS_GEN_INCLUDE}/fast>
  $<INSTALL_INTERFACE:${PLEXUS_GEN_INCLUDE}/fast/plexus/msg>)
target_include_directories(plexus_msgs_fast INTERFACE $<INSTALL_INTERFACE:${PLEXUS_GEN_INCLUDE}/fast>
                                                      $<INSTALL_INTERFACE:${PLEXUS_GEN_INCLUDE}/fast/plexus/msg>)
target_include_directories(plexus_msgs_cyclone_c INTERFACE $<INSTALL_INTERFACE:${PLEXUS_GEN_INCLUDE}/cyclone>)
install(TARGETS ${PLEXUS_SDK_LIBRARIES} plexus_msgs_fast plexus_msgs_cyclone_c
        EXPORT plexusTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set_target_properties(plexus_idlgen PROPERTIES EXPORT_NAME idlgen)
install(TARGETS plexus_idlgen EXPORT plexusTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Public headers: every SDK library's include/ (internal headers live in src/).
foreach(dir common/base common/runtime common/algorithms common/scenario common/evaluation common/distributed
            common/service idl)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
get_target_property(msgs_gen plexus_msgs PLEXUS_GEN_DIR)
install(DIRECTORY ${msgs_gen}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${msgs_gen}/fast/ DESTINATION ${PLEXUS_GEN_INCLUDE}/fast FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${msgs_gen}/cyclone/ DESTINATION ${PLEXUS_GEN_INCLUDE}/cyclone FILES_MATCHING PATTERN "*.h")

# Data: the QoS profiles, parameter files, scenarios and their training data; the IDL.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/deploy/ DESTINATION ${CMAKE_INSTALL_DATADIR}/plexus)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/idl/plexus DESTINATION ${CMAKE_INSTALL_DATADIR}/plexus/idl)

# The programs a user runs (test helpers stay in the build tree).
get_property(builtin_services GLOBAL PROPERTY PLEXUS_BUILTIN_SERVICES)
get_property(builtin_components GLOBAL PROPERTY PLEXUS_BUILTIN_COMPONENT_LIBRARIES)
install(TARGETS plexus ${builtin_services} serial_bridge udp_bridge foxglove_bridge device_emulator demo_node pingpong_node
                raw_fast_pingpong
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${builtin_components} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})

install(EXPORT plexusTargets NAMESPACE plexus:: DESTINATION ${PLEXUS_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/plexusConfig.cmake.in
  ${PROJECT_BINARY_DIR}/plexusConfig.cmake INSTALL_DESTINATION ${PLEXUS_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR PLEXUS_GEN_INCLUDE)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/plexusConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/plexusConfig.cmake ${PROJECT_BINARY_DIR}/plexusConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/PlexusMessages.cmake ${PROJECT_SOURCE_DIR}/cmake/PlexusService.cmake
        DESTINATION ${PLEXUS_CMAKE_DIR})

# cpack -G DEB: plexus_<version>_amd64.deb, depending on Debian's runtime packages.
set(CPACK_PACKAGE_NAME plexus)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "plexus maintainers <plexus@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "distributed real-time runtime for robot estimation and control over DDS")
set(CPACK_PACKAGE_DESCRIPTION "Services exchange IDL-typed topics over Fast DDS or Cyclone DDS, chosen at run time and
 wire-compatible, in QoS-configured real-time loops; with the SDK to build your own services and
 messages (find_package(plexus)), the plexus command-line tool and the reference scenarios.")
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES ON)  # a runtime package: no debug symbols (lintian unstripped-binary-or-object)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://localhost/plexus")
# Runtime dependencies: dpkg-shlibdeps reads them off the installed binaries (the package's own
# libraries found through their $ORIGIN run path). Besides those: gnuplot for `plexus report`'s plots, and
# dygraphs for the page of `plexus launch --monitor` (served from /usr/share/javascript). The SDK's
# build dependencies (headers, generators, compiler) are recommended: apt installs them by
# default, a deployment host may leave them out (--no-install-recommends).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "gnuplot-nox, libjs-dygraphs")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
  "libfastrtps-dev, libfastcdr-dev, fastddsgen, cyclonedds-dev, cyclonedds-tools, libeigen3-dev, libspdlog-dev, \
libyaml-cpp-dev, libcli11-dev, nlohmann-json3-dev, liborocos-kdl-dev, cmake, g++")
include(CPack)
