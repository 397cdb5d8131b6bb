// Force-kernel throughput (nnz * steps per second) of one leap-frog step, beside baselines
// measured in the same run:
//  - LeapFrogStep/N/degree/replicas/threads/precision: hmfnet's fused kernel (sincos once per
//    rotor, interleaved [cos, sin] per neighbour for all replicas, Tpetra Import of ghosts), one
//    step; precision 0 = float64, 1 = float32 gathered table and accumulation;
//  - YardstickStep/N/degree/threads: the yardstick (docs/performance.md, goal 2), the plain
//    OpenMP CSR loop over an interleaved [cos, sin] array (one accumulator pair per row, an
//    `omp parallel for` per loop, the same flags), one step of one replica;
//  - SegmentedStep/N/degree/replicas/precision/slice_KiB: LeapFrogStep at 1 thread with the
//    column segments forced to slices of slice_KiB of the [cos, sin] table (0: unsegmented),
//    the measurement behind the segment size rule (dynamics/column_segments.hpp);
//  - SegmentedTeamStep/N/degree/replicas/precision/slice_KiB/threads: the same on `threads`;
//  - PlainCsrStep: the textbook loop a user would write first: two CSR products over separate
//    cos and sin arrays, then the kick and drift (1 thread);
//  - IndexStreamFloor: reading the int32 column array once (the memory floor of any pass);
//  - RankOneStep/N/replicas/threads/self_loops: one leap-frog step on K_N held implicitly, the
//    O(N) rank-one force (the complete-graph verification drivers); rotors x replicas x steps
//    per second.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "app/force_choice.hpp"
#include "cached_network.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"

using namespace hmfnet;

namespace {

// Leap-frog steps of `replicas` replicas (momenta around omega with spread sigma0, coupling K)
// for as long as the benchmark asks; `work` (per replica and step) gives the counter `counter`.
void leapfrog_steps(benchmark::State& state, const DistributedNetwork& d, CouplingForce& force,
                    int replicas, double omega, double sigma0, double h, double K,
                    const char* counter, double work) {
  std::vector<InitialCondition> ic;
  ic.reserve(static_cast<std::size_t>(replicas));
  for (int b = 0; b < replicas; ++b) ic.push_back({omega, sigma0, static_cast<std::uint64_t>(b)});
  RotorState s = initial_state(d.first_row(), d.local_size(), ic);
  ForceEvaluation f(force);
  f.update(s);
  const LeapFrog lf;
  const std::vector<double> Ks(static_cast<std::size_t>(replicas), K);
  for (auto _ : state) lf.step(s, h, Ks, f);
  state.counters[counter] =
      benchmark::Counter(work * replicas, benchmark::Counter::kIsIterationInvariantRate);
}

void LeapFrogStep(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  omp_set_num_threads(static_cast<int>(state.range(3)));
  const DistributedNetwork d(net);
  // The kernel by name (not "auto"), through the choice a run makes: the sparse one at the
  // precision this benchmark measures.
  const auto force = app::choose_force("sparse", state.range(4) == 0 ? "float64" : "float32", d);
  leapfrog_steps(state, d, *force, static_cast<int>(state.range(2)), 6.0, 1.0, 0.01, 50.0,
                 "nnz_steps_per_s", static_cast<double>(net.nnz()));
}

// LeapFrogStep with the segments forced to slices of state.range(4) KiB, on `threads` threads:
// the sparse kernel built directly at that segment width (src/dynamics/column_segments.hpp), which
// the force choice leaves to the kernel's own rule, as the width is what is measured.
void segmented_steps(benchmark::State& state, int threads) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  omp_set_num_threads(threads);
  const DistributedNetwork d(net);
  const auto replicas = static_cast<int>(state.range(2));
  const bool f64 = state.range(3) == 0;
  const auto record = static_cast<std::int64_t>(2 * replicas) * (f64 ? 8 : 4);
  const auto width =
      state.range(4) == 0 ? k_unsegmented : static_cast<NodeIndex>((state.range(4) << 10) / record);
  NetworkForce force(d, f64 ? ForcePrecision::float64 : ForcePrecision::float32, width);
  leapfrog_steps(state, d, force, replicas, 6.0, 1.0, 0.01, 50.0, "nnz_steps_per_s",
                 static_cast<double>(net.nnz()));
  state.counters["segments"] = force.segments();
}

