// The device's sparse step against the CPU's (host_ensemble.hpp, the CPU's arithmetic in its
// order): bit for bit in float64 and float32, with a K per replica; the same bits run to run
// and whatever the threads per block; a run moved between device and host mid-way (the state
// a checkpoint holds) goes on with the same bits both ways; each step's order sums and a
// record's sums (what simulate --device cuda reads back) are the CPU's bits; the energy error falls
// as h^2 (leap-frog) and h^4 (yoshida4); float32's energy error against float64's; memory refused
// before anything is allocated.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cuda/sparse_ensemble.hpp"
#include "host_ensemble.hpp"

using namespace hmfnet;
using hmfnet::gpu_test::differing;
using hmfnet::gpu_test::HostEnsemble;

namespace {

constexpr std::size_t k_replicas = 3;

const cuda::HostCsr& test_network() {
  static const cuda::HostCsr net = gpu_test::random_network(1500, 12.0, 5);
  return net;
}

// The test network with weights A_nm in [0.5, 2] drawn from `seed` (symmetric pairs need not be:
// the force reads rows).
cuda::HostCsr weighted_network(std::uint64_t seed) {
  cuda::HostCsr net = test_network();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  for (std::size_t k = 0; k < net.columns.size(); ++k) net.weights.push_back(weight(rng));
  return net;
}

struct Start {
  std::vector<double> theta, p, K;
};

Start start(std::int64_t n) {
  Start s;
  gpu_test::waterbag(n, static_cast<int>(k_replicas), 0.6, 11, s.theta, s.p);
  s.K = {1.0, 2.5, 6.0};  // one K per replica (--K-across-replicas)
  return s;
}

// The device run: `steps` steps of `c` from the start.
void device_run(cuda::DevicePrecision precision, int threads, const SplittingCoefficients& c,
                double h, std::int64_t steps, std::vector<double>& theta, std::vector<double>& p) {
  const Start s = start(test_network().rows);
  cuda::SparseEnsemble e(test_network(), static_cast<int>(k_replicas), precision, threads);
  e.set_coupling(s.K);
  e.set_state(s.theta, s.p);
  e.advance(c, h, steps);
  e.get_state(theta, p);
}

HostEnsemble host_run(bool float32, const SplittingCoefficients& c, double h, std::int64_t steps) {
  const Start s = start(test_network().rows);
  HostEnsemble host(test_network(), static_cast<int>(k_replicas), float32);
  host.K = s.K;
  host.set_state(s.theta, s.p);
  host.advance(c, h, steps);
  return host;
}

// Max over replicas and records of |H(t) - H(0)| / |H(0)|, on the device, over T = 20 with
// `h`: each replica's H from the ordered sums.
double energy_error(cuda::DevicePrecision precision, const SplittingCoefficients& c, double h) {
  const Start s = start(test_network().rows);
  cuda::SparseEnsemble e(test_network(), static_cast<int>(k_replicas), precision);
  e.set_coupling(s.K);
  e.set_state(s.theta, s.p);
  const double n = static_cast<double>(test_network().rows);
  const auto energy = [&] {
    const cuda::EnsembleSums sums = e.sums();
    std::vector<double> H;
    for (std::size_t b = 0; b < k_replicas; ++b) {
      H.push_back(sums.kinetic[b] - s.K[b] / (2.0 * n) * sums.coupling[b]);
    }
    return H;
  };
  const std::vector<double> H0 = energy();
  double worst = 0.0;
  const auto per_record = static_cast<std::int64_t>(std::lround(1.0 / h));
  for (int record = 0; record < 20; ++record) {
    e.advance(c, h, per_record);
    const std::vector<double> H = energy();
    for (std::size_t b = 0; b < k_replicas; ++b)
      worst = std::max(worst, std::abs(H[b] - H0[b]) / std::abs(H0[b]));
  }
  return worst;
}

}  // namespace

TEST_CASE("float64 device steps are the CPU's bits over 100 leap-frog steps, a K per replica",
          "[gpu][sparse]") {
  std::vector<double> theta, p;
  device_run(cuda::DevicePrecision::float64, 256, leap_frog_coefficients(), 0.05, 100, theta, p);
  const HostEnsemble host = host_run(false, leap_frog_coefficients(), 0.05, 100);
  CHECK(differing(theta, host.theta) == 0);
  CHECK(differing(p, host.p) == 0);
}

