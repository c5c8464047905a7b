# Project helpers: every folder's CMakeLists.txt is a few declarative calls to these.
# Policy (warnings, include root, test labels and timeouts) lives here only.

set(AVC_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align
                 -Woverloaded-virtual -Wimplicit-fallthrough)
# GCC 12 reports impossible memcpy overlaps inside std::string at -O3 (GCC bug 105329).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND AVC_WARNINGS -Wno-restrict)
endif()
if(AVC_WERROR_ENABLED)
  list(APPEND AVC_WARNINGS -Werror)
endif()

# Glue code (tests, the CLI's subcommands, the benchmarks' drivers) runs for milliseconds but is template-heavy (gtest,
# CLI11, nlohmann::json): -O3 on it costs about a quarter of its compile time for nothing, so in
# Release it gets -O1. The libraries, where the work is done, keep -O3.
set(AVC_GLUE_OPTIMIZATION $<$<CONFIG:Release>:-O1>)
# At -O1 GCC 12 also reports impossible std::string bounds, overflows and overreads (siblings of the
# -Wrestrict bug 105329 above).
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND AVC_GLUE_OPTIMIZATION $<$<CONFIG:Release>:-Wno-array-bounds>
       $<$<CONFIG:Release>:-Wno-stringop-overflow> $<$<CONFIG:Release>:-Wno-stringop-overread>)
endif()

# Unity builds: each target's sources are compiled AVC_UNITY_BATCH_SIZE at a time as one
# translation unit, so the heavy third-party headers (Eigen, OpenCV, PCL, CGAL, nlohmann::json,
# CLI11) are parsed and their templates instantiated once per batch instead of once per file
# (BENCHMARKS.md, build). Sources in a target therefore share one namespace scope: helpers in
# anonymous namespaces need names unique within their library.
set(AVC_UNITY_BATCH_SIZE 16 CACHE STRING "Sources per unity translation unit")

function(_avc_policy target)
  target_compile_options(${target} PRIVATE ${AVC_WARNINGS})
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${AVC_UNITY_BUILD_ENABLED}
                                             UNITY_BUILD_BATCH_SIZE ${AVC_UNITY_BATCH_SIZE})
  # Includes are rooted at the repository: #include "core/bus/bus.h".
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
endfunction()

