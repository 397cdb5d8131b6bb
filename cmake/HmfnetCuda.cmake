# Optional CUDA: the device backend (src/dynamics/cuda, library hmfnet_cuda) is built when CMake
# finds a CUDA compiler, and the rest of the build is the same either way.
#   HMFNET_CUDA               ON by default when nvcc is found; -DHMFNET_CUDA=OFF skips even the
#                             search. ON without a compiler is an error.
#   CMAKE_CUDA_ARCHITECTURES  90-real;90-virtual unless given: sm_90 code for the H100 and H200,
#                             and PTX for 9.0 that the driver compiles for a newer card.
# nvcc compiles the host side with the C++ compiler of the rest of the build.
include(CheckLanguage)

if(NOT DEFINED HMFNET_CUDA OR HMFNET_CUDA)
  check_language(CUDA)
endif()
# check_language leaves a compiler given on the command line unchecked: one that is not there
# counts as none found.
set(_hmfnet_cuda_found OFF)
if(CMAKE_CUDA_COMPILER AND NOT (IS_ABSOLUTE "${CMAKE_CUDA_COMPILER}"
                                AND NOT EXISTS "${CMAKE_CUDA_COMPILER}"))
  set(_hmfnet_cuda_found ON)
endif()
option(HMFNET_CUDA "Build the CUDA device backend (src/dynamics/cuda)" ${_hmfnet_cuda_found})

if(NOT HMFNET_CUDA)
  message(STATUS "CUDA backend: off (HMFNET_CUDA=OFF or no CUDA compiler found)")
  return()
endif()
if(NOT _hmfnet_cuda_found)
  message(FATAL_ERROR "HMFNET_CUDA=ON but no CUDA compiler was found (CMAKE_CUDA_COMPILER="
                      "'${CMAKE_CUDA_COMPILER}'): put nvcc on the PATH, or configure with "
                      "-DHMFNET_CUDA=OFF")
endif()

if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
  set(CMAKE_CUDA_ARCHITECTURES "90-real;90-virtual")
endif()
if(NOT CMAKE_CUDA_HOST_COMPILER)
  set(CMAKE_CUDA_HOST_COMPILER "${CMAKE_CXX_COMPILER}")
endif()
set(CMAKE_CUDA_STANDARD 17)
set(CMAKE_CUDA_STANDARD_REQUIRED ON)
set(CMAKE_CUDA_EXTENSIONS OFF)
enable_language(CUDA)
find_package(CUDAToolkit REQUIRED)
message(STATUS "CUDA backend: nvcc ${CMAKE_CUDA_COMPILER_VERSION}, architectures "
               "${CMAKE_CUDA_ARCHITECTURES}")

# Options for hmfnet's own CUDA files: the host compiler's warnings of cmake/HmfnetWarnings.cmake
# (nvcc takes them through -Xcompiler, not as its own), and with HMFNET_WERROR nvcc's own
# warnings too as errors. --fmad=false: no multiply-add is fused, so that the device computes the
# CPU's operations (src/dynamics/kernel_arithmetic.hpp says why this flag and not intrinsics).
set(HMFNET_CUDA_OPTIONS
    --fmad=false -Xcompiler=-Wall,-Wextra,-Wshadow,-Wconversion,-Wsign-conversion)
if(HMFNET_WERROR)
  list(APPEND HMFNET_CUDA_OPTIONS --Werror=all-warnings -Xcompiler=-Werror)
endif()
