# Vendor-native unicycle plants, built like native_cyclone_peer / native_fast_peer: only the
# generated code of plexus's IDL and the vendor API, no plexus library.
#   native_unicycle_plant_cyclone: C, Cyclone DDS + idlc output (plexus_msgs_cyclone_c)
#   native_unicycle_plant_fast:    C++, Fast DDS 2.9 + fastddsgen types (plexus_msgs_fast)
# Included from tests/CMakeLists.txt; sources are found next to this file. Executables go to
# ${CMAKE_BINARY_DIR}/bin (CMAKE_RUNTIME_OUTPUT_DIRECTORY).
include_guard(GLOBAL)
find_package(Threads REQUIRED)

add_executable(native_unicycle_plant_cyclone ${CMAKE_CURRENT_LIST_DIR}/native_unicycle_plant_cyclone.c)
target_link_libraries(native_unicycle_plant_cyclone PRIVATE plexus_msgs_cyclone_c CycloneDDS::ddsc Threads::Threads m)

add_executable(native_unicycle_plant_fast ${CMAKE_CURRENT_LIST_DIR}/native_unicycle_plant_fast.cpp)
target_link_libraries(native_unicycle_plant_fast PRIVATE plexus_msgs_fast fastrtps fastcdr Threads::Threads)

if(COMMAND plexus_warnings)
  plexus_warnings(native_unicycle_plant_cyclone)
  plexus_warnings(native_unicycle_plant_fast)
endif()
