// The device's rank-one step (rank_one_ensemble.hpp) against the CPU's (host_ensemble.hpp:
// rank_one_force.cpp's arithmetic in its order), K_N with and without self-loops and A = a a^T
// with a in [0.5, 1.5]: the state bit for bit over 100 leap-frog steps and 30 of yoshida4, a K
// per replica; each step's order sums, the fields y_n (node data) and a record's five sums bit
// for bit across chunks; the same bits for 64, 256 and 1024 threads per block and run to run.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "dynamics/cuda/rank_one_ensemble.hpp"
#include "host_ensemble.hpp"

using namespace hmfnet;
using hmfnet::gpu_test::differing;
using hmfnet::gpu_test::HostEnsemble;

namespace {

// N = 5000: three of the 2048-row blocks Z is summed by, the last ending in a part tile (904 =
// 7 x 128 + 8 rows of rank_one_ensemble.cu's tiles).
constexpr std::int64_t k_n = 5000;
constexpr int k_replicas = 3;

struct Run {
  std::vector<double> theta, p, order, fields;
  cuda::EnsembleSums sums;
};

// 1, 2.5, 6 repeated over the replicas.
std::vector<double> couplings(int replicas) {
  std::vector<double> K(static_cast<std::size_t>(replicas));
  for (std::size_t b = 0; b < K.size(); ++b) K[b] = std::array<double, 3>{1.0, 2.5, 6.0}[b % 3];
  return K;
}

// a_n: 1 (K_N), or in [0.5, 1.5] (the disordered HMF, A = a a^T).
std::vector<double> weights(bool disordered) {
  std::vector<double> a(k_n, 1.0);
  if (!disordered) return a;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  for (double& x : a) x = spread(rng);
  return a;
}

// `steps` steps of `c` in the given chunks (the order sums of every step), on the device.
Run device_run(bool self_loops, int threads, const SplittingCoefficients& c, double h,
               const std::vector<std::int64_t>& chunks, bool disordered = false,
               int replicas = k_replicas) {
  std::vector<double> theta, p;
  gpu_test::waterbag(k_n, replicas, 0.6, 21, theta, p);
  cuda::RankOneEnsemble e(weights(disordered), self_loops, replicas, threads);
  e.set_coupling(couplings(replicas));
  e.keep_fields();  // node data's y_n, compared too
  e.set_state(theta, p);
  Run r;
  for (const std::int64_t chunk : chunks) e.advance(c, h, chunk, &r.order);
  e.get_state(r.theta, r.p);
  e.fields(r.fields);
  r.sums = e.sums();
  return r;
}

Run host_run(bool self_loops, const SplittingCoefficients& c, double h, std::int64_t steps,
             bool disordered = false, int replicas = k_replicas) {
  std::vector<double> theta, p;
  gpu_test::waterbag(k_n, replicas, 0.6, 21, theta, p);
  auto host = HostEnsemble::rank_one(weights(disordered), replicas, self_loops);
  host.K = couplings(replicas);
  host.set_state(theta, p);
  Run r;
  host.advance(c, h, steps, &r.order);
  r.theta = host.theta;
  r.p = host.p;
  r.fields = host.fields();
  r.sums = host.sums();
  return r;
}

void require_same(const Run& a, const Run& b) {
  CHECK(differing(a.theta, b.theta) == 0);
  CHECK(differing(a.p, b.p) == 0);
  CHECK(differing(a.order, b.order) == 0);
  CHECK(differing(a.fields, b.fields) == 0);
  CHECK(differing(a.sums.order, b.sums.order) == 0);
  CHECK(differing(a.sums.coupling, b.sums.coupling) == 0);
  CHECK(differing(a.sums.kinetic, b.sums.kinetic) == 0);
  CHECK(differing(a.sums.momentum, b.sums.momentum) == 0);
  CHECK(differing(a.sums.momentum_scale, b.sums.momentum_scale) == 0);
}

}  // namespace

TEST_CASE("the rank-one device step is the CPU's bits: K_N with and without self-loops",
          "[gpu][rank_one]") {
  for (const bool self_loops : {true, false}) {
    INFO("self-loops " << self_loops);
    require_same(device_run(self_loops, 256, leap_frog_coefficients(), 0.1, {1, 40, 59}),
                 host_run(self_loops, leap_frog_coefficients(), 0.1, 100));
    require_same(device_run(self_loops, 256, yoshida4_coefficients(), 0.1, {30}),
                 host_run(self_loops, yoshida4_coefficients(), 0.1, 30));
    INFO("a in [0.5, 1.5]");
    require_same(device_run(self_loops, 256, leap_frog_coefficients(), 0.1, {13, 37}, true),
                 host_run(self_loops, leap_frog_coefficients(), 0.1, 50, true));
  }
}

TEST_CASE("the rank-one device step: the same bits for 64, 256 and 1024 threads and run to run",
          "[gpu][rank_one]") {
  const Run first = device_run(false, 256, yoshida4_coefficients(), 0.05, {50});
  for (const int threads : {256, 64, 1024}) {
    INFO(threads << " threads per block");
    require_same(device_run(false, threads, yoshida4_coefficients(), 0.05, {50}), first);
  }
}

TEST_CASE("the rank-one device step: 19 replicas, Z's kernel in two groups of replicas",
          "[gpu][rank_one]") {
  // rank_one_ensemble.cu sums Z for up to 16 replicas per CUDA block: 19 makes a full group and
  // a part one.
  require_same(device_run(true, 256, leap_frog_coefficients(), 0.1, {7, 13}, true, 19),
               host_run(true, leap_frog_coefficients(), 0.1, 20, true, 19));
}
