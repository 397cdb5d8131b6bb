# Provenance: the code version and git commit are baked into every output file.
# The header is written at configure time and rewritten at every build by the target
# hmfnet_version (cmake/HmfnetVersionScript.cmake), so a build after a commit records that commit
# without a reconfigure; configure_file leaves the file untouched when nothing changed, so only a
# new commit (or a change of the --dirty state) recompiles the few files that include it.
set(HMFNET_VERSION_HEADER ${CMAKE_BINARY_DIR}/generated/hmfnet/version.hpp)
set(HMFNET_VERSION_ARGS -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${HMFNET_VERSION_HEADER}
    -DPROJECT_VERSION=${PROJECT_VERSION})
execute_process(COMMAND ${CMAKE_COMMAND} ${HMFNET_VERSION_ARGS}
                -P ${CMAKE_CURRENT_LIST_DIR}/HmfnetVersionScript.cmake)
add_custom_target(hmfnet_version ALL
  COMMAND ${CMAKE_COMMAND} ${HMFNET_VERSION_ARGS} -P ${CMAKE_CURRENT_LIST_DIR}/HmfnetVersionScript.cmake
  BYPRODUCTS ${HMFNET_VERSION_HEADER}
  COMMENT "provenance: git commit into version.hpp"
  VERBATIM)
