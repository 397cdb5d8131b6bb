// The device's complete-graph stepper against the CPU's rank-one step (host_ensemble.hpp):
// within 1e-12 over 100 leap-frog steps (Z is summed in another fixed order, so not the bits);
// the same bits run to run and whatever the threads per block; several systems in one launch
// equal each run alone; the records (mean R over an interval, the energy at its end) against
// the host's.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "dynamics/cuda/complete_graph_ensembles.hpp"
#include "host_ensemble.hpp"

using namespace hmfnet;

namespace {

constexpr int k_replicas = 4;
constexpr double k_h = 0.1;
// The water-bag at U = 0.69 (qss_lifetime.cpp): sigma0^2 = 2 U - 1.
const double k_sigma0 = std::sqrt(0.38);

struct Run {
  std::vector<double> theta, p;
  cuda::CompleteGraphRecords records;
};

// cluster: blocks per replica (0: the automatic choice); batch: rotors loaded together.
Run device_run(std::int64_t n, int threads, std::int64_t steps, std::int64_t record_every,
               int cluster = 0, int batch = 4) {
  std::vector<double> theta, p;
  gpu_test::waterbag(n, k_replicas, k_sigma0, 21, theta, p);
  cuda::CompleteGraphEnsembles e({{n, k_replicas, 1.0, record_every, steps / record_every}},
                                 threads, cluster);
  if (cluster > 0) REQUIRE(e.cluster_blocks() == cluster);
  e.set_batch(batch);
  e.set_state(0, theta, p);
  e.advance(leap_frog_coefficients(), k_h, {steps});
  Run r;
  e.get_state(0, r.theta, r.p);
  r.records = e.records(0);
  return r;
}

double largest_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double gap = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    gap = std::max(gap, std::abs(a[k] - b[k]) / std::max(1.0, std::abs(b[k])));
  }
  return gap;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// System `s` of `e` holds the state and records of `want`, bit for bit.
void check_same_run(const cuda::CompleteGraphEnsembles& e, std::size_t s, const Run& want) {
  std::vector<double> theta, p;
  e.get_state(s, theta, p);
  CHECK(same_bits(theta, want.theta));
  CHECK(same_bits(p, want.p));
  CHECK(same_bits(e.records(s).R_mean, want.records.R_mean));
  CHECK(same_bits(e.records(s).energy, want.records.energy));
}

}  // namespace

TEST_CASE("the complete graph on the device follows the CPU's step to 1e-12 over 100 steps",
          "[gpu][complete]") {
  // N = 9000: five of the CPU's 2048-row blocks; on the device tiles of 4 and 5 rotors, so that
  // complete_graph_ensembles.cu's batches of 4 loads and the rotors after them both run.
  const std::int64_t n = 9000;
  const Run d = device_run(n, 512, 100, 10);
  std::vector<double> theta, p;
  gpu_test::waterbag(n, k_replicas, k_sigma0, 21, theta, p);
  auto host = gpu_test::HostEnsemble::complete(n, k_replicas);
  host.set_state(theta, p);
  std::vector<double> R_host, H_host;
  for (int record = 0; record < 10; ++record) {
    double R_sum[k_replicas] = {};
    for (int s = 0; s < 10; ++s) {
      host.advance(leap_frog_coefficients(), k_h, 1);
      for (std::size_t b = 0; b < k_replicas; ++b) {
        R_sum[b] += std::hypot(host.z()[2 * b], host.z()[2 * b + 1]) / static_cast<double>(n);
      }
    }
    const std::vector<double> H = host.energy();
    for (int b = 0; b < k_replicas; ++b) {
      R_host.push_back(R_sum[b] / 10.0);
      H_host.push_back(H[static_cast<std::size_t>(b)]);
    }
  }
  const double gap = std::max(largest_gap(d.theta, host.theta), largest_gap(d.p, host.p));
  INFO("largest relative gap of theta and p: " << gap);
  CHECK(gap < 1e-12);
  REQUIRE(d.records.written == 10);
  constexpr auto replicas = static_cast<std::size_t>(k_replicas);
  for (std::size_t b = 0; b < replicas; ++b) {
    for (std::size_t i = 0; i < 10; ++i) {
      const double R = d.records.R_mean[b * 10 + i];
      const double H = d.records.energy[b * 10 + i];
      CHECK(std::abs(R - R_host[i * replicas + b]) < 1e-12);
      CHECK(std::abs(H - H_host[i * replicas + b]) < 1e-12 * static_cast<double>(n));
    }
  }
}

TEST_CASE("the complete graph's bits repeat run to run and for 128, 512 and 1024 threads",
          "[gpu][complete]") {
  const Run a = device_run(3000, 512, 200, 20);
  for (const int threads : {512, 128, 1024}) {
    const Run b = device_run(3000, threads, 200, 20);
    CHECK(same_bits(a.theta, b.theta));
    CHECK(same_bits(a.p, b.p));
    CHECK(same_bits(a.records.R_mean, b.records.R_mean));
  }
}

