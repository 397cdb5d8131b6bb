// The device's per-element arithmetic against the host's (dynamics/kernel_arithmetic.hpp), bit
// for bit: a CUDA kernel (dynamics/cuda/device_arithmetic_check.cu) evaluates sincos, the kick
// and the drift on device arrays, and every result is compared with the same function run here.
// tests/dynamics/test_kernel_arithmetic.cpp ties these host functions to the CPU kernels, so
// equal bits here mean the device reproduces the CPU. Beyond k_reduced_range the device takes
// CUDA's sincos, not glibc's: there only closeness is required.
//
// Runs where a CUDA device can run this build's code; elsewhere it prints why and exits with
// k_skipped, which tests/gpu/CMakeLists.txt declares as CTest's SKIP_RETURN_CODE.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cuda/device.hpp"
#include "dynamics/cuda/device_arithmetic_check.hpp"
#include "dynamics/kernel_arithmetic.hpp"
#include "support/catch_session.hpp"

#if !defined(HMFNET_HAVE_CUDA)
#error "hmfnet_cuda's consumers see HMFNET_HAVE_CUDA=1 (src/CMakeLists.txt)"
#endif

using namespace hmfnet;

namespace {

constexpr int k_skipped = 77;

std::uint64_t bits_of(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Equal bits; NaNs only as NaN (a GPU returns its canonical NaN where x86 keeps the operand's).
bool same(double a, double b) {
  return bits_of(a) == bits_of(b) || (std::isnan(a) && std::isnan(b));
}

// Random angles in +-100, the doubles nearest k pi/2 (k < 2000, then growing by 1% to |x| ~
// 10^7: the cases test_sincos.cpp calls hard), and values beyond the reduced range.
std::vector<double> check_angles() {
  std::mt19937_64 rng(90);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  std::vector<double> x(100000);
  for (auto& v : x) v = u(rng);
  const long double half_pi = 1.5707963267948966192313216916397514L;
  for (double k = 1.0; k < 6.3e6; k = k < 2000.0 ? k + 1.0 : std::ceil(k * 1.01)) {
    const auto nearest = static_cast<double>(static_cast<long double>(k) * half_pi);
    for (const double v : {nearest, std::nextafter(nearest, 0.0), std::nextafter(nearest, 1e9)}) {
      x.push_back(v);
      x.push_back(-v);
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (const double v : {k_reduced_range, std::nextafter(k_reduced_range, inf), -1e8, 1e300, inf,
                         -inf, std::numeric_limits<double>::quiet_NaN()})
    x.push_back(v);
  return x;
}

}  // namespace

TEST_CASE("device sincos, kick and drift equal the host's bit for bit [10^5 angles, hard cases]",
          "[gpu][arithmetic]") {
  cuda::ArithmeticCheckInput in;
  in.theta = check_angles();
  std::mt19937_64 rng(91);
  std::normal_distribution<double> momentum(6.0, 1.0);
  std::uniform_real_distribution<double> force(-1.0, 1.0);
  for (std::size_t k = 0; k < in.theta.size(); ++k) {
    in.p.push_back(momentum(rng));
    in.g.push_back(force(rng));
  }
  in.c_kick = 0.5 * 0.05;  // leap-frog's half kick at h = 0.05
  in.coupling = 2.5;
  in.c_drift = 0.05;
  cuda::ArithmeticCheckOutput out;
  std::string message;
  const bool ran = cuda::run_arithmetic_check(in, out, message);
  INFO(message);
  REQUIRE(ran);
  std::size_t differ = 0, beyond = 0;
  double largest_beyond = 0.0;
  for (std::size_t k = 0; k < in.theta.size(); ++k) {
    const double x = in.theta[k];
    double c = 0.0, s = 0.0;
    sincos_one(x, c, s);
    const double p = kicked_momentum(in.p[k], in.c_kick, in.coupling, in.g[k]);
    const double theta = drifted_angle(x, in.c_drift, p);
    const bool kick_drift_same = same(out.p[k], p) && same(out.theta[k], theta);
    if (sincos_reduces(x)) {
      if (!kick_drift_same || !same(out.cs[2 * k], c) || !same(out.cs[2 * k + 1], s)) {
        if (differ++ == 0) {
          UNSCOPED_INFO("first difference: angle " << std::hexfloat << x << ": cos " << c
                                                   << " host, " << out.cs[2 * k] << " device; sin "
                                                   << s << ", " << out.cs[2 * k + 1]);
        }
      }
      continue;
    }
    // CUDA's sin and cos are within 2 ulp (CUDA C++ Programming Guide, mathematical functions),
    // glibc's within 1: the two differ by at most 3 ulp of a value below 1, < 4 DBL_EPSILON.
    ++beyond;
    const bool finite = std::isfinite(x);
    const double gap =
        finite ? std::max(std::abs(out.cs[2 * k] - c), std::abs(out.cs[2 * k + 1] - s)) : 0.0;
    largest_beyond = std::max(largest_beyond, gap);
    CHECK(kick_drift_same);
    CHECK(std::isnan(out.cs[2 * k]) == !finite);
    CHECK(gap <= 4.0 * DBL_EPSILON);
  }
  INFO(in.theta.size() << " angles, " << beyond << " beyond the reduced range (largest gap "
                       << largest_beyond << ")");
  CHECK(differ == 0);
}

int main(int argc, char* argv[]) {
  std::string why;
  if (!cuda::device_usable(why)) {
    std::cout << "hmfnet_gpu_tests: skipped: " << why << '\n';
    return k_skipped;
  }
  return hmfnet::test::run_catch_session(argc, argv);
}
