#pragma once
// The paper's simulation protocol (Sec. numericalExperiments): rotors start with theta uniform in
// [0, 2 pi) and p ~ Gaussian(Omega, sigma0); for each coupling K of a schedule the system is
// integrated for T time units continuing from the current state, the first T1 are discarded and
// <R>_t (eq:timeAverage, eq:globalOrderParam) is averaged over the rest. Recorded on a stride:
// R(t), the energy H (eq:hamiltonianNetworkCase) and the total momentum (both conserved).
//
// B replicas (seeds, sigma0, Omega) run side by side in one pass over the network; with
// K_across_replicas, so do the K values of a restart-each-K schedule (replica_lanes.hpp). A run can
// be checkpointed and resumed bit-identically; a blow-up (NaN or energy error above a tolerance)
// stops it with the likely cause.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/blow_up_guard.hpp"
#include "dynamics/coupling_force.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/point_result.hpp"
#include "dynamics/rotor_state.hpp"
#include "dynamics/simulation_parameters.hpp"
#include "dynamics/step_choice.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct SimulationResult {
  std::vector<PointResult> points;
  TimeSeries series;
  std::int64_t steps = 0;
  std::int64_t force_evaluations = 0;
  double integration_seconds = 0.0;   ///< the stepping loop only (no set-up, no I/O)
  EdgeOffset nnz_per_evaluation = 0;  ///< summed over ranks
  int threads = 1;                    ///< OpenMP threads per rank the stepping used
  std::int64_t thread_rule_work = 0;  ///< this rank's work per step for the thread rule
  /// The timed first steps that chose the default count (StepTrial::summary), or empty.
  std::string thread_trial;
  /// The timed first steps that chose the sparse force's column segments (StepTrial::summary;
  /// NetworkForce::segment_candidates), or empty.
  std::string segment_trial;
  int lanes = 1;  ///< replicas integrated side by side per step (lanes(params))
  std::string force_name;
  std::string device = "cpu";  ///< where the steps ran (EnsembleStepper::device)
  bool resumed = false;
  bool interrupted = false;  ///< stopped by stop_after_steps or a signal: points incomplete
};

/// Runs the schedule. Collective over ranks: `network` is the distributed matrix and `force`
/// evaluates the coupling on this rank's rows. Throws SimulationBlowUp (checkpoint kept),
/// ParameterError, InputError (checkpoint unreadable or from other parameters).
SimulationResult simulate(const DistributedNetwork& network, const std::vector<double>& degrees,
                          CouplingForce& force, const SimulationParameters& params);

}  // namespace hmfnet
