// The hardware limit of the force kernel (docs/performance.md, goal 5), measured, not assumed: the
// kernel's irreducible work is, per stored entry, one index read from a stream and one gather of
// a record of 2B values of T (the [cos, sin] of B replicas) added into accumulators. These
// benchmarks do exactly that and nothing else (no sin/cos, no kick, no sums), so their rate is
// the ceiling of LeapFrogStep on the same table:
//  - GatherBound/N/degree/replicas/threads/precision: the ER network's own column stream over a
//    table of N records (the kernel's table, the same size and record width, in the same cache
//    level and the same pages: core/cache_aligned.hpp, huge pages from 4 MiB);
//  - SincosFloor/N/degree/replicas/threads: the other per-step work the kernel cannot skip, one
//    sincos per rotor and replica (the kernel's own vectorised one), counted per stored entry x
//    replica so that 1 / (1 / gather + 1 / sincos) is the kernel's floor; SincosLibc: the same
//    with glibc's scalar sincos, which the kernel used before;
//  - GatherLadder/table_kib/threads: uniform random indices over a table of 16-byte records
//    sized for L1, L2, L3 and memory (this machine: 32 KiB L1d and 512 KiB L2 per core, 32 MiB
//    L3 shared), the latency-bandwidth ladder the kernel's tables sit on (in the kernel's pages).
// Rates count stored entries x replicas per second, as LeapFrogStep's do.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "cached_network.hpp"
#include "core/cache_aligned.hpp"
#include "dynamics/sincos.hpp"

using namespace hmfnet;

namespace {

// Sum of the gathered records over rows [0, rows), one record of W values per entry, into S
// accumulator sets over the entries k, k + 1, ... of each row: enough independent add chains to
// hide the add latency (S = 4 for one [cos, sin] pair), few enough that S x W values stay in
// registers (a wide record brings its own W chains).
template <typename T, std::size_t W>
T gather_rows(const EdgeOffset* row_ptr, const NodeIndex* cols, NodeIndex rows, const T* table) {
  constexpr std::size_t bytes = W * sizeof(T);
  constexpr std::size_t S = bytes <= 32 ? 4 : bytes <= 64 ? 2 : 1;
  T total = 0;
#pragma omp parallel for schedule(static) reduction(+ : total)
  for (NodeIndex r = 0; r < rows; ++r) {
    T acc[S][W] = {};
    const EdgeOffset begin = row_ptr[r], end = row_ptr[r + 1];
    EdgeOffset k = begin;
    for (; k + static_cast<EdgeOffset>(S) <= end; k += static_cast<EdgeOffset>(S)) {
      for (std::size_t c = 0; c < S; ++c) {
        const T* q = table + static_cast<std::ptrdiff_t>(cols[k + static_cast<EdgeOffset>(c)]) *
                                 static_cast<std::ptrdiff_t>(W);
#pragma omp simd
        for (std::size_t j = 0; j < W; ++j) acc[c][j] += q[j];
      }
    }
    for (; k < end; ++k) {
      const T* q = table + static_cast<std::ptrdiff_t>(cols[k]) * static_cast<std::ptrdiff_t>(W);
#pragma omp simd
      for (std::size_t j = 0; j < W; ++j) acc[0][j] += q[j];
    }
    for (std::size_t c = 0; c < S; ++c)
      for (std::size_t j = 0; j < W; ++j) total += acc[c][j];
  }
  return total;
}

template <typename T, std::size_t W>
void run_bound(benchmark::State& state, const Network& net) {
  const CacheAlignedVector<T> table(static_cast<std::size_t>(net.size()) * W, T(0.5));
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        gather_rows<T, W>(net.row_ptr().data(), net.cols().data(), net.size(), table.data()));
  }
}