TEST_CASE("float32 device steps are the CPU's float32 bits, and yoshida4 and blanes_moan too",
          "[gpu][sparse]") {
  std::vector<double> theta, p;
  device_run(cuda::DevicePrecision::float32, 256, leap_frog_coefficients(), 0.05, 100, theta, p);
  const HostEnsemble host = host_run(true, leap_frog_coefficients(), 0.05, 100);
  CHECK(differing(theta, host.theta) == 0);
  CHECK(differing(p, host.p) == 0);
  for (const auto& c : {yoshida4_coefficients(), blanes_moan4_coefficients()}) {
    device_run(cuda::DevicePrecision::float64, 128, c, 0.1, 30, theta, p);
    const HostEnsemble h = host_run(false, c, 0.1, 30);
    CHECK(differing(theta, h.theta) == 0);
    CHECK(differing(p, h.p) == 0);
  }
}

TEST_CASE("a weighted network's device steps are the CPU's bits, float64 and float32",
          "[gpu][sparse]") {
  // float32 narrows the weights as network_force.cpp does.
  const cuda::HostCsr net = weighted_network(13);
  const Start s = start(net.rows);
  for (const bool float32 : {false, true}) {
    cuda::SparseEnsemble e(
        net, static_cast<int>(k_replicas),
        float32 ? cuda::DevicePrecision::float32 : cuda::DevicePrecision::float64);
    e.set_coupling(s.K);
    e.set_state(s.theta, s.p);
    HostEnsemble host(net, static_cast<int>(k_replicas), float32);
    host.K = s.K;
    host.set_state(s.theta, s.p);
    std::vector<double> device_order, host_order;
    e.advance(leap_frog_coefficients(), 0.05, 50, &device_order);
    host.advance(leap_frog_coefficients(), 0.05, 50, &host_order);
    std::vector<double> theta, p;
    e.get_state(theta, p);
    INFO((float32 ? "float32" : "float64"));
    CHECK(differing(theta, host.theta) == 0);
    CHECK(differing(p, host.p) == 0);
    CHECK(differing(device_order, host_order) == 0);
    CHECK(differing(e.sums().coupling, host.sums().coupling) == 0);
  }
}

TEST_CASE("the same bits run to run and for 64, 256 and 1024 threads per block", "[gpu][sparse]") {
  std::vector<double> t0, p0, t1, p1;
  device_run(cuda::DevicePrecision::float64, 256, yoshida4_coefficients(), 0.05, 200, t0, p0);
  for (const int threads : {256, 64, 1024}) {
    device_run(cuda::DevicePrecision::float64, threads, yoshida4_coefficients(), 0.05, 200, t1, p1);
    CHECK(differing(t0, t1) == 0);
    CHECK(differing(p0, p1) == 0);
  }
}

TEST_CASE("a run moved device -> host and host -> device mid-way keeps its bits", "[gpu][sparse]") {
  const auto lf = leap_frog_coefficients();
  const HostEnsemble whole = host_run(false, lf, 0.05, 60);
  const Start s = start(test_network().rows);
  // Device for 30 steps, then the host from the device's state (a GPU checkpoint resumed on
  // the CPU).
  cuda::SparseEnsemble e(test_network(), static_cast<int>(k_replicas),
                         cuda::DevicePrecision::float64);
  e.set_coupling(s.K);
  e.set_state(s.theta, s.p);
  e.advance(lf, 0.05, 30);
  std::vector<double> theta, p;
  e.get_state(theta, p);
  HostEnsemble host(test_network(), static_cast<int>(k_replicas), false);
  host.K = s.K;
  host.set_state(theta, p);
  host.advance(lf, 0.05, 30);
  CHECK(differing(host.theta, whole.theta) == 0);
  CHECK(differing(host.p, whole.p) == 0);
  // The host for 30 steps, then the device (a CPU checkpoint resumed on the GPU).
  const HostEnsemble first = host_run(false, lf, 0.05, 30);
  e.set_state(first.theta, first.p);
  e.advance(lf, 0.05, 30);
  e.get_state(theta, p);
  CHECK(differing(theta, whole.theta) == 0);
  CHECK(differing(p, whole.p) == 0);
}

