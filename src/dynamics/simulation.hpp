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

#include "dynamics/coupling_force.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/rotor_state.hpp"
#include "dynamics/simulation_parameters.hpp"
#include "dynamics/step_choice.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct PointResult {
  double K = 0.0;
  std::string integrator;                    ///< the method of this K's segment (step_at)
  double h = 0.0;                            ///< the step of this K's segment
  std::vector<double> R_mean, R_sem;         ///< per replica
  std::vector<double> energy_rel_error_max;  ///< per replica, over the whole segment
  std::vector<double> momentum_drift;        ///< per replica: max |P(t) - P(0)| / sum |p_n(0)|
  std::vector<double> R_node;                ///< N x replicas: <R_n>_t (node_data)
  std::vector<double> omega_node;            ///< N x replicas: Omega_n (node_data)
  // node_data, replica 0 (see node_statistics.hpp):
  std::vector<double> r_node;                        ///< r_n of eq:rnDef, N
  std::vector<double> fluctuation;                   ///< Re<z_n e^{-i theta_bar_n}>_t, N
  std::vector<double> synchronised;                  ///< <r_n cos theta_bar_n>_t, N
  std::vector<double> phase_histogram;               ///< psi_n - psi_1 counts over [-pi, pi)
  std::vector<double> rotor_theta_bar, rotor_p_bar;  ///< samples of the chosen rotor
  std::vector<double> psi_frequency;                 ///< N: mean rate of the unwrapped psi_n
  std::vector<double> frame;  ///< {measured frame frequency Omega, phi, P/N} (node_statistics.hpp)
};

struct TimeSeries {
  std::vector<double> t, K;                 ///< per record (t: time since the run started)
  std::vector<double> R, energy, momentum;  ///< records x replicas
};

struct SimulationResult {
  std::vector<PointResult> points;
  TimeSeries series;
  std::int64_t steps = 0;
  std::int64_t force_evaluations = 0;
  double integration_seconds = 0.0;   ///< the stepping loop only (no set-up, no I/O)
  EdgeOffset nnz_per_evaluation = 0;  ///< summed over ranks
  int threads = 1;                    ///< OpenMP threads per rank the stepping used
  std::int64_t thread_rule_work = 0;  ///< this rank's work per step for the thread rule
  int lanes = 1;                      ///< replicas integrated side by side per step (lanes(params))
  std::string force_name;
  bool resumed = false;
  bool interrupted = false;  ///< stopped by stop_after_steps or a signal: points incomplete
};

/// NaN/Inf or an energy error beyond the tolerance.
class SimulationBlowUp : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs the schedule. Collective over ranks: `network` is the distributed matrix and `force`
/// evaluates the coupling on this rank's rows. Throws SimulationBlowUp (checkpoint kept),
/// ParameterError, InputError (checkpoint unreadable or from other parameters).
SimulationResult simulate(const DistributedNetwork& network, const std::vector<double>& degrees,
                          CouplingForce& force, const SimulationParameters& params);

}  // namespace hmfnet
