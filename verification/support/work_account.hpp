#pragma once
// A driver's simulation cost: every simulate() of a driver is passed here, so its output records
// the force evaluations it spent (the pipeline's speed-up over the paper's leap-frog h = 0.01 is
// measured, not estimated) and the kernel work and stepping time beside the kernel's measured
// bound (paper/REPORT.md, summary table).
#include "dynamics/simulation.hpp"
#include "support/claim_check.hpp"
#include "support/simulation_cost.hpp"

namespace hmfnet::verification {

/// Each K of the schedule integrates T = params.duration time units for all replicas at once.
/// A run across replicas evaluates every K in one pass (each evaluation K.size() times wider):
/// its evaluations are counted as those of the sequential schedule, so the figure compares
/// methods and steps, not the lane layout; the kernel work counts the lanes actually integrated.
inline SimulationCost cost_of(const SimulationParameters& params, const SimulationResult& result) {
  const double per_pass = params.K_across_replicas ? static_cast<double>(params.K.size()) : 1.0;
  const auto evaluations = static_cast<double>(result.force_evaluations);
  SimulationCost cost;
  cost.simulated_time = static_cast<double>(params.K.size()) * params.duration;
  cost.evaluations = per_pass * evaluations;
  cost.kernel_work = evaluations * static_cast<double>(result.nnz_per_evaluation) *
                     static_cast<double>(result.lanes);
  cost.kernel_seconds = result.integration_seconds;
  cost.threads = result.threads;
  return cost;
}

inline void account(ClaimCheck& check, const SimulationParameters& params,
                    const SimulationResult& result) {
  check.account(cost_of(params, result));
}

}  // namespace hmfnet::verification
