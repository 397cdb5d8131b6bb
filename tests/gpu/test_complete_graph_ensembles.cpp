// The device's complete-graph stepper against the CPU's rank-one step (host_ensemble.hpp):
// within 1e-12 over 100 leap-frog steps (Z is summed in another fixed order, so not the bits);
// the same bits run to run and whatever the threads per block; several systems in one launch
// equal each run alone; the records (mean R over an interval, the energy at its end) against
// the host's; the state kept in shared memory gives the bits of the state in global memory.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
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

// cluster: blocks per replica (0: the automatic choice); batch: rotors loaded together; place:
// where the state is kept.
Run device_run(std::int64_t n, int threads, std::int64_t steps, std::int64_t record_every,
               int cluster = 0, int batch = 4,
               cuda::StatePlace place = cuda::StatePlace::global_memory,
               const SplittingCoefficients& splitting = leap_frog_coefficients()) {
  std::vector<double> theta, p;
  gpu_test::waterbag(n, k_replicas, k_sigma0, 21, theta, p);
  cuda::CompleteGraphEnsembles e({{n, k_replicas, 1.0, record_every, steps / record_every}},
                                 threads, cluster);
  e.set_state_place(place);
  if (cluster > 0) REQUIRE(e.cluster_blocks() == cluster);
  e.set_batch(batch);
  e.set_state(0, theta, p);
  e.advance(splitting, k_h, {steps});
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

void check_same_bits(const Run& got, const Run& want) {
  CHECK(same_bits(got.theta, want.theta));
  CHECK(same_bits(got.p, want.p));
  CHECK(same_bits(got.records.R_mean, want.records.R_mean));
  CHECK(same_bits(got.records.energy, want.records.energy));
  CHECK(got.records.written == want.records.written);
}

// The water-bags of N = 700 (seed 5) and N = 3000 (seed 21, device_run's) as systems 0 and 1.
void start_two_systems(cuda::CompleteGraphEnsembles& e) {
  std::vector<double> t1, p1, t2, p2;
  gpu_test::waterbag(700, k_replicas, k_sigma0, 5, t1, p1);
  gpu_test::waterbag(3000, k_replicas, k_sigma0, 21, t2, p2);
  e.set_state(0, t1, p1);
  e.set_state(1, t2, p2);
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
  cuda::CompleteGraphEnsembles e({{700, k_replicas, 1.0, 7, 100}, {3000, k_replicas, 1.0, 20, 10}});
  start_two_systems(e);
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

TEST_CASE("the state in shared memory gives the bits of the state in global memory",
          "[gpu][complete]") {
  using cuda::StatePlace;
  struct Shape {
    std::int64_t n;
    int threads, cluster;
  };
  // N = 3000 on 1, 2 and 8 blocks (the [cos, sin] kept: 16 to 1 tiles a thread) and on 3 blocks
  // of 32 threads (64 chunks: the most heads), N = 700 (fewer tiles than the cap, idle threads),
  // N = 5 (a chunk of 5 tiles on one of 8 blocks), N = 20000 (tiles of 9 and 10 rotors: the
  // batches' tails), and the benchmark's N = 10^5 on 8 blocks of 256 (the [cos, sin] formed again
  // at each stage).
  for (const Shape s :
       {Shape{3000, 128, 1}, Shape{3000, 128, 2}, Shape{3000, 256, 8}, Shape{3000, 32, 3},
        Shape{700, 64, 0}, Shape{5, 32, 8}, Shape{20000, 512, 0}, Shape{100000, 256, 8}}) {
    for (const int batch : {1, 4, 8}) {
      INFO("N = " << s.n << ", " << s.threads << " threads, " << s.cluster << " blocks, batch "
                  << batch);
      const std::int64_t steps = s.n > 20000 ? 20 : 60;
      const Run global = device_run(s.n, s.threads, steps, 10, s.cluster, batch);
      const Run shared =
          device_run(s.n, s.threads, steps, 10, s.cluster, batch, StatePlace::shared_memory);
      check_same_bits(shared, global);
    }
  }
  // A fourth-order splitting (seven stages a step, records between them).
  const Run global =
      device_run(3000, 128, 30, 10, 0, 4, StatePlace::global_memory, yoshida4_coefficients());
  const Run shared =
      device_run(3000, 128, 30, 10, 0, 4, StatePlace::shared_memory, yoshida4_coefficients());
  check_same_bits(shared, global);
}

TEST_CASE("the state in shared memory keeps the [cos, sin] where they fit and forms them where not",
          "[gpu][complete]") {
  cuda::CompleteGraphEnsembles small({{3000, 2, 1.0, 1, 0}}, 128, 1);
  small.set_state_place(cuda::StatePlace::shared_memory);
  CHECK(small.keeps_phases());
  CHECK(small.active_clusters() >= 1);
  // 10^5 rotors on 8 blocks of 256: theta and p 196 KiB a block, with [cos, sin] 392 KiB.
  cuda::CompleteGraphEnsembles large({{100000, 2, 1.0, 1, 0}}, 256);
  large.set_state_place(cuda::StatePlace::shared_memory);
  CHECK(large.cluster_blocks() == 8);
  CHECK_FALSE(large.keeps_phases());
  large.set_state_place(cuda::StatePlace::global_memory);
  CHECK_FALSE(large.keeps_phases());
}

TEST_CASE("a run switched between global and shared memory between launches keeps its bits",
          "[gpu][complete]") {
  const Run alone = device_run(3000, 256, 200, 20);
  // Two systems side by side (their blocks' shared memory sized by the larger), in chunks that
  // stop inside a record's interval, the place switched between chunks.
  cuda::CompleteGraphEnsembles e({{700, k_replicas, 1.0, 7, 100}, {3000, k_replicas, 1.0, 20, 10}},
                                 256);
  start_two_systems(e);
  e.set_state_place(cuda::StatePlace::shared_memory);
  e.advance(leap_frog_coefficients(), k_h, {100, 55});
  e.set_state_place(cuda::StatePlace::global_memory);
  e.advance(leap_frog_coefficients(), k_h, {100, 45});
  e.set_state_place(cuda::StatePlace::shared_memory);
  e.advance(leap_frog_coefficients(), k_h, {100, 100});
  check_same_run(e, 1, alone);
}

TEST_CASE("a launch that forms the [cos, sin] again leaves them for the global stepper's next",
          "[gpu][complete]") {
  // N = 10^5 on 8 blocks of 256: the shared-memory stepper keeps no [cos, sin] and writes them
  // back from the angles; the global stepper's next launch reads them.
  std::vector<double> theta, p;
  gpu_test::waterbag(100000, k_replicas, k_sigma0, 21, theta, p);
  const auto run = [&](bool split) {
    cuda::CompleteGraphEnsembles e({{100000, k_replicas, 1.0, 5, 4}}, 256, 8);
    e.set_state(0, theta, p);
    if (split) {
      e.set_state_place(cuda::StatePlace::shared_memory);
      REQUIRE_FALSE(e.keeps_phases());
      e.advance(leap_frog_coefficients(), k_h, {12});
      e.set_state_place(cuda::StatePlace::global_memory);
      e.advance(leap_frog_coefficients(), k_h, {8});
    } else {
      e.advance(leap_frog_coefficients(), k_h, {20});
    }
    Run r;
    e.get_state(0, r.theta, r.p);
    r.records = e.records(0);
    return std::make_pair(r, e.order_sums(0));
  };
  const auto whole = run(false);
  const auto split = run(true);
  check_same_bits(split.first, whole.first);
  CHECK(same_bits(split.second, whole.second));
}

TEST_CASE("the state in shared memory refuses shapes it cannot run, naming them",
          "[gpu][complete]") {
  cuda::CompleteGraphEnsembles odd({{3000, 1, 1.0, 1, 0}}, 96);
  CHECK_THROWS_WITH(odd.set_state_place(cuda::StatePlace::shared_memory),
                    Catch::Contains("power of two up to 512, not 96"));
  CHECK(odd.state_place() == cuda::StatePlace::global_memory);
  cuda::CompleteGraphEnsembles wide({{3000, 1, 1.0, 1, 0}}, 1024);
  CHECK_THROWS_WITH(wide.set_state_place(cuda::StatePlace::shared_memory),
                    Catch::Contains("not 1024"));
  // 10^6 rotors on one block: 16 MB of theta and p.
  cuda::CompleteGraphEnsembles big({{1000000, 1, 1.0, 1, 0}}, 256, 1);
  CHECK_THROWS_WITH(
      big.set_state_place(cuda::StatePlace::shared_memory),
      Catch::Contains("bytes a block on 1 blocks of 256 threads a replica; the device "
                      "allows"));
}
