# Provenance: the code version and git commit are written into every output file.
# They live in one generated source, build/generated/hmfnet/version.cpp, written at configure
# time and rewritten at every build by the target hmfnet_version (cmake/HmfnetVersionScript.cmake),
# so a build after a commit records that commit without a reconfigure; configure_file leaves the
# file untouched when nothing changed.
# The file is the only source of the SHARED library hmfnet_version_info, and no target re-links
# because that library changed (CMAKE_LINK_DEPENDS_NO_SHARED; it is the only shared library
# hmfnet builds and its interface, src/core/version.hpp, never changes). A new commit therefore
# rebuilds one small library and leaves every executable untouched: `make paper-figures`, whose
# data step depends on the driver executables, re-runs only the drivers whose code changed, and
# each run records the commit it ran at, read from the library when it runs.
set(HMFNET_VERSION_SOURCE ${CMAKE_BINARY_DIR}/generated/hmfnet/version.cpp)
set(HMFNET_VERSION_ARGS -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${HMFNET_VERSION_SOURCE}
    -DPROJECT_VERSION=${PROJECT_VERSION})
execute_process(COMMAND ${CMAKE_COMMAND} ${HMFNET_VERSION_ARGS}
                -P ${CMAKE_CURRENT_LIST_DIR}/HmfnetVersionScript.cmake)
add_custom_target(hmfnet_version ALL
  COMMAND ${CMAKE_COMMAND} ${HMFNET_VERSION_ARGS} -P ${CMAKE_CURRENT_LIST_DIR}/HmfnetVersionScript.cmake
  BYPRODUCTS ${HMFNET_VERSION_SOURCE}
  COMMENT "provenance: git commit into version.cpp"
  VERBATIM)
add_library(hmfnet_version_info SHARED ${HMFNET_VERSION_SOURCE})
add_dependencies(hmfnet_version_info hmfnet_version)
target_include_directories(hmfnet_version_info PUBLIC $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}/src>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/hmfnet>)
set_target_properties(hmfnet_version_info PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
set(CMAKE_LINK_DEPENDS_NO_SHARED ON)
