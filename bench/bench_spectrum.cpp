// Largest-eigenvalue benchmarks: Anasazi's Perron solve (target: ER N = 10^4, degree 100
// in <= 0.1 s) beside one Tpetra sparse product A x on the same matrix, so the solve can be read
// as a count of products (a Krylov method needs at least one per iteration), and beside the
// streaming floor of one product (nnz * (4 + 8) bytes of index and value read once).
#include <benchmark/benchmark.h>

#include <vector>

#include "cached_network.hpp"
#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"

using namespace hmfnet;

namespace {

void PerronSolve(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const DistributedNetwork distributed(net);
  int iterations = 0;
  for (auto _ : state) {
    const PerronResult r = perron_eigenpair(distributed);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.lambda);
  }
  state.counters["anasazi_iterations"] = iterations;
}

void SparseProduct(benchmark::State& state) {
  const Network& net = bench::cached_erdos_renyi(static_cast<NodeIndex>(state.range(0)),
                                                 static_cast<double>(state.range(1)));
  const DistributedNetwork distributed(net);
  std::vector<double> x(static_cast<std::size_t>(distributed.local_size()), 1.0), y;
  for (auto _ : state) {
    distributed.apply(x, y);
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["nnz_per_s"] = benchmark::Counter(static_cast<double>(net.nnz()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(PerronSolve)->Args({10000, 100})->Unit(benchmark::kMillisecond);
BENCHMARK(SparseProduct)->Args({10000, 100})->Unit(benchmark::kMicrosecond);