TEST_CASE(
    "each step's order sums and a record's five sums are the CPU's bits, in chunks, over three "
    "sum blocks",
    "[gpu][sparse]") {
  // What `hmfnet simulate --device cuda` reads back (device_stepper.cpp): per step sum_n |y_n|
  // for the time average, at a record the sums of the observables, both in OrderedColumnSums'
  // order (N = 4500: three 2048-row blocks), across chunks of several lengths.
  const cuda::HostCsr net = gpu_test::random_network(4500, 8.0, 17);
  std::vector<double> theta, p;
  gpu_test::waterbag(net.rows, static_cast<int>(k_replicas), 0.6, 3, theta, p);
  const std::vector<double> K = {2.0, 3.5, 5.0};
  for (const bool float32 : {false, true}) {
    cuda::SparseEnsemble e(
        net, static_cast<int>(k_replicas),
        float32 ? cuda::DevicePrecision::float32 : cuda::DevicePrecision::float64);
    e.set_coupling(K);
    e.set_state(theta, p);
    HostEnsemble host(net, static_cast<int>(k_replicas), float32);
    host.K = K;
    host.set_state(theta, p);
    std::vector<double> device_order, host_order;
    for (const std::int64_t chunk : {1, 7, 3, 20}) {
      e.advance(yoshida4_coefficients(), 0.05, chunk, &device_order);
      host.advance(yoshida4_coefficients(), 0.05, chunk, &host_order);
      e.advance(yoshida4_coefficients(), 0.05, chunk);  // no sums asked: the same steps
      host.advance(yoshida4_coefficients(), 0.05, chunk);
    }
    INFO((float32 ? "float32" : "float64"));
    REQUIRE(device_order.size() == 31 * k_replicas);
    CHECK(differing(device_order, host_order) == 0);
    const cuda::EnsembleSums d = e.sums();
    const cuda::EnsembleSums h = host.sums();
    CHECK(differing(d.order, h.order) == 0);
    CHECK(differing(d.coupling, h.coupling) == 0);
    CHECK(differing(d.kinetic, h.kinetic) == 0);
    CHECK(differing(d.momentum, h.momentum) == 0);
    CHECK(differing(d.momentum_scale, h.momentum_scale) == 0);
  }
}

TEST_CASE("the energy error falls as h^2 (leap-frog) and h^4 (yoshida4), float32 against float64",
          "[gpu][sparse]") {
  // Halving h divides a p-th order method's error by 2^p once h is in the asymptotic range.
  // Measured with the host stepper (the same arithmetic): leap-frog 3.763e-7 -> 9.408e-8 (order
  // 2.00), yoshida4 1.115e-10 -> 6.968e-12 (4.00) at h = 0.04 -> 0.02; the bands (+-0.3) are
  // for a device that would step differently, not for noise (the device has the host's bits).
  const double lf_coarse =
      energy_error(cuda::DevicePrecision::float64, leap_frog_coefficients(), 0.04);
  const double lf_fine =
      energy_error(cuda::DevicePrecision::float64, leap_frog_coefficients(), 0.02);
  const double y_coarse =
      energy_error(cuda::DevicePrecision::float64, yoshida4_coefficients(), 0.04);
  const double y_fine = energy_error(cuda::DevicePrecision::float64, yoshida4_coefficients(), 0.02);
  const double lf_order = std::log2(lf_coarse / lf_fine);
  const double y_order = std::log2(y_coarse / y_fine);
  INFO("leap-frog " << lf_coarse << " -> " << lf_fine << " (order " << lf_order << "); yoshida4 "
                    << y_coarse << " -> " << y_fine << " (order " << y_order << ")");
  CHECK(std::abs(lf_order - 2.0) < 0.3);
  CHECK(std::abs(y_order - 4.0) < 0.3);
  // float32 rounds each gathered [cos, sin] to float (relative 6e-8), far below the splitting's
  // error at h = 0.02: the host measured 9.394e-8 against float64's 9.408e-8 (0.15% apart).
  const double f32 = energy_error(cuda::DevicePrecision::float32, leap_frog_coefficients(), 0.02);
  INFO("float32 leap-frog h = 0.02: " << f32 << ", float64 " << lf_fine);
  CHECK(std::abs(f32 - lf_fine) < 0.01 * lf_fine);
}

