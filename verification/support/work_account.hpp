#pragma once
// A driver's simulation cost against the paper's protocol (leap-frog h = 0.01): every simulate()
// of a driver is passed here, so its output records the force evaluations it spent and the
// pipeline's speed-up over the paper's integrator is measured, not estimated (paper/REPORT.md).
#include "dynamics/simulation.hpp"
#include "support/claim_check.hpp"

namespace hmfnet::verification {

/// Each K of the schedule integrates T = params.duration time units for all replicas at once.
inline void account(ClaimCheck& check, const SimulationParameters& params,
                    const SimulationResult& result) {
  check.account(static_cast<double>(params.K.size()) * params.duration,
                static_cast<double>(result.force_evaluations));
}

}  // namespace hmfnet::verification