void GatherBound(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const auto replicas = static_cast<int>(state.range(2));
  omp_set_num_threads(static_cast<int>(state.range(3)));
  const bool f32 = state.range(4) != 0;
  switch (replicas) {
    case 1:
      f32 ? run_bound<float, 2>(state, net) : run_bound<double, 2>(state, net);
      break;
    case 4:
      f32 ? run_bound<float, 8>(state, net) : run_bound<double, 8>(state, net);
      break;
    case 8:
      f32 ? run_bound<float, 16>(state, net) : run_bound<double, 16>(state, net);
      break;
    default:
      state.SkipWithError("replicas: 1, 4 or 8");
      return;
  }
  state.counters["nnz_steps_per_s"] = benchmark::Counter(
      static_cast<double>(net.nnz()) * replicas, benchmark::Counter::kIsIterationInvariantRate);
}

// One [cos, sin] per rotor and replica, by `sincos` over a team of `threads` (the kernel's own,
// dynamics/sincos.hpp: SincosFloor; or glibc's scalar sincos: SincosLibc, its predecessor, for
// the ratio in one run). Rates per stored entry x replica, as LeapFrogStep's.
template <bool Libc>
void sincos_rate(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const auto replicas = static_cast<std::size_t>(state.range(2));
  omp_set_num_threads(static_cast<int>(state.range(3)));
  const std::size_t cells = static_cast<std::size_t>(net.size()) * replicas;
  std::vector<double> theta(cells), cs(2 * cells);
  for (std::size_t k = 0; k < cells; ++k) theta[k] = 0.001 * static_cast<double>(k);
  const auto count = static_cast<std::int64_t>(cells);
  for (auto _ : state) {
    if constexpr (Libc) {
#pragma omp parallel for schedule(static)
      for (std::int64_t k = 0; k < count; ++k)
        ::sincos(theta[std::size_t(k)], &cs[2 * std::size_t(k) + 1], &cs[2 * std::size_t(k)]);
    } else {
#pragma omp parallel
      sincos_interleaved_team(theta.data(), cells, cs.data());
    }
    benchmark::DoNotOptimize(cs.data());
  }
  state.counters["nnz_steps_per_s"] =
      benchmark::Counter(static_cast<double>(net.nnz()) * static_cast<double>(replicas),
                         benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ns_per_angle"] = benchmark::Counter(
      static_cast<double>(cells) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void SincosFloor(benchmark::State& state) { sincos_rate<false>(state); }
void SincosLibc(benchmark::State& state) { sincos_rate<true>(state); }

void GatherLadder(benchmark::State& state) {
  const auto records = static_cast<std::size_t>(state.range(0)) * 1024 / 16;
  omp_set_num_threads(static_cast<int>(state.range(1)));
  // 2^22 gathers in rows of 64, uniform over the table (seed 7).
  const NodeIndex rows = 1 << 16;
  const EdgeOffset per_row = 64;
  std::vector<EdgeOffset> row_ptr(static_cast<std::size_t>(rows) + 1);
  for (std::size_t r = 0; r < row_ptr.size(); ++r)
    row_ptr[r] = static_cast<EdgeOffset>(r) * per_row;
  std::vector<NodeIndex> cols(static_cast<std::size_t>(row_ptr.back()));
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<NodeIndex> pick(0, static_cast<NodeIndex>(records) - 1);
  for (auto& c : cols) c = pick(rng);
  const CacheAlignedVector<double> table(2 * records, 0.5);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        gather_rows<double, 2>(row_ptr.data(), cols.data(), rows, table.data()));
  }
  state.counters["gathers_per_s"] = benchmark::Counter(
      static_cast<double>(cols.size()), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

// Args: N, mean degree, replicas, threads, precision (0 float64, 1 float32): those of the
// LeapFrogStep table (bench_dynamics.cpp).
BENCHMARK(GatherBound)
    ->ArgsProduct({{10000, 1000000}, {100}, {1, 4, 8}, {1, 2}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(SincosFloor)
    ->ArgsProduct({{10000, 1000000}, {100}, {1, 4, 8}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(SincosLibc)
    ->ArgsProduct({{10000}, {100}, {1}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// Args: table KiB (L1, L2, L3, memory), threads.
BENCHMARK(GatherLadder)
    ->ArgsProduct({{16, 256, 8192, 524288}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