TEST_CASE("the complete graph's bits are the same for a replica on 1, 2, 4 and 8 blocks",
          "[gpu][complete]") {
  // N = 3000: 2048 tiles over the cluster's blocks (128 threads: 16 to 2 tiles a thread); the
  // tile sums travel between the blocks' shared memories at every stage and record.
  const Run one = device_run(3000, 128, 200, 20, 1);
  for (const int cluster : {2, 4, 8}) {
    INFO(cluster << " blocks per replica");
    const Run b = device_run(3000, 128, 200, 20, cluster);
    CHECK(same_bits(one.theta, b.theta));
    CHECK(same_bits(one.p, b.p));
    CHECK(same_bits(one.records.R_mean, b.records.R_mean));
    CHECK(same_bits(one.records.energy, b.records.energy));
  }
}

TEST_CASE("systems side by side in one launch, in chunks, equal each run alone",
          "[gpu][complete]") {
  const Run alone = device_run(3000, 512, 200, 20);
  std::vector<double> t1, p1, t2, p2;
  gpu_test::waterbag(700, k_replicas, k_sigma0, 5, t1, p1);
  gpu_test::waterbag(3000, k_replicas, k_sigma0, 21, t2, p2);
  cuda::CompleteGraphEnsembles e({{700, k_replicas, 1.0, 7, 100}, {3000, k_replicas, 1.0, 20, 10}});
  e.set_state(0, t1, p1);
  e.set_state(1, t2, p2);
  // 200 steps of the second system in launches of 50, 0 (idle) and 150; the first runs 300.
  e.advance(leap_frog_coefficients(), k_h, {100, 50});
  e.advance(leap_frog_coefficients(), k_h, {100, 0});
  e.advance(leap_frog_coefficients(), k_h, {100, 150});
  check_same_run(e, 1, alone);
  CHECK(e.steps_done(0) == 300);
  CHECK(e.records(0).written == 42);
}

TEST_CASE("a run stopped at a record's end and resumed in new ensembles equals it uninterrupted",
          "[gpu][complete]") {
  const Run alone = device_run(3000, 512, 200, 20);
  std::vector<double> theta, p;
  gpu_test::waterbag(3000, k_replicas, k_sigma0, 21, theta, p);
  cuda::CompleteGraphRecords saved;
  {
    cuda::CompleteGraphEnsembles first({{3000, k_replicas, 1.0, 20, 10}});
    first.set_state(0, theta, p);
    first.advance(leap_frog_coefficients(), k_h, {120});
    first.get_state(0, theta, p);
    saved = first.records(0);
    CHECK(saved.written == 6);
  }
  // Beside another system, on another launch shape: the bits depend on neither.
  cuda::CompleteGraphEnsembles second(
      {{700, k_replicas, 1.0, 7, 10}, {3000, k_replicas, 1.0, 20, 10}}, 128);
  std::vector<double> t1, p1;
  gpu_test::waterbag(700, k_replicas, k_sigma0, 5, t1, p1);
  second.set_state(0, t1, p1);
  // Steps of both first: the resumed system's own open interval (13 of 20 steps) is dropped.
  second.set_state(1, theta, p);
  second.advance(leap_frog_coefficients(), k_h, {33, 13});
  second.resume(1, 120, theta, p, saved);
  CHECK(second.steps_done(1) == 120);
  second.advance(leap_frog_coefficients(), k_h, {0, 80});
  check_same_run(second, 1, alone);
  CHECK(second.records(1).written == 10);
  CHECK_THROWS_AS(second.resume(1, 130, theta, p, saved), cuda::DeviceError);
  CHECK_THROWS_AS(second.resume(1, 120, theta, p, cuda::CompleteGraphRecords{}), cuda::DeviceError);
}

TEST_CASE("the complete graph's bits are the same for batches of 1, 4 and 8 rotors",
          "[gpu][complete]") {
  // N = 20000: tiles of 9 and 10 rotors, so a batch of 8 runs once and leaves a tail, 4 twice.
  const Run one = device_run(20000, 512, 60, 20, 0, 1);
  for (const int batch : {4, 8}) {
    INFO("batch " << batch);
    const Run b = device_run(20000, 512, 60, 20, 0, batch);
    CHECK(same_bits(one.theta, b.theta));
    CHECK(same_bits(one.p, b.p));
    CHECK(same_bits(one.records.R_mean, b.records.R_mean));
    CHECK(same_bits(one.records.energy, b.records.energy));
  }
  cuda::CompleteGraphEnsembles e({{100, 1, 1.0, 1, 0}});
  CHECK_THROWS_AS(e.set_batch(3), cuda::DeviceError);
}
