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

# avc_add_test(NAME <name> LABEL unit|bus|replay|multiproc SRCS ... [DEPS ...] [TIMEOUT s])
# Registers "<label>/<name>" with ctest. multiproc tests run inside a private network namespace
# (tests/support/in_netns) and hold a resource lock so two heavy ones never share the 2 cores.
function(avc_add_test)
  cmake_parse_arguments(ARG "" "NAME;LABEL;TIMEOUT" "SRCS;DEPS" ${ARGN})
  set(allowed unit bus replay multiproc)
  if(NOT ARG_LABEL IN_LIST allowed)
    message(FATAL_ERROR "avc_add_test(${ARG_NAME}): LABEL must be one of ${allowed}")
  endif()
  set(target test_${ARG_LABEL}_${ARG_NAME})
  add_executable(${target} ${ARG_SRCS})
  _avc_policy(${target})
  target_compile_options(${target} PRIVATE ${AVC_GLUE_OPTIMIZATION})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS} avc_test_support GTest::gtest_main)
  # gtest, Eigen, OpenCV core, json and the standard library parsed once (tests/support).
  if(TARGET avc_test_pch)
    target_precompile_headers(${target} REUSE_FROM avc_test_pch)
  endif()
  set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 60)
  endif()
  if(ARG_LABEL STREQUAL "multiproc")
    add_test(NAME ${ARG_LABEL}/${ARG_NAME}
             COMMAND ${PROJECT_SOURCE_DIR}/tests/support/in_netns $<TARGET_FILE:${target}>)
    set_tests_properties(${ARG_LABEL}/${ARG_NAME} PROPERTIES RESOURCE_LOCK multiproc)
  else()
    add_test(NAME ${ARG_LABEL}/${ARG_NAME} COMMAND ${target})
  endif()
  set_tests_properties(${ARG_LABEL}/${ARG_NAME} PROPERTIES
    LABELS ${ARG_LABEL} TIMEOUT ${ARG_TIMEOUT}
    ENVIRONMENT "AVC_BUILD_DIR=${PROJECT_BINARY_DIR};AVC_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