void SegmentedStep(benchmark::State& state) { segmented_steps(state, 1); }

void SegmentedTeamStep(benchmark::State& state) {
  segmented_steps(state, static_cast<int>(state.range(5)));
}

void RankOneStep(benchmark::State& state) {
  const CompleteGraph graph = CompleteGraph::make(state.range(0), state.range(3) != 0);
  omp_set_num_threads(static_cast<int>(state.range(2)));
  const DistributedNetwork d(graph);
  const auto force = app::choose_force("rank-one", "float64", d);
  leapfrog_steps(state, d, *force, static_cast<int>(state.range(1)), 0.0, 0.6, 0.1, 1.0,
                 "rotor_steps_per_s", static_cast<double>(graph.n));
}

void PlainCsrStep(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const auto n = static_cast<std::size_t>(net.size());
  std::vector<double> theta(n), p(n, 6.0), c(n), s(n), g(n);
  for (std::size_t i = 0; i < n; ++i) theta[i] = 0.001 * static_cast<double>(i);
  const double h = 0.01, K = 50.0, inv_n = 1.0 / static_cast<double>(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      c[i] = std::cos(theta[i]);
      s[i] = std::sin(theta[i]);
    }
    for (NodeIndex i = 0; i < net.size(); ++i) {
      double yc = 0.0, ys = 0.0;
      for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k)
        yc += c[std::size_t(net.col(k))];
      for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k)
        ys += s[std::size_t(net.col(k))];
      g[std::size_t(i)] = inv_n * (c[std::size_t(i)] * ys - s[std::size_t(i)] * yc);
    }
    for (std::size_t i = 0; i < n; ++i) {
      p[i] += h * K * g[i];
      theta[i] += h * p[i];
    }
    benchmark::DoNotOptimize(theta.data());
  }
  state.counters["nnz_steps_per_s"] = benchmark::Counter(
      static_cast<double>(net.nnz()), benchmark::Counter::kIsIterationInvariantRate);
}

void YardstickStep(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  const NodeIndex n = net.size();
  const auto size = static_cast<std::size_t>(n);
  const EdgeOffset* row_ptr = net.row_ptr().data();
  const NodeIndex* cols = net.cols().data();
  std::vector<double> theta(size), p(size, 6.0), cs(2 * size), g(size);
  for (std::size_t i = 0; i < size; ++i) theta[i] = 0.001 * static_cast<double>(i);
  const double h = 0.01, K = 50.0, inv_n = 1.0 / static_cast<double>(n);
  for (auto _ : state) {
#pragma omp parallel for schedule(static)
    for (NodeIndex i = 0; i < n; ++i)
      ::sincos(theta[std::size_t(i)], &cs[2 * std::size_t(i) + 1], &cs[2 * std::size_t(i)]);
#pragma omp parallel for schedule(static)
    for (NodeIndex i = 0; i < n; ++i) {
      double yc = 0.0, ys = 0.0;
      for (EdgeOffset k = row_ptr[i]; k < row_ptr[i + 1]; ++k) {
        yc += cs[2 * std::size_t(cols[k])];
        ys += cs[2 * std::size_t(cols[k]) + 1];
      }
      g[std::size_t(i)] = inv_n * (cs[2 * std::size_t(i)] * ys - cs[2 * std::size_t(i) + 1] * yc);
    }
#pragma omp parallel for schedule(static)
    for (NodeIndex i = 0; i < n; ++i) {
      p[std::size_t(i)] += h * K * g[std::size_t(i)];
      theta[std::size_t(i)] += h * p[std::size_t(i)];
    }
    benchmark::DoNotOptimize(theta.data());
  }
  state.counters["nnz_steps_per_s"] = benchmark::Counter(
      static_cast<double>(net.nnz()), benchmark::Counter::kIsIterationInvariantRate);
}

