#pragma once
// The `simulate` service: the paper's protocol (Sec. numericalExperiments) on a network already
// read, from a typed request (simulate_request.hpp) to a typed outcome. The CLI prints the outcome
// (text, or its report fields as JSON) and the Python module converts the same fields to a dict
// and the full results to numpy arrays: one code path, the same numbers. Collective over the MPI
// ranks; the outcome is complete on every rank.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/simulate_request.hpp"
#include "dynamics/simulation.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::app {

/// One K's results summed up over the replicas (the run's report, `--json`'s "points").
struct PointSummary {
  double K = 0.0, K_over_Kc = 0.0;
  double R_mean = 0.0;  ///< mean of the replicas' <R>_t
  double R_sem = 0.0;   ///< its standard error, from the replicas' batch-means SEMs
  std::vector<double> R_mean_replicas, R_sem_replicas;
  double energy_rel_error_max = 0.0;  ///< the largest over the replicas
  double momentum_drift = 0.0;        ///< the largest over the replicas
};

template <class Visitor, class... Point>
void visit_summary_fields(Visitor& v, Point&... p) {
  v.field("K", p.K...);
  v.field("K_over_Kc", p.K_over_Kc...);
  v.field("R_mean", p.R_mean...);
  v.field("R_sem", p.R_sem...);
  v.field("R_mean_replicas", p.R_mean_replicas...);
  v.field("R_sem_replicas", p.R_sem_replicas...);
  v.field("energy_rel_error_max", p.energy_rel_error_max...);
  v.field("momentum_drift", p.momentum_drift...);
}

struct SimulateOutcome {
  std::int64_t n = 0, nnz = 0, edges = 0;
  double lambda = 0.0, Kc = 0.0;
  std::string momenta, force, integrator;
  std::string device;  ///< where the steps ran: "cpu" or the GPU's name
  std::int64_t steps = 0;
  double integration_seconds = 0.0;
  /// Stored entries x steps x replica lanes per second of the stepping loop.
  double nnz_steps_per_second = 0.0;
  bool resumed = false;
  int threads = 1;
  std::int64_t thread_rule_work = 0;
  std::string thread_trial;   ///< SimulationResult::thread_trial
  std::string segment_trial;  ///< SimulationResult::segment_trial
  int ranks = 1;
  std::vector<double> peak_rss_mb_per_rank;
  /// What each force evaluation imports: [cos, sin] of every lane for each ghost column
  /// (docs/scaling.md: the communication per step against the rank count).
  std::vector<double> ghosts_per_rank, bytes_imported_per_evaluation_per_rank;
  std::vector<PointSummary> points;
  SimulationParameters params;  ///< what ran
  SimulationResult result;      ///< every result (time series, node data): point_result.hpp
};

/// The report's fields (`--json` prints them; Python returns them), less the points.
template <class Visitor>
void visit_report_fields(Visitor& v, const SimulateOutcome& o) {
  v.field("n", o.n);
  v.field("nnz", o.nnz);
  v.field("lambda", o.lambda);
  v.field("Kc", o.Kc);
  v.field("momenta", o.momenta);
  v.field("force", o.force);
  v.field("integrator", o.integrator);
  v.field("device", o.device);
  v.field("steps", o.steps);
  v.field("integration_seconds", o.integration_seconds);
  v.field("nnz_steps_per_second", o.nnz_steps_per_second);
  v.field("resumed", o.resumed);
  v.field("threads", o.threads);
  v.field("thread_rule_work", o.thread_rule_work);
  v.field("thread_trial", o.thread_trial);
  v.field("segment_trial", o.segment_trial);
  v.field("ranks", o.ranks);
  v.field("peak_rss_mb_per_rank", o.peak_rss_mb_per_rank);
  v.field("ghosts_per_rank", o.ghosts_per_rank);
  v.field("bytes_imported_per_evaluation_per_rank", o.bytes_imported_per_evaluation_per_rank);
}

/// Before the network is read: validate(r), the OpenMP thread count (r.threads, or the cores
/// shared by the ranks) and the output locations (writable, distinct from the input and from each
/// other).
void prepare_simulate(const SimulateRequest& r);

/// What the caller adds around the run: when it started (the results file's wall_seconds count
/// from there) and what to do once the set-up is done and the integration starts (the CLI
/// installs its interrupt handlers there: a signal during the set-up still ends the process at
/// once, one during the integration ends it at the next record with a checkpoint).
struct SimulateHooks {
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  std::function<void()> before_integration;
};

/// The run: lambda and K_c, the force (force_choice.hpp), the free-space check, the integration,
/// the results file (r.output, root rank). A run stopped by a signal throws RunInterrupted.
SimulateOutcome simulate(const SimulateRequest& r, const DistributedInput& input,
                         const SimulateHooks& hooks = {});
/// The same run on a network that is the run's alone (the CLI reads it for this run, Python
/// distributes its Network afresh for each): the sparse force may take its column indices where it
/// cuts them into segments or reads them in 16 bits (NetworkForce::take_columns), 4 bytes per
/// stored entry less at the peak; the same results.
SimulateOutcome simulate(const SimulateRequest& r, DistributedInput&& input,
                         const SimulateHooks& hooks = {});

}  // namespace hmfnet::app
