# LCM 1.3.1 as Debian ships it: no CMake package, and a pkg-config file that needs glib headers
# which are not installed. Find the pieces directly and make lcm::lcm.
find_program(AVC_LCM_GEN lcm-gen)
find_path(AVC_LCM_INCLUDE_DIR lcm/lcm-cpp.hpp)
find_library(AVC_LCM_LIBRARY lcm)
if(NOT AVC_LCM_GEN)
  avc_missing_dependency("lcm-gen" liblcm-bin)
endif()
if(NOT AVC_LCM_INCLUDE_DIR OR NOT AVC_LCM_LIBRARY)
  avc_missing_dependency("the LCM library and headers" liblcm-dev)
endif()
add_library(lcm::lcm UNKNOWN IMPORTED)
set_target_properties(lcm::lcm PROPERTIES IMPORTED_LOCATION "${AVC_LCM_LIBRARY}"
                      INTERFACE_INCLUDE_DIRECTORIES "${AVC_LCM_INCLUDE_DIR}")

set(AVC_LCM_JAR /usr/share/java/lcm.jar)
if(AVC_JAVA_ENABLED)
  find_package(Java COMPONENTS Development QUIET)
  if(NOT Java_FOUND)
    message(STATUS "No JDK: build/avc-lcmtypes.jar (for lcm-spy) will not be built "
                   "(apt-get install default-jdk-headless liblcm-java)")
  elseif(NOT EXISTS ${AVC_LCM_JAR})
    message(STATUS "No ${AVC_LCM_JAR}: the lcm-spy jar will not be built (apt-get install liblcm-java)")
    set(Java_FOUND FALSE)
  endif()
endif()

# avc_lcm_generate(TARGET <name> PACKAGE_DIR <dir with <package>/*.lcm>)
# Generates C++ headers into the build tree (included as SYSTEM: they do not pass our warnings),
# their array decoding bounded by the bytes received (AvcLcmBoundArrays.cmake)
# and, with a JDK, ${PROJECT_BINARY_DIR}/avc-lcmtypes.jar.
function(avc_lcm_generate)
  cmake_parse_arguments(ARG "" "TARGET;PACKAGE_DIR" "" ${ARGN})
  file(GLOB_RECURSE lcm_files CONFIGURE_DEPENDS ${ARG_PACKAGE_DIR}/*.lcm)
  set(gen ${PROJECT_BINARY_DIR}/lcmtypes)
  set(hpps "")
  set(javas "")
  foreach(f IN LISTS lcm_files)
    get_filename_component(type ${f} NAME_WE)
    get_filename_component(pkgdir ${f} DIRECTORY)
    get_filename_component(pkg ${pkgdir} NAME)
    set(hpp ${gen}/cpp/${pkg}/${type}.hpp)
    set(java ${gen}/java/${pkg}/${type}.java)
    set(outputs ${hpp})
    set(java_args "")
    if(Java_FOUND)
      list(APPEND outputs ${java})
      set(java_args --java --jpath ${gen}/java)
    endif()
    add_custom_command(OUTPUT ${outputs}
      COMMAND ${AVC_LCM_GEN} --cpp --cpp-std=c++11 --cpp-hpath ${gen}/cpp ${java_args} ${f}
      COMMAND ${CMAKE_COMMAND} -DFILE=${hpp} -P ${PROJECT_SOURCE_DIR}/cmake/AvcLcmBoundArrays.cmake
      DEPENDS ${f} ${PROJECT_SOURCE_DIR}/cmake/AvcLcmBoundArrays.cmake
      COMMENT "lcm-gen ${pkg}/${type}.lcm"
      VERBATIM)
    list(APPEND hpps ${hpp})
    list(APPEND javas ${java})
  endforeach()
  add_custom_target(${ARG_TARGET}_gen DEPENDS ${hpps})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_gen)
  target_include_directories(${ARG_TARGET} SYSTEM INTERFACE ${gen}/cpp)
  target_link_libraries(${ARG_TARGET} INTERFACE lcm::lcm)
  if(Java_FOUND)
    include(UseJava)
    add_jar(${ARG_TARGET}_java SOURCES ${javas} INCLUDE_JARS ${AVC_LCM_JAR}
            OUTPUT_NAME avc-lcmtypes OUTPUT_DIR ${PROJECT_BINARY_DIR})
    set(AVC_LCMTYPES_JAR ${PROJECT_BINARY_DIR}/avc-lcmtypes.jar CACHE INTERNAL "")
  endif()
endfunction()
