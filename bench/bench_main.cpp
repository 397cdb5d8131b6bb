// Google Benchmark runner with the ParallelSession (MPI + Kokkos) the Tpetra benchmarks need.
#include <benchmark/benchmark.h>

#include "parallel/parallel_session.hpp"

int main(int argc, char** argv) {
  hmfnet::ParallelSession session(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
