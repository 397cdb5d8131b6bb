#pragma once
// What a driver's simulations cost, summed over its runs (support/work_account.hpp makes one
// from a run; ClaimCheck::account adds them up and writes them beside the driver's results).
// Kernel work over kernel seconds is the rate the REPORT's summary table compares with the
// measured bound of the force kernel (docs/performance.md: "The kernel against the yardstick").
#include <algorithm>

namespace hmfnet::verification {

struct SimulationCost {
  double simulated_time = 0.0;  ///< time units of the schedules (each K's T; replicas at once)
  double evaluations = 0.0;     ///< force evaluations of the sequential K schedule
  double kernel_work = 0.0;     ///< stored entries (rows on the rank-one force) x replica lanes,
                                ///< summed over the force evaluations made
  double kernel_seconds = 0.0;  ///< wall time of the stepping loops (no set-up, theory or I/O)
  int threads = 0;              ///< the most OpenMP threads per rank that a run used

  SimulationCost& operator+=(const SimulationCost& other) {
    simulated_time += other.simulated_time;
    evaluations += other.evaluations;
    kernel_work += other.kernel_work;
    kernel_seconds += other.kernel_seconds;
    threads = std::max(threads, other.threads);
    return *this;
  }
};

}  // namespace hmfnet::verification
