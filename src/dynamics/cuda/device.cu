// The device's checks and description (device.hpp, device_buffer.cuh).
#include <cuda_runtime.h>

#include <string>

#include "dynamics/cuda/device.hpp"
#include "dynamics/cuda/device_buffer.cuh"

namespace hmfnet::cuda {

namespace {

int current_device() {
  int device = 0;
  check(cudaGetDevice(&device), "cudaGetDevice");
  return device;
}

}  // namespace

int device_count() {
  int count = 0;
  return cudaGetDeviceCount(&count) == cudaSuccess ? count : 0;
}

void use_device(int index) {
  const int count = device_count();
  if (index < 0 || index >= count) {
    throw DeviceError("CUDA device " + std::to_string(index) + " does not exist (" +
                      std::to_string(count) + " found)");
  }
  check(cudaSetDevice(index), "cudaSetDevice");
}

bool device_usable(std::string& why) {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess || count == 0) {
    why = std::string("no CUDA device: ") +
          (status != cudaSuccess ? cudaGetErrorString(status) : "none found");
    return false;
  }
  cudaDeviceProp properties{};
  int device = 0;
  if (cudaGetDevice(&device) != cudaSuccess ||
      cudaGetDeviceProperties(&properties, device) != cudaSuccess) {
    why = "cudaGetDeviceProperties failed";
    return false;
  }
  // The build carries sm_90 code and PTX for 9.0 (cmake/HmfnetCuda.cmake).
  if (properties.major < 9) {
    why = std::string("CUDA device ") + properties.name + " (compute capability " +
          std::to_string(properties.major) + "." + std::to_string(properties.minor) +
          ") has no code in this build (built for 9.0 and newer)";
    return false;
  }
  return true;
}

std::string device_description() {
  cudaDeviceProp pr{};
  check(cudaGetDeviceProperties(&pr, current_device()), "cudaGetDeviceProperties");
  return std::string(pr.name) + ", " + std::to_string(pr.totalGlobalMem >> 20) + " MiB, " +
         std::to_string(pr.multiProcessorCount) + " SMs, L2 " +
         std::to_string(pr.l2CacheSize >> 20) + " MiB, compute capability " +
         std::to_string(pr.major) + "." + std::to_string(pr.minor);
}

void require_device() {
  std::string why;
  if (!device_usable(why)) throw DeviceError(why);
}

void require_memory(std::size_t needed, const char* what) {
  std::size_t free = 0, total = 0;
  check(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
  if (needed > free) {
    throw DeviceError(std::string(what) + " needs " + std::to_string(needed) +
                      " bytes of device memory, " + std::to_string(free) + " are free");
  }
}

}  // namespace hmfnet::cuda