void IndexStreamFloor(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  for (auto _ : state) {
    long long sum = 0;
    for (const NodeIndex j : net.cols()) sum += j;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["nnz_per_s"] = benchmark::Counter(static_cast<double>(net.nnz()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

// Args: N, mean degree, replicas, threads, precision (0 float64, 1 float32). The table of
// bench/ensemble_table.sh: these, YardstickStep and GatherBound (bench_gather_bound.cpp).
BENCHMARK(LeapFrogStep)
    ->ArgsProduct({{10000, 1000000}, {100}, {1, 4, 8}, {1, 2}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// B = 2 at 1 thread: the replica count whose segment runs have an AVX2 version besides B = 1
// (dynamics/segment_runs.hpp; bench/segmented_rows_table.sh).
BENCHMARK(LeapFrogStep)
    ->ArgsProduct({{10000, 1000000}, {100}, {2}, {1}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(YardstickStep)
    ->ArgsProduct({{10000, 1000000}, {100}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(PlainCsrStep)->Args({10000, 100})->Unit(benchmark::kMillisecond);
// Args: N, mean degree, replicas, precision, slice KiB (0: unsegmented).
BENCHMARK(SegmentedStep)
    ->ArgsProduct({{1000000}, {100}, {1, 4, 8}, {0, 1}, {0, 512, 1024, 2048, 4096, 16384}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// Args: as SegmentedStep's, then threads: the slices against the rule's choice at two threads,
// where each core holds its L2 slice and the two share the L3 (docs/performance.md, "An Intel
// Xeon's L3 is no core complex's"; 12 MiB: half a 48 MiB L3 over two threads; 2 MiB beside the
// rule's 4 MiB on the AMD EPYC family 25 model 1 guest, "The L3 a guest can count on").
BENCHMARK(SegmentedTeamStep)
    ->ArgsProduct({{1000000}, {100}, {1, 4, 8}, {0, 1}, {0, 1024, 2048, 4096, 12288}, {2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// N = 10^4 (its 160 KiB table in L2 whole) cut as N = 10^6 is (16 segments of ~6 entries a
// row): what the segmented walk costs where no cache needs it, apart from the misses it avoids.
BENCHMARK(SegmentedStep)
    ->ArgsProduct({{10000}, {100}, {1}, {0}, {0, 10}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// N = 10^4 with 8 replicas, whose 640 KB (float32) and 1.28 MB (float64) tables sit in L2: slices
// down to L1's size, where the gathered lines would come from L1 (docs/performance.md, "Sums only
// where a record reads them": the carried partials cost more than the misses they save).
BENCHMARK(SegmentedStep)
    ->ArgsProduct({{10000}, {100}, {8}, {0, 1}, {0, 16, 32, 64, 128, 256}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// Args: N, replicas, threads, self-loops (1: A = 1 1^T, the Antoni-Ruffo HMF; 0: K_N).
BENCHMARK(RankOneStep)
    ->ArgsProduct({{2000, 20000}, {1, 16}, {1, 2}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(IndexStreamFloor)->Args({10000, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(LeapFrogStep)
    ->Args({25000, 5000, 1, 1, 0})
    ->Args({25000, 5000, 1, 1, 1})
    ->Args({25000, 5000, 1, 2, 0})
    ->Args({25000, 5000, 8, 1, 0})
    ->Args({25000, 5000, 8, 1, 1})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(PlainCsrStep)->Args({25000, 5000})->Unit(benchmark::kMillisecond);
BENCHMARK(IndexStreamFloor)->Args({25000, 5000})->Unit(benchmark::kMillisecond);