# avc_add_library(NAME <target> SRCS ... [DEPS ...] [PRIVATE_DEPS ...])
function(avc_add_library)
  cmake_parse_arguments(ARG "" "NAME" "SRCS;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SRCS})
  _avc_policy(${ARG_NAME})
  # The CLI's and the benchmarks' own code only sequences and prints: glue optimization.
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  if(folder MATCHES "^(tools|bench)(/|$)")
    target_compile_options(${ARG_NAME} PRIVATE ${AVC_GLUE_OPTIMIZATION})
  endif()
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  set_target_properties(${ARG_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# avc_add_executable(NAME <binary name> SRCS ... [DEPS ...])
# Binaries land in build/bin so tests and the launcher find them in one place.
function(avc_add_executable)
  cmake_parse_arguments(ARG "" "NAME" "SRCS;DEPS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SRCS})
  _avc_policy(${ARG_NAME})
  target_compile_options(${ARG_NAME} PRIVATE ${AVC_GLUE_OPTIMIZATION})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_DEPS})
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bin)
endfunction()

# The gtest names a test source defines, as a --gtest_filter pattern list ("Suite.Name:...";
# TEST_P as "*/Suite.Name/*"), in `out`. Fails for a source with no test.
function(_avc_test_filter out)
  set(patterns "")
  set(space "[ \t\r\n]*")
  set(word "[A-Za-z0-9_]+")
  foreach(src IN LISTS ARGN)
    get_filename_component(path ${src} ABSOLUTE)
    file(READ ${path} text)
    string(REGEX MATCHALL "TEST(_F|_P)?\\(${space}${word}${space},${space}${word}${space}\\)" found
           "${text}")
    foreach(test IN LISTS found)
      string(REGEX REPLACE "[ \t\r\n]" "" test "${test}")
      string(REGEX MATCH "^TEST(_F|_P)?\\((${word}),(${word})\\)$" parts "${test}")
      if(CMAKE_MATCH_1 STREQUAL "_P")
        list(APPEND patterns "*/${CMAKE_MATCH_2}.${CMAKE_MATCH_3}/*")
      else()
        list(APPEND patterns "${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
      endif()
    endforeach()
  endforeach()
  if(NOT patterns)
    message(FATAL_ERROR "${CMAKE_CURRENT_SOURCE_DIR}: no TEST in ${ARGN}")
  endif()
  string(REPLACE ";" ":" filter "${patterns}")
  set(${out} "${filter}" PARENT_SCOPE)
endfunction()

# avc_add_test(NAME <name> LABEL unit|bus|replay|multiproc SRCS ... [DEPS ...] [TIMEOUT s]
#              [USES_AVC])
# Registers "<folder>/<name>" with ctest, where <folder> is the test's folder under tests/ (which
# mirrors the sources), so `ctest -R ^core/bus/` selects a module and `-L LABEL` a kind.
# The tests of one folder and label are one executable (test_<label>_<folder>), compiled in
# unity batches like the libraries: each ctest entry runs it with a gtest filter naming the
# tests its own sources define (two sources may not define the same test). multiproc tests run
# inside a private network namespace (tests/support/in_netns) and hold a resource lock so two
# heavy ones never share the 2 cores. USES_AVC: the test runs build/bin/avc, built first.
function(avc_add_test)
  cmake_parse_arguments(ARG "USES_AVC" "NAME;LABEL;TIMEOUT" "SRCS;DEPS" ${ARGN})
  set(allowed unit bus replay multiproc)
  if(NOT ARG_LABEL IN_LIST allowed)
    message(FATAL_ERROR "avc_add_test(${ARG_NAME}): LABEL must be one of ${allowed}")
  endif()
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR}/tests ${CMAKE_CURRENT_SOURCE_DIR})
  string(REPLACE "/" "_" flat "${folder}")
  set(target test_${ARG_LABEL}_${flat})
  if(NOT TARGET ${target})
    add_executable(${target})
    _avc_policy(${target})
    target_compile_options(${target} PRIVATE ${AVC_GLUE_OPTIMIZATION})
    target_link_libraries(${target} PRIVATE avc_test_support GTest::gtest_main)
    # gtest, Eigen, OpenCV core, json and the standard library parsed once (tests/support).
    if(TARGET avc_test_pch)
      target_precompile_headers(${target} REUSE_FROM avc_test_pch)
    endif()
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  endif()
  target_sources(${target} PRIVATE ${ARG_SRCS})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS})
  if(ARG_USES_AVC)
    add_dependencies(${target} avc)
  endif()
  # Only the sources that define tests name them; helpers shared by several tests of the folder
  # are compiled once.
  set(test_sources "")
  foreach(src IN LISTS ARG_SRCS)
    if(src MATCHES "_test\\.cc$")
      list(APPEND test_sources ${src})
    endif()
  endforeach()
  _avc_test_filter(filter ${test_sources})
  get_property(defined TARGET ${target} PROPERTY AVC_DEFINED_TESTS)
  string(REPLACE ":" ";" mine "${filter}")
  foreach(test IN LISTS mine)
    if(test IN_LIST defined)
      message(FATAL_ERROR "${folder}: ${test} is defined by two tests of ${target}")
    endif()
  endforeach()
  set_property(TARGET ${target} APPEND PROPERTY AVC_DEFINED_TESTS ${mine})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 60)
  endif()
  # core/surface's "surface_phases" is core/surface/phases.
  get_filename_component(leaf ${folder} NAME)
  string(REGEX REPLACE "^${leaf}_(.)" "\\1" short ${ARG_NAME})
  set(name ${folder}/${short})
  if(ARG_LABEL STREQUAL "multiproc")
    add_test(NAME ${name} COMMAND ${PROJECT_SOURCE_DIR}/tests/support/in_netns
                                  $<TARGET_FILE:${target}> --gtest_filter=${filter})
    set_tests_properties(${name} PROPERTIES RESOURCE_LOCK multiproc)
  else()
    add_test(NAME ${name} COMMAND ${target} --gtest_filter=${filter})
  endif()
  set_tests_properties(${name} PROPERTIES
    LABELS ${ARG_LABEL} TIMEOUT ${ARG_TIMEOUT}
    ENVIRONMENT "AVC_BUILD_DIR=${PROJECT_BINARY_DIR};AVC_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
