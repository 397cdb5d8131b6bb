# Install and packages (README, "Quick start"):
#   cmake --install build --prefix P   the CLI (bin/hmfnet), the library (static archives, their
#                                      headers under include/hmfnet, the shared provenance
#                                      library), a CMake package (lib/cmake/hmfnet) and the Python
#                                      module (lib/python3/dist-packages/hmfnet, Debian's layout)
#   pip install . (P on CMAKE_PREFIX_PATH) the Python module again, built for the interpreter
#                                      running pip against P (python/CMakeLists.txt): it links
#                                      hmfnet::hmfnet_app, the application layer (src/app)
#   cd build && cpack -G DEB           a Debian package of the same, runtime dependencies from
#                                      dpkg-shlibdeps (dpkg-dev)
# A C++ consumer writes find_package(hmfnet) and links hmfnet::hmfnet (tests/install/consumer).
include(CMakePackageConfigHelpers)

set(HMFNET_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
    "Where the Python package goes, relative to the install prefix")

# hmfnet::hmfnet: the whole library (networks, I/O, theory, spectrum, dynamics). The archives are
# static, so their private dependencies (Trilinos, Zoltan2, HDF5) travel as link-only entries and
# hmfnetConfig.cmake finds them again.
add_library(hmfnet_library INTERFACE)
target_link_libraries(hmfnet_library INTERFACE hmfnet_dynamics hmfnet_analysis hmfnet_parallel
                                               hmfnet_theory hmfnet_core)
set_target_properties(hmfnet_library PROPERTIES EXPORT_NAME hmfnet)
add_library(hmfnet::hmfnet ALIAS hmfnet_library)

# The executable and the module find the provenance library (the one shared library) beside them.
file(RELATIVE_PATH _hmfnet_bin_to_lib ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}
     ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR})
set_target_properties(hmfnet PROPERTIES INSTALL_RPATH "$ORIGIN/${_hmfnet_bin_to_lib}")

install(TARGETS hmfnet RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# hmfnet_cuda (the CUDA backend, where it was built) travels as the dynamics' link-only archive.
set(_hmfnet_cuda_target "")
if(HMFNET_CUDA)
  set(_hmfnet_cuda_target hmfnet_cuda)
endif()
install(TARGETS hmfnet_library hmfnet_dynamics hmfnet_analysis hmfnet_parallel hmfnet_theory
                hmfnet_core
                hmfnet_version_info hmfnet_warnings hmfnet_commands hmfnet_cli_options hmfnet_app
                hmfnet_app_requests ${_hmfnet_cuda_target}
        EXPORT hmfnetTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The library's headers, the application layer's (src/app) that the Python module calls among them;
# src/python is the module itself, built from a checkout.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/src/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hmfnet
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "python" EXCLUDE)
install(EXPORT hmfnetTargets NAMESPACE hmfnet::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hmfnet)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/hmfnetConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/hmfnetConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hmfnet)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/hmfnetConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/hmfnetConfig.cmake ${CMAKE_BINARY_DIR}/hmfnetConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hmfnet)

if(HMFNET_PYTHON_MODULE)
  file(RELATIVE_PATH _hmfnet_module_to_lib
       ${CMAKE_INSTALL_PREFIX}/${HMFNET_PYTHON_INSTALL_DIR}/hmfnet
       ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR})
  set_target_properties(_hmfnet PROPERTIES INSTALL_RPATH "$ORIGIN/${_hmfnet_module_to_lib}")
  install(TARGETS _hmfnet LIBRARY DESTINATION ${HMFNET_PYTHON_INSTALL_DIR}/hmfnet)
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/python/hmfnet/ DESTINATION ${HMFNET_PYTHON_INSTALL_DIR}/hmfnet
          FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
endif()

# cpack -G DEB. Depends: what dpkg-shlibdeps finds the binaries linked against, and the Python
# module's interpreter and numpy; building against the library needs the -dev packages that
# ci/install-deps.sh lists (Recommends).
set(CPACK_PACKAGE_NAME hmfnet)
set(CPACK_PACKAGE_VENDOR "hmfnet developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Hamiltonian Mean Field model of coupled rotors on networks: CLI, C++ library, Python module")
set(CPACK_PACKAGE_CONTACT "hmfnet developers <hmfnet@example.org>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(HMFNET_PYTHON_MODULE)
  # The extension is built for this CPython (3.11 on Debian 12) only.
  math(EXPR _hmfnet_next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), \
python3 (<< ${Python3_VERSION_MAJOR}.${_hmfnet_next_minor}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "python3-scipy, python3-networkx, python3-h5py, python3-matplotlib, libeigen3-dev, libboost-math-dev, libhdf5-dev, libopenmpi-dev, nlohmann-json3-dev, libcli11-dev, libtrilinos-tpetra-dev, libtrilinos-anasazi-dev, libtrilinos-zoltan2-dev, libptscotch-dev")
include(CPack)
