# Script mode (cmake -P): writes OUTPUT from src/core/version.cpp.in with the current
# `git describe --always --dirty`; "unknown" outside a git checkout. Used by HmfnetVersion.cmake
# at configure time and by the hmfnet_version target at build time.
find_package(Git QUIET)
set(HMFNET_GIT_COMMIT "unknown")
if(GIT_FOUND AND EXISTS ${SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY ${SOURCE_DIR}
                  OUTPUT_VARIABLE HMFNET_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(NOT HMFNET_GIT_COMMIT)
    set(HMFNET_GIT_COMMIT "unknown")
  endif()
endif()
configure_file(${SOURCE_DIR}/src/core/version.cpp.in ${OUTPUT} @ONLY)
