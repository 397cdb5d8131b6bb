#pragma once
// The parameters of a simulation run (the paper's protocol, Sec. numericalExperiments, and the
// controls around it), their ranges, and their one serialisation: `to_json` is what the results
// file records, what the CLI's provenance records, and, less the fields that cannot change a
// trajectory, what a checkpoint's fingerprint holds.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dynamics/rotor_state.hpp"
#include "dynamics/step_choice.hpp"
#include "network/network.hpp"

namespace hmfnet {

/// The most K values one run takes (a list, or what a sweep expands to): each is a segment of
/// its own with its own results, and a paper's sweep has 17.
inline constexpr std::size_t k_max_schedule = 10'000;

struct SimulationParameters {
  double h = 0.01;           ///< time step, > 0
  double duration = 1000.0;  ///< T2: time per K, > transient
  double transient = 500.0;  ///< T1: discarded at the start of each K, >= 0
  std::vector<double> K;     ///< the schedule, each >= 0
  /// true: the paper's protocol, each K continues from the state left by the previous one;
  /// false: each K restarts from the initial condition.
  bool continue_state = true;
  /// true: every K of the schedule runs at once, as its own set of replicas (lane m R + r is
  /// replica r at K_m: replica_lanes.hpp), in one pass over the network instead of one pass per
  /// K; results equal the continue_state = false run bit for bit. Needs continue_state = false,
  /// one step for every K, no node_data and K.size() x replicas.size() <= 64.
  bool K_across_replicas = false;
  std::vector<InitialCondition> replicas{InitialCondition{}};
  int record_stride = 100;         ///< steps between time-series records
  int batches = 20;                ///< batch means for the SEM of <R>_t
  double energy_tolerance = 1e-2;  ///< stop when |E - E0| / |E0| exceeds this
  bool node_data = false;          ///< per-node statistics over [T1, T2] (PointResult)
  NodeIndex rotor_node = 0;        ///< node_data: the rotor whose (theta_bar, p_bar) is sampled
  int phase_bins = 72;             ///< node_data: bins of the psi_n - psi_1 histogram
  std::string integrator = "leapfrog";
  /// Optional per-K method: empty, or one entry per element of K that replaces h and integrator
  /// for that K's segment (each segment still has T and T1 in time units; the state carries
  /// over, since the force cache of an integrator step is method-independent).
  std::vector<StepChoice> steps;
  // Run control: where and how often to checkpoint, and how to report. None of these changes a
  // result, so none is serialised.
  std::string checkpoint_path;      ///< empty: no checkpoints
  double checkpoint_seconds = 5.0;  ///< wall time between checkpoints (also at each K's end)
  bool resume = false;              ///< continue from checkpoint_path if it exists
  bool progress = false;            ///< progress line on stderr (root rank)
  /// Stop after this many steps in this session, as an interruption would (0: never). For
  /// fault-injection tests of checkpoint/resume.
  std::int64_t stop_after_steps = 0;
  /// OpenMP threads per rank: 0 lets the work per step choose (default_threads,
  /// thread_choice.hpp) among the threads OpenMP offers. Results are bit-identical for any count.
  int threads = 0;
  /// Where the steps run: "cpu", or "cuda" (device_stepper.hpp: the same bits, so a checkpoint
  /// resumes on either).
  std::string device = "cpu";
};

/// Replicas integrated side by side in each step: replicas.size(), times K.size() when
/// K_across_replicas.
std::size_t lanes(const SimulationParameters& params);

/// Throws ParameterError naming the first parameter out of range.
void validate(const SimulationParameters& params);

/// The integrator and step of the k-th K: params.steps[k], or (integrator, h) when steps is empty.
StepChoice step_at(const SimulationParameters& params, std::size_t k);

/// Every parameter that can change a result, seeds included (the run-control fields are left
/// out). Keys follow the CLI's option names where there is one (T, transient, K, ...).
nlohmann::json to_json(const SimulationParameters& params);

/// What a run is besides its parameters: the network (size, stored entries and a hash of them,
/// parallel/network_content_hash.hpp) and the force kernel with its precision.
struct RunIdentity {
  NodeIndex n = 0;
  EdgeOffset nnz = 0;
  std::uint64_t network_hash = 0;
  std::string force;  ///< CouplingForce::name(): "sparse", "sparse-float32", "rank-one"
};

/// to_json less what cannot change the trajectory (the energy tolerance only decides whether a
/// run stops), with the run's identity: a checkpoint is only resumed by a run with the same one.
std::string fingerprint(const SimulationParameters& params, const RunIdentity& identity);

/// Empty when the two fingerprints are equal; otherwise the first field that differs (the
/// network's fields first, then the force, then the parameters by name) with both values, as
/// "FIELD: VALUE in the checkpoint, VALUE in this run".
std::string fingerprint_difference(const std::string& checkpoint, const std::string& run);

}  // namespace hmfnet