TEST_CASE("device memory is checked before anything is allocated", "[gpu][sparse]") {
  // N = 2 10^9 rows do not fit (int32 columns alone: 8 10^11 bytes at degree 100).
  try {
    cuda::SparseEnsemble::directed_er(2000000000, 100.0, 1, 1, cuda::DevicePrecision::float64);
    FAIL("no refusal");
  } catch (const cuda::DeviceError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("bytes of device memory") != std::string::npos);
    CHECK(what.find("are free") != std::string::npos);
  }
}

TEST_CASE("the directed ER generator draws G(N, p): its entry count", "[gpu][sparse]") {
  cuda::SparseEnsemble e =
      cuda::SparseEnsemble::directed_er(100000, 50.0, 3, 1, cuda::DevicePrecision::float64);
  // Binomial(N^2, p): mean 5 10^6, sd ~2236; 6 sd.
  CHECK(std::abs(static_cast<double>(e.entries()) - 5e6) < 6.0 * 2236.0);
}

TEST_CASE("one or four threads a row: the CPU's bits, one replica and three, weighted or not",
          "[gpu][sparse]") {
  // The four threads sum the row's quarters as row_field's four partials and combine them in its
  // order (sparse_ensemble.cu's force_kernel_split); rows of 0 to ~30 entries end in every tail.
  const cuda::HostCsr weighted = weighted_network(29);
  const std::array<const cuda::HostCsr*, 2> networks = {&test_network(), &weighted};
  for (const cuda::HostCsr* net : networks) {
    for (const int replicas : {1, 3}) {
      for (const bool float32 : {false, true}) {
        std::vector<double> theta0, p0;
        gpu_test::waterbag(net->rows, replicas, 0.6, 17, theta0, p0);
        HostEnsemble host(*net, replicas, float32);
        host.set_state(theta0, p0);
        std::vector<double> host_order;
        host.advance(leap_frog_coefficients(), 0.05, 40, &host_order);
        for (const int per_row : {1, 4}) {
          INFO((net->weights.empty() ? "0/1" : "weighted")
               << ", " << replicas << " replicas, " << (float32 ? "float32" : "float64") << ", "
               << per_row << " threads a row");
          cuda::SparseEnsemble e(
              *net, replicas,
              float32 ? cuda::DevicePrecision::float32 : cuda::DevicePrecision::float64, 128);
          CHECK(e.threads_per_row() == (replicas == 1 ? 4 : 1));
          e.set_threads_per_row(per_row);
          e.keep_fields();  // node data: each cell's y_n kept by both kernels
          e.set_state(theta0, p0);
          std::vector<double> order, theta, p, y;
          e.advance(leap_frog_coefficients(), 0.05, 40, &order);
          e.get_state(theta, p);
          e.fields(y);
          CHECK(differing(theta, host.theta) == 0);
          CHECK(differing(p, host.p) == 0);
          CHECK(differing(order, host_order) == 0);
          CHECK(differing(y, host.fields()) == 0);
          CHECK(differing(e.sums().coupling, host.sums().coupling) == 0);
        }
      }
    }
  }
  cuda::SparseEnsemble e(test_network(), 1, cuda::DevicePrecision::float64);
  CHECK_THROWS_AS(e.set_threads_per_row(2), cuda::DeviceError);
  std::vector<double> y;
  CHECK_THROWS_AS(e.fields(y), cuda::DeviceError);  // not kept
  e.keep_fields();
  CHECK_THROWS_AS(e.fields(y), cuda::DeviceError);  // no state yet
  // Kept once a state is set: current at once, and after a record's sums.
  std::vector<double> theta0, p0;
  gpu_test::waterbag(test_network().rows, 1, 0.6, 19, theta0, p0);
  cuda::SparseEnsemble late(test_network(), 1, cuda::DevicePrecision::float64);
  late.set_state(theta0, p0);
  late.advance(leap_frog_coefficients(), 0.05, 7);
  late.keep_fields();
  HostEnsemble host(test_network(), 1, false);
  host.set_state(theta0, p0);
  host.advance(leap_frog_coefficients(), 0.05, 7);
  late.fields(y);
  CHECK(differing(y, host.fields()) == 0);
  static_cast<void>(late.sums());
  late.fields(y);
  CHECK(differing(y, host.fields()) == 0);
}
