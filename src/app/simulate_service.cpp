#include "app/simulate_service.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/force_choice.hpp"
#include "app/provenance.hpp"
#include "core/atomic_file.hpp"
#include "core/distinct_files.hpp"
#include "core/error.hpp"
#include "dynamics/device_stepper.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/run_file.hpp"
#include "io/network_file.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"

namespace hmfnet::app {

namespace {

PointSummary summary(const PointResult& p, double Kc) {
  const double B = static_cast<double>(p.R_mean.size());
  PointSummary s;
  double var = 0.0;
  for (std::size_t b = 0; b < p.R_mean.size(); ++b) {
    s.R_mean += p.R_mean[b] / B;
    var += p.R_sem[b] * p.R_sem[b] / (B * B);
    s.energy_rel_error_max = std::max(s.energy_rel_error_max, p.energy_rel_error_max[b]);
    s.momentum_drift = std::max(s.momentum_drift, p.momentum_drift[b]);
  }
  s.K = p.K;
  s.K_over_Kc = p.K / Kc;
  s.R_sem = std::sqrt(var);
  s.R_mean_replicas = p.R_mean;
  s.R_sem_replicas = p.R_sem;
  return s;
}

// Before any work: every output location must hold what the run will write (a checkpoint in the
// same directory as the results counts against the same space).
void require_space(const SimulateRequest& r, const SimulationParameters& params, NodeIndex n) {
  const std::uintmax_t results = r.output.empty() ? 0 : estimated_run_file_bytes(params, n);
  const std::uintmax_t checkpoint =
      r.checkpoint.empty() ? 0 : estimated_checkpoint_bytes(params, n);
  if (!r.output.empty()) require_free_space(r.output, results + checkpoint);
  if (!r.checkpoint.empty()) require_free_space(r.checkpoint, results + checkpoint);
}

[[noreturn]] void interrupted(const SimulateRequest& r, std::int64_t steps) {
  const int signal = interrupt_signal();
  throw RunInterrupted(
      signal,
      std::string(signal == SIGINT ? "SIGINT" : "SIGTERM") + " after " + std::to_string(steps) +
          " steps; " +
          (r.checkpoint.empty()
               ? "no results written (add --checkpoint F to make runs resumable)"
               : "checkpoint " + r.checkpoint + " written: rerun with --resume to continue"));
}

void write_results_file(const SimulateRequest& r, const SimulateOutcome& o,
                        const SimulateHooks& hooks) {
  RunMetadata meta;
  meta.inputs_json =
      nlohmann::json{{"input", r.input}, {"force", r.force}, {"precision", r.precision}}.dump();
  meta.network_json = nlohmann::json{
      {"n", o.n},
      {"nnz", o.nnz},
      {"edges", o.edges},
      {"lambda", o.lambda},
      {"Kc", o.Kc}}.dump();
  nlohmann::json prov =
      nlohmann::json::parse(provenance("simulate", run_parameters(o.params, meta.inputs_json)));
  prov["ranks"] = o.ranks;
  prov["threads"] = o.threads;
  if (!o.thread_trial.empty()) prov["thread_trial"] = o.thread_trial;
  if (!o.segment_trial.empty()) prov["segment_trial"] = o.segment_trial;
  prov["device"] = o.device;
  prov["peak_rss_mb_per_rank"] = o.peak_rss_mb_per_rank;
  prov["wall_seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - hooks.started).count();
  meta.provenance_json = prov.dump();
  meta.Kc = o.Kc;
  if (ParallelSession::rank() == 0) write_run_file(r.output, o.result, o.params, meta);
}

}  // namespace

void prepare_simulate(const SimulateRequest& r) {
  validate(r);
  // Before the network is read: an option the device does not take, or a machine without one.
  if (r.device == "cuda") require_device_for(simulation_parameters(r, 1.0));
  if (r.threads > 0) {
    omp_set_num_threads(r.threads);
  } else if (ParallelSession::ranks() > 1 && std::getenv("OMP_NUM_THREADS") == nullptr) {
    // At most "all cores" shared by the ranks (assumed on one machine; set --threads otherwise);
    // the run takes fewer when its work per step is small (thread_choice.hpp).
    omp_set_num_threads(std::max(1, omp_get_num_procs() / ParallelSession::ranks()));
  }
  // The input first: an output over it is the refusal that matters most (its message says so).
  require_distinct_files({{"input", r.input}},
                         {{"--output", r.output}, {"--checkpoint", r.checkpoint}});
  const auto check_destination = [](const char* role, const std::string& path) {
    if (path.empty()) return;
    require_not_a_text_network_name(role, path);
    require_writable_destination(path);
  };
  check_destination("--output", r.output);
  check_destination("--checkpoint", r.checkpoint);
}

namespace {

SimulateOutcome run_simulation(const SimulateRequest& r, const DistributedInput& input,
                               const SimulateHooks& hooks, DistributedNetwork* owned) {
  const CompleteGraph* complete = input.complete ? &*input.complete : nullptr;
  const DistributedNetwork& distributed = *input.network;
  SimulateOutcome o;
  o.lambda = complete != nullptr ? complete->lambda() : perron_eigenpair(distributed).lambda;
  o.n = distributed.global_size();
  o.nnz = distributed.global_nnz();
  o.edges = (o.nnz + distributed.global_self_loops()) / 2;
  const auto n = static_cast<NodeIndex>(o.n);
  o.Kc =
      critical_coupling(parse_momentum_distribution(r.momenta, "--momenta"), r.sigma0, n, o.lambda);
  o.params = simulation_parameters(r, o.Kc);
  require_space(r, o.params, n);
  auto force = choose_force(r.force, r.precision, input);
  if (auto* sparse = dynamic_cast<NetworkForce*>(force.get());
      sparse != nullptr && owned != nullptr) {
    sparse->take_columns(*owned);
  }
  const std::vector<double> degrees =
      complete != nullptr ? std::vector<double>(static_cast<std::size_t>(n), complete->degree())
                          : distributed.gather(distributed.local_degrees());
  if (hooks.before_integration) hooks.before_integration();
  o.result = hmfnet::simulate(distributed, degrees, *force, o.params);
  const SimulationResult& result = o.result;
  if (result.interrupted) interrupted(r, result.steps);

  o.momenta = r.momenta;
  o.force = result.force_name;
  o.device = result.device;
  o.integrator = step_at(o.params, 0).integrator;
  o.steps = result.steps;
  o.integration_seconds = result.integration_seconds;
  // Aggregate over replicas: each step reads every stored entry once per replica's sum.
  o.nnz_steps_per_second = static_cast<double>(result.nnz_per_evaluation) *
                           static_cast<double>(result.steps) * static_cast<double>(result.lanes) /
                           result.integration_seconds;
  o.resumed = result.resumed;
  o.threads = result.threads;
  o.thread_rule_work = result.thread_rule_work;
  o.thread_trial = result.thread_trial;
  o.segment_trial = result.segment_trial;
  o.ranks = ParallelSession::ranks();
  o.peak_rss_mb_per_rank = ParallelSession::peak_memory_mb();
  o.ghosts_per_rank.assign(static_cast<std::size_t>(o.ranks), 0.0);
  o.ghosts_per_rank[static_cast<std::size_t>(ParallelSession::rank())] =
      static_cast<double>(distributed.ghost_count());
  ParallelSession::sum_in_place(o.ghosts_per_rank);
  o.bytes_imported_per_evaluation_per_rank = o.ghosts_per_rank;
  for (double& b : o.bytes_imported_per_evaluation_per_rank)
    b *= 2.0 * static_cast<double>(result.lanes) * sizeof(double);
  for (const PointResult& p : result.points) o.points.push_back(summary(p, o.Kc));
  if (!r.output.empty()) write_results_file(r, o, hooks);
  return o;
}

}  // namespace

SimulateOutcome simulate(const SimulateRequest& r, const DistributedInput& input,
                         const SimulateHooks& hooks) {
  return run_simulation(r, input, hooks, nullptr);
}

SimulateOutcome simulate(const SimulateRequest& r, DistributedInput&& input,
                         const SimulateHooks& hooks) {
  const DistributedInput run_input = std::move(input);
  return run_simulation(r, run_input, hooks, run_input.network.get());
}

}  // namespace hmfnet::app
