# The language and output defaults of every hmfnet build: the main project (CMakeLists.txt) and the
# device check's own (ci/device/CMakeLists.txt). C++17 without GNU extensions, Release unless told,
# executables in bin/, a compile database for clang-tidy, and the warnings-as-errors switch.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin)
set(CMAKE_EXPORT_COMPILE_COMMANDS ON)
option(HMFNET_WERROR "Treat warnings in hmfnet's own code as errors" OFF)
