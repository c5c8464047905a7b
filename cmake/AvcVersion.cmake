# The version string every process reports in its heartbeat and every log's run header.
# It is fixed at configure time so that outputs do not depend on when a file was compiled.
find_package(Git QUIET)
set(AVC_GIT_DESCRIBE "")
if(GIT_FOUND AND EXISTS ${PROJECT_SOURCE_DIR}/.git)
  execute_process(
    COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=12
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    OUTPUT_VARIABLE AVC_GIT_DESCRIBE
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
endif()
if(AVC_GIT_DESCRIBE)
  set(AVC_VERSION_STRING "${PROJECT_VERSION}+${AVC_GIT_DESCRIBE}")
else()
  set(AVC_VERSION_STRING "${PROJECT_VERSION}")
endif()
