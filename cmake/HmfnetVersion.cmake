# Provenance: the code version and git commit are baked into every output file.
find_package(Git QUIET)
set(HMFNET_GIT_COMMIT "unknown")
if(GIT_FOUND AND EXISTS ${CMAKE_SOURCE_DIR}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                  OUTPUT_VARIABLE HMFNET_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(NOT HMFNET_GIT_COMMIT)
    set(HMFNET_GIT_COMMIT "unknown")
  endif()
endif()
configure_file(${CMAKE_SOURCE_DIR}/src/core/version.hpp.in
               ${CMAKE_BINARY_DIR}/generated/hmfnet/version.hpp @ONLY)
