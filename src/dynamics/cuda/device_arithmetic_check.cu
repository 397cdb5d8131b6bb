// Launches and memory of the arithmetic check (device_arithmetic_check.hpp); the arithmetic
// itself is dynamics/kernel_arithmetic.hpp's, the same functions the CPU tests exercise. This
// file is compiled with --fmad=false (src/CMakeLists.txt): kernel_arithmetic.hpp says why.
#include <cuda_runtime.h>

#include <cstddef>
#include <string>

#include "dynamics/cuda/device.hpp"
#include "dynamics/cuda/device_arithmetic_check.hpp"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

// One thread per element.
__global__ void arithmetic_kernel(const double* theta, const double* p, const double* g,
                                  std::size_t n, double c_kick, double coupling, double c_drift,
                                  double* cs, double* p_out, double* theta_out) {
  const std::size_t k = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= n) return;
  sincos_one(theta[k], cs[2 * k], cs[2 * k + 1]);
  const double kicked = kicked_momentum(p[k], c_kick, coupling, g[k]);
  p_out[k] = kicked;
  theta_out[k] = drifted_angle(theta[k], c_drift, kicked);
}

// A device array of doubles, freed on every way out.
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  ~DeviceArray() {
    if (m_data != nullptr) cudaFree(m_data);
  }
  cudaError_t allocate(std::size_t n) {
    return cudaMalloc(reinterpret_cast<void**>(&m_data), n * sizeof(double));
  }
  double* data() const { return m_data; }

 private:
  double* m_data = nullptr;
};

// True (and the message set) when `status` is an error.
bool failed(cudaError_t status, const char* what, std::string& message) {
  if (status == cudaSuccess) return false;
  message = std::string(what) + ": " + cudaGetErrorString(status);
  return true;
}

bool to_device(DeviceArray& device, const std::vector<double>& host, std::string& message) {
  return !failed(device.allocate(host.size()), "cudaMalloc", message) &&
         !failed(cudaMemcpy(device.data(), host.data(), host.size() * sizeof(double),
                            cudaMemcpyHostToDevice),
                 "cudaMemcpy to the device", message);
}

bool to_host(std::vector<double>& host, const DeviceArray& device, std::size_t n,
             std::string& message) {
  host.resize(n);
  return !failed(cudaMemcpy(host.data(), device.data(), n * sizeof(double), cudaMemcpyDeviceToHost),
                 "cudaMemcpy to the host", message);
}

}  // namespace

bool run_arithmetic_check(const ArithmeticCheckInput& in, ArithmeticCheckOutput& out,
                          std::string& message) {
  const std::size_t n = in.theta.size();
  if (in.p.size() != n || in.g.size() != n) {
    message = "arithmetic check: theta, p and g must have one length";
    return false;
  }
  if (!device_usable(message)) return false;
  DeviceArray theta, p, g, cs, p_out, theta_out;
  if (!to_device(theta, in.theta, message) || !to_device(p, in.p, message) ||
      !to_device(g, in.g, message) || failed(cs.allocate(2 * n), "cudaMalloc", message) ||
      failed(p_out.allocate(n), "cudaMalloc", message) ||
      failed(theta_out.allocate(n), "cudaMalloc", message)) {
    return false;
  }
  constexpr unsigned k_threads = 256;
  if (n > 0) {
    const auto blocks = static_cast<unsigned>((n + k_threads - 1) / k_threads);
    arithmetic_kernel<<<blocks, k_threads>>>(theta.data(), p.data(), g.data(), n, in.c_kick,
                                             in.coupling, in.c_drift, cs.data(), p_out.data(),
                                             theta_out.data());
    if (failed(cudaGetLastError(), "arithmetic kernel launch", message) ||
        failed(cudaDeviceSynchronize(), "arithmetic kernel", message)) {
      return false;
    }
  }
  return to_host(out.cs, cs, 2 * n, message) && to_host(out.p, p_out, n, message) &&
         to_host(out.theta, theta_out, n, message);
}

}  // namespace hmfnet::cuda
