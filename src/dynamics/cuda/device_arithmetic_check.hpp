#pragma once
// The device half of the arithmetic check (tests/gpu): the host-and-device functions of
// dynamics/kernel_arithmetic.hpp evaluated by a CUDA kernel on device arrays, so that a test can
// compare the device's bits with the host's. A plain C++ interface: no CUDA header reaches the
// caller, and the hmfnet_cuda library that implements it is built only where CMake finds nvcc
// (cmake/HmfnetCuda.cmake; its consumers see HMFNET_HAVE_CUDA=1).
#include <string>
#include <vector>

namespace hmfnet::cuda {

/// Per element k: [cos, sin] of theta[k], then the fused kick and drift of integrator.cpp's
/// kick_drift, p' = p + c_kick K g and theta' = theta + c_drift p'. theta, p and g have one
/// length.
struct ArithmeticCheckInput {
  std::vector<double> theta;
  std::vector<double> p;
  std::vector<double> g;
  double c_kick = 0.0;
  double coupling = 0.0;
  double c_drift = 0.0;
};

/// What the device computed: cs = [cos, sin] interleaved (2 per element), p', theta'.
struct ArithmeticCheckOutput {
  std::vector<double> cs;
  std::vector<double> p;
  std::vector<double> theta;
};

/// Runs the check on device 0: true with `out` filled, or false with `message` naming the CUDA
/// error (no device included). Lengths that differ are refused the same way.
bool run_arithmetic_check(const ArithmeticCheckInput& in, ArithmeticCheckOutput& out,
                          std::string& message);

}  // namespace hmfnet::cuda
