# plexus_add_messages(): a message package from its IDL files, the same way for plexus's own
# messages (idl/CMakeLists.txt) and a user's (docs/sdk.md, "Messages"). Installed with the
# CMake package (plexusConfig.cmake includes it).
#
#   plexus_add_messages(<target>
#     IDL_ROOT <dir>          the include root: IDL files are named relative to it, and include
#                             each other (and plexus's) by that name: #include "mylab/msg/contact.idl"
#     IDL <file.idl>...       the package's files
#     [HEADER <name>]         include name of the generated header (default <target>/messages.hpp)
#     [DOCS <file.md>]        also write the Markdown reference of the types
#     [ROS2 <dir>]            also write the ROS 2 interface package of the types into <dir>
#                             (package.xml, CMakeLists.txt, msg/*.msg; docs/ros2.md): its name
#                             is <target>
#     [DEPENDS <target>...])  message packages whose IDL these files include (plexus's own is implied)
#
# Runs, for both vendors and at build time:
#   fastddsgen     C++ classes and TopicDataTypes (no type objects: the interop rule)
#   idlc -t        C topic descriptors (no type information: the interop rule)
#   plexus_idlgen  the interop checks (@final, no @optional/@key, case-insensitive names,
#                  bounded strings and sequences), each type's TypeSupport, signal fields with
#                  units and ranges (the edge check), omgidl schema, JSON form, SignalLayout
#                  (typed ports), and the registration that makes every plexus tool know the types.
# Targets: <target> (SHARED: link it, or load it as a plugin), <target>_fast and
# <target>_cyclone_c (STATIC: the vendors' generated code alone, for programs that use no plexus).
#
# Where plexus's pieces are: in plexus's own tree (PLEXUS_IN_TREE) its targets, installed the
# imported ones of plexusConfig.cmake.
find_program(FASTDDSGEN fastddsgen REQUIRED)
find_program(IDLC idlc REQUIRED)

