#pragma once
// What every CUDA file of the backend shares: a CUDA call's status turned into DeviceError, a
// device array freed on every way out, and the device check of this build's code.
#include <cuda_runtime.h>

#include <cstddef>
#include <string>
#include <utility>

#include "dynamics/cuda/device.hpp"

namespace hmfnet::cuda {

/// Throws DeviceError naming `what` and CUDA's message when `status` is an error.
inline void check(cudaError_t status, const char* what) {
  if (status != cudaSuccess) {
    throw DeviceError(std::string(what) + ": " + cudaGetErrorString(status));
  }
}

/// After a launch: its configuration error at once (the kernel's own errors come at the next
/// synchronisation).
inline void check_launch(const char* kernel) { check(cudaGetLastError(), kernel); }

/// A device array of n T, freed on every way out; moved, never copied.
template <typename T>
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(std::size_t n) { allocate(n); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& other) noexcept
      : m_data(std::exchange(other.m_data, nullptr)), m_size(std::exchange(other.m_size, 0)) {}
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept {
    std::swap(m_data, other.m_data);
    std::swap(m_size, other.m_size);
    return *this;
  }
  ~DeviceBuffer() {
    if (m_data != nullptr) cudaFree(m_data);
  }
  void allocate(std::size_t n) {
    if (m_data != nullptr) cudaFree(m_data);
    m_data = nullptr;
    m_size = 0;
    if (n == 0) return;
    check(cudaMalloc(reinterpret_cast<void**>(&m_data), n * sizeof(T)), "cudaMalloc");
    m_size = n;
  }
  void upload(const T* host, std::size_t n) {
    if (n != m_size) allocate(n);
    if (n > 0) {
      check(cudaMemcpy(m_data, host, n * sizeof(T), cudaMemcpyHostToDevice),
            "cudaMemcpy to the device");
    }
  }
  void download(T* host, std::size_t n) const {
    if (n > 0) {
      check(cudaMemcpy(host, m_data, n * sizeof(T), cudaMemcpyDeviceToHost),
            "cudaMemcpy to the host");
    }
  }
  T* data() const { return m_data; }
  std::size_t size() const { return m_size; }

 private:
  T* m_data = nullptr;
  std::size_t m_size = 0;
};

/// Blocks of `threads` covering n items.
inline unsigned blocks_for(std::size_t n, int threads) {
  return static_cast<unsigned>((n + static_cast<std::size_t>(threads) - 1) /
                               static_cast<std::size_t>(threads));
}

/// Throws DeviceError unless the current device can run this build (device_usable).
void require_device();

/// Throws DeviceError naming the bytes needed and free when `needed` exceeds the free memory.
void require_memory(std::size_t needed, const char* what);

}  // namespace hmfnet::cuda
