// What one barrier of a two-thread OpenMP team costs under this process's OMP_WAIT_POLICY (read
// by libgomp at start: run the binary under each policy). A simulation step is one team's work
// between a few barriers (src/dynamics/team.hpp), so a second thread pays for itself once half a
// step's work outweighs them: this is the "a" of docs/performance.md, "The thread rule on the
// AMD EPYC", measured apart from any step (bench/thread_rule.sh prints it under each policy).
//  - TeamBarrier/threads: `threads` threads pass k_barriers barriers in a row, nothing between;
//    seconds_per_barrier is the wall time of one. Under PASSIVE a waiting thread sleeps at once, so
//    each barrier is one futex wake and the sleeper's return; spinning, a cache line's round trip.
#include <benchmark/benchmark.h>

namespace {

constexpr int k_barriers = 1000;

void TeamBarrier(benchmark::State& state) {
  const auto threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
#pragma omp parallel num_threads(threads)
    {
      for (int i = 0; i < k_barriers; ++i) {
#pragma omp barrier
      }
    }
  }
  state.counters["seconds_per_barrier"] = benchmark::Counter(
      static_cast<double>(k_barriers),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(TeamBarrier)->Arg(2)->MinWarmUpTime(0.1)->Repetitions(3)->UseRealTime();