function(plexus_add_messages target)
  cmake_parse_arguments(M "" "IDL_ROOT;HEADER;DOCS;ROS2" "IDL;DEPENDS" ${ARGN})
  if(NOT M_IDL_ROOT OR NOT M_IDL)
    message(FATAL_ERROR "plexus_add_messages(${target}): IDL_ROOT and IDL are required")
  endif()
  if(NOT M_HEADER)
    set(M_HEADER ${target}/messages.hpp)
  endif()
  get_filename_component(root ${M_IDL_ROOT} ABSOLUTE)
  # core: what the generated code links (the registry; for a user's package, plexus's own
  # messages too). The include directories of plexus's generated code, for files that include
  # plexus's IDL.
  if(PLEXUS_IN_TREE)
    set(idlgen $<TARGET_FILE:plexus_idlgen>)
    set(idlgen_dep plexus_idlgen)
    set(core plexus_msgs)
    set(plexus_idl_dir ${PROJECT_SOURCE_DIR}/idl)
    set(plexus_fast_include ${PROJECT_BINARY_DIR}/idl/gen/plexus_msgs/fast)
    set(plexus_cyc_include ${PROJECT_BINARY_DIR}/idl/gen/plexus_msgs/cyclone)
  else()
    set(idlgen $<TARGET_FILE:plexus::idlgen>)
    set(idlgen_dep "")
    set(core plexus::msgs)
    set(plexus_idl_dir ${PLEXUS_IDL_DIR})
    set(plexus_fast_include ${PLEXUS_FAST_INCLUDE_DIR})
    set(plexus_cyc_include ${PLEXUS_CYCLONE_INCLUDE_DIR})
  endif()
  set(own_package OFF)
  if(target STREQUAL "plexus_msgs")
    set(own_package ON)
    set(core plexus_msgs_core)
  endif()
  set(include_args -I ${root})
  if(NOT root STREQUAL plexus_idl_dir)
    list(APPEND include_args -I ${plexus_idl_dir})
  endif()
  foreach(dep ${M_DEPENDS})
    get_target_property(dep_root ${dep} PLEXUS_IDL_ROOT)
    if(dep_root)
      list(APPEND include_args -I ${dep_root})
    endif()
  endforeach()

  set(gen ${CMAKE_CURRENT_BINARY_DIR}/gen/${target})
  set(gen_fast ${gen}/fast)
  set(gen_cyc ${gen}/cyclone)
  set(gen_tmp ${gen}/fastddsgen)
  file(MAKE_DIRECTORY ${gen_fast} ${gen_cyc} ${gen_tmp})

  # fastddsgen writes a package's files flat (#include "header.h"): they share one folder, the
  # folder of the files under the include root, also the path their headers are included by
  # (#include "plexus/msg/pose.h").
  list(GET M_IDL 0 first)
  get_filename_component(first ${first} ABSOLUTE)
  file(RELATIVE_PATH first_rel ${root} ${first})
  get_filename_component(pkg_dir ${first_rel} DIRECTORY)
  set(gen_fast_flat ${gen_fast}/${pkg_dir})
  file(MAKE_DIRECTORY ${gen_fast_flat})
  set(idl_abs "")
  set(fast_out "")
  set(fast_src "")
  set(cyc_src "")
  set(copy_cmds "")
  foreach(idl ${M_IDL})
    get_filename_component(abs ${idl} ABSOLUTE)
    file(RELATIVE_PATH rel ${root} ${abs})
    if(rel MATCHES "^\\.\\.")
      message(FATAL_ERROR "plexus_add_messages(${target}): ${idl} is not under IDL_ROOT ${root}")
    endif()
    get_filename_component(base ${abs} NAME_WE)
    get_filename_component(rel_dir ${rel} DIRECTORY)
    if(NOT rel_dir STREQUAL pkg_dir)
      message(FATAL_ERROR "plexus_add_messages(${target}): ${idl} is in ${rel_dir}, the package's other files in "
                          "${pkg_dir}; a package's IDL files share one folder")
    endif()
    if(EXISTS /usr/include/${base}.h)
      # fastddsgen includes its headers flat (#include "pose.h"): a file named like a system
      # header would shadow it.
      message(FATAL_ERROR "${idl}: the name clashes with the system header <${base}.h>; rename the file")
    endif()
    list(APPEND idl_abs ${abs})
    foreach(suffix .h .cxx PubSubTypes.h PubSubTypes.cxx)
      list(APPEND fast_out ${gen_fast_flat}/${base}${suffix})
      list(APPEND copy_cmds COMMAND ${CMAKE_COMMAND} -E copy_if_different ${gen_tmp}/${base}${suffix}
                                    ${gen_fast_flat}/${base}${suffix})
    endforeach()
    list(APPEND fast_src ${gen_fast_flat}/${base}.cxx ${gen_fast_flat}/${base}PubSubTypes.cxx)
    set(cyc_out ${gen_cyc}/${rel_dir}/${base}.h ${gen_cyc}/${rel_dir}/${base}.c)
    file(MAKE_DIRECTORY ${gen_cyc}/${rel_dir})
    add_custom_command(OUTPUT ${cyc_out}
      COMMAND ${IDLC} -t ${include_args} -b ${root} -o ${gen_cyc} ${abs}
      DEPENDS ${abs}
      COMMENT "idlc ${rel}" VERBATIM)
    list(APPEND cyc_src ${gen_cyc}/${rel_dir}/${base}.c)
  endforeach()
  # One fastddsgen for all files (it also writes the code of every file they include: one command,
  # so that parallel builds never rewrite a header while a compiler reads it); only the package's
  # own files are kept. No -typeobject: the interop rule. The outputs are touched after the copy:
  # a file copy_if_different left alone stays older than an IDL file edited since, and the
  # command (and every compile and link after it) would run again at every build, relinking
  # the shared libraries under running tests (cpack's preinstall build in sdk.deb_package did,
  # 2026-11-30: "libplexus_msgs.so: file too short" in three tests beside it).
  add_custom_command(OUTPUT ${fast_out}
    COMMAND ${FASTDDSGEN} -replace ${include_args} -d ${gen_tmp} ${idl_abs} > /dev/null
    ${copy_cmds}
    COMMAND ${CMAKE_COMMAND} -E touch_nocreate ${fast_out}
    DEPENDS ${idl_abs}
    COMMENT "fastddsgen ${target}" VERBATIM)

  set(header ${gen}/include/${M_HEADER})
  set(source ${gen}/${target}_registry.cpp)
  set(outputs ${header} ${source})
  set(docs_args "")
  if(M_DOCS)
    list(APPEND outputs ${M_DOCS})
    set(docs_args --docs ${M_DOCS})
  endif()
  if(M_ROS2)
    list(APPEND outputs ${M_ROS2}/package.xml)
    list(APPEND docs_args --ros2 ${M_ROS2})
  endif()
  set(dep_headers "")
  if(NOT own_package)
    list(APPEND dep_headers --dependency-header plexus/msg/messages.hpp)
  endif()
  foreach(dep ${M_DEPENDS})
    get_target_property(dep_header ${dep} PLEXUS_MESSAGES_HEADER)
    if(dep_header)
      list(APPEND dep_headers --dependency-header ${dep_header})
    endif()
  endforeach()
  add_custom_command(OUTPUT ${outputs}
    COMMAND ${idlgen} --package ${target} --header-name ${M_HEADER} ${dep_headers} --header ${header} --source ${source}
            ${docs_args} ${include_args} ${idl_abs}
    DEPENDS ${idl_abs} ${idlgen_dep}
    COMMENT "plexus_idlgen ${target}" VERBATIM)

  add_library(${target}_cyclone_c STATIC ${cyc_src})
  target_include_directories(${target}_cyclone_c PUBLIC $<BUILD_INTERFACE:${gen_cyc}>)
  if(NOT own_package)
    target_include_directories(${target}_cyclone_c PUBLIC ${plexus_cyc_include})
  endif()
  target_link_libraries(${target}_cyclone_c PUBLIC CycloneDDS::ddsc)
  target_compile_options(${target}_cyclone_c PRIVATE -w)
  set_target_properties(${target}_cyclone_c PROPERTIES POSITION_INDEPENDENT_CODE ON)

  add_library(${target}_fast STATIC ${fast_src})
  target_include_directories(${target}_fast PUBLIC $<BUILD_INTERFACE:${gen_fast}> $<BUILD_INTERFACE:${gen_fast_flat}>)
  target_link_libraries(${target}_fast PUBLIC fastcdr fastrtps)
  if(NOT own_package)
    target_include_directories(${target}_fast PUBLIC ${plexus_fast_include} ${plexus_fast_include}/plexus/msg)
  endif()
  foreach(dep ${M_DEPENDS})
    get_target_property(dep_flat ${dep} PLEXUS_FAST_FLAT_DIR)
    if(dep_flat)
      target_include_directories(${target}_fast PUBLIC ${dep_flat})
    endif()
  endforeach()
  target_compile_options(${target}_fast PRIVATE -w)
  set_target_properties(${target}_fast PROPERTIES POSITION_INDEPENDENT_CODE ON)

  add_library(${target} SHARED ${source} ${header})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${gen}/include> $<BUILD_INTERFACE:${gen_fast}>
                                              $<BUILD_INTERFACE:${gen_fast_flat}>)
  target_link_libraries(${target}
    PUBLIC ${core} fastcdr fastrtps nlohmann_json::nlohmann_json ${M_DEPENDS}
    PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,${target}_fast>" "$<LINK_LIBRARY:WHOLE_ARCHIVE,${target}_cyclone_c>"
            CycloneDDS::ddsc)
  target_compile_options(${target} PRIVATE -w)
  set_target_properties(${target} PROPERTIES
    PLEXUS_IDL_ROOT ${root}
    PLEXUS_MESSAGES_HEADER ${M_HEADER}
    PLEXUS_GEN_DIR ${gen}
    PLEXUS_FAST_FLAT_DIR ${gen_fast_flat})
  set_property(TARGET ${target} APPEND PROPERTY EXPORT_PROPERTIES PLEXUS_IDL_ROOT PLEXUS_MESSAGES_HEADER)
endfunction()
