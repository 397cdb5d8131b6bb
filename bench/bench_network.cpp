// Network generation benchmarks, each beside its floor measured in the same run:
//  - ErdosRenyi: the generator (N = 10^6, mean degree 100; the target: <= 3 s);
//  - GeometricSkipFloor: only the random draws and logs of the skipping (compute floor);
//  - StreamWriteFloor: writing nnz int32 column indices once (memory floor: the CSR must be
//    written at least once).
// Ratios generator / floor are what docs/performance.md reports.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "core/random.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"

using namespace hmfnet;

namespace {

void ErdosRenyi(benchmark::State& state) {
  const auto n = static_cast<NodeIndex>(state.range(0));
  const double degree = static_cast<double>(state.range(1));
  EdgeOffset nnz = 0;
  for (auto _ : state) {
    const Network net = erdos_renyi({n, erdos_renyi_probability(n, degree), 1});
    nnz = net.nnz();
    benchmark::DoNotOptimize(net.cols().data());
  }
  state.counters["nnz"] = static_cast<double>(nnz);
  state.counters["nnz_per_s"] =
      benchmark::Counter(static_cast<double>(nnz), benchmark::Counter::kIsIterationInvariantRate);
}

void GeometricSkipFloor(benchmark::State& state) {
  const auto n = static_cast<std::int64_t>(state.range(0));
  const double q = static_cast<double>(state.range(1)) / static_cast<double>(n - 1);
  const double log_miss = std::log1p(-q);
  const auto draws = n * state.range(1) / 2;
  for (auto _ : state) {
    Rng rng(1, 0);
    double sink = 0.0;
    for (std::int64_t k = 0; k < draws; ++k) sink += std::log(rng.uniform_open_zero()) / log_miss;
    benchmark::DoNotOptimize(sink);
  }
  state.counters["nnz_per_s"] = benchmark::Counter(static_cast<double>(2 * draws),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void StreamWriteFloor(benchmark::State& state) {
  const auto nnz = static_cast<std::size_t>(state.range(0) * state.range(1));
  std::vector<NodeIndex> cols(nnz);
  for (auto _ : state) {
    std::memset(cols.data(), static_cast<int>(state.iterations() & 0x7f), nnz * sizeof(NodeIndex));
    benchmark::DoNotOptimize(cols.data());
    benchmark::ClobberMemory();
  }
  state.counters["nnz_per_s"] =
      benchmark::Counter(static_cast<double>(nnz), benchmark::Counter::kIsIterationInvariantRate);
}

void ChungLu(benchmark::State& state) {
  const auto n = static_cast<NodeIndex>(state.range(0));
  const double alpha = static_cast<double>(state.range(1)) / 10.0;
  const auto targets = power_law_targets(n, {alpha, power_law_d_min_for_mean(alpha, 100.0)}, 1);
  EdgeOffset nnz = 0;
  for (auto _ : state) {
    const Network net = chung_lu(targets, LinkProbability::capped, 1);
    nnz = net.nnz();
    benchmark::DoNotOptimize(net.cols().data());
  }
  state.counters["nnz_per_s"] =
      benchmark::Counter(static_cast<double>(nnz), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(ErdosRenyi)->Args({1000000, 100})->Args({10000, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(GeometricSkipFloor)->Args({1000000, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(StreamWriteFloor)->Args({1000000, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(ChungLu)->Args({10000, 25})->Args({100000, 25})->Unit(benchmark::kMillisecond);
