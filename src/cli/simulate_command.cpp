// `hmfnet simulate`: the paper's protocol (Sec. numericalExperiments) on a network file.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/command_options.hpp"
#include "cli/command_reports.hpp"
#include "cli/commands.hpp"
#include "cli/provenance.hpp"
#include "cli/read_flags.hpp"
#include "cli/validators.hpp"
#include "core/atomic_file.hpp"
#include "core/distinct_files.hpp"
#include "core/error.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/interrupt.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/rank_one_force.hpp"
#include "dynamics/run_file.hpp"
#include "dynamics/simulation.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"

namespace hmfnet::cli {

namespace {

// "START:STOP:STEP" -> START, START+STEP, ... <= STOP (+ half a step of slack for round-off).
std::vector<double> parse_sweep(const std::string& text) {
  std::vector<double> v;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) {
    std::size_t used = 0;
    try {
      v.push_back(std::stod(part, &used));
    } catch (const std::exception&) {
      used = 0;  // not a number (std::stod throws): refused below with the option's grammar
    }
    if (used == 0 || used != part.size()) {
      throw ParameterError("--K-sweep", text, "START:STOP:STEP with numbers");
    }
  }
  if (v.size() != 3 || !(v[2] > 0) || !(v[1] >= v[0])) {
    throw ParameterError("--K-sweep", text, "START:STOP:STEP with STEP > 0 and STOP >= START");
  }
  // The count first: a step far below the range would otherwise fill the memory before any
  // check could see the list (0:1:1e-300 asks for 10^300 values).
  const double count = std::floor((v[1] - v[0]) / v[2] + 0.5) + 1.0;
  if (!(count <= static_cast<double>(k_max_schedule))) {
    throw ParameterError("--K-sweep", text + " gives " + number_text(count) + " K values",
                         "at most " + std::to_string(k_max_schedule) + " K values per run");
  }
  std::vector<double> K;
  // `k <= count` ends the loop where START + k STEP rounds back to START (1e10:1e10:1e-10).
  for (int k = 0; k <= count && v[0] + k * v[2] <= v[1] + 0.5 * v[2]; ++k) {
    K.push_back(v[0] + k * v[2]);
  }
  return K;
}

// K_N held implicitly has no rows for the sparse kernel: the O(N) rank-one force with a = 1
// (without the diagonal unless it has self-loops) is its only force, exact in float64.
std::unique_ptr<CouplingForce> complete_graph_force(const SimulateFlags& f,
                                                    const CompleteGraph& graph,
                                                    const DistributedNetwork& distributed) {
  if (f.force == "sparse") {
    throw ParameterError("--force", "sparse on the complete graph stored implicitly",
                         "auto or rank-one (K_N has no stored rows)");
  }
  if (parse_force_precision(f.precision) == ForcePrecision::float32) {
    throw ParameterError("--precision", "float32 on the complete graph stored implicitly",
                         "float64 (its rank-one force)");
  }
  return std::make_unique<RankOneForce>(complete_graph_structure(graph), distributed.first_row(),
                                        distributed.local_size());
}

std::unique_ptr<CouplingForce> choose_force(const SimulateFlags& f, const DistributedInput& input,
                                            const DistributedNetwork& distributed) {
  if (input.complete) return complete_graph_force(f, *input.complete, distributed);
  const ForcePrecision precision = parse_force_precision(f.precision);
  if (precision == ForcePrecision::float32 && f.force == "rank-one") {
    throw ParameterError("--precision", "float32",
                         "only for the sparse force (--force sparse|auto)");
  }
  // float32 is a property of the sparse kernel: asking for it selects that kernel under auto.
  if (f.force != "sparse" && precision == ForcePrecision::float64) {
    auto structure = detect_rank_one(distributed);
    if (structure) {
      return std::make_unique<RankOneForce>(std::move(*structure), distributed.first_row(),
                                            distributed.local_size());
    }
    if (f.force == "rank-one") {
      throw ParameterError("--force", "rank-one", "only for A = a a^T networks (see --help)");
    }
  }
  return std::make_unique<NetworkForce>(distributed, precision);
}

SimulationParameters parameters(const SimulateFlags& f, double Kc) {
  SimulationParameters p;
  p.h = f.h;
  p.duration = f.T;
  p.transient = f.transient;
  if (!f.K.empty()) p.K = f.K;
  for (const double r : f.K_over_Kc) p.K.push_back(r * Kc);
  if (!f.sweep.empty()) p.K = parse_sweep(f.sweep);
  p.continue_state = !(f.restart_each_K || f.K_across_replicas);
  p.K_across_replicas = f.K_across_replicas;
  p.replicas.clear();
  for (int b = 0; b < f.replicas; ++b) {
    p.replicas.push_back({f.omega, f.sigma0, f.seed + static_cast<std::uint64_t>(b),
                          parse_momentum_distribution(f.momenta, "--momenta")});
  }
  p.record_stride = f.record_stride;
  p.energy_tolerance = f.energy_tolerance;
  p.node_data = f.node_data;
  p.integrator = f.integrator;
  p.rotor_node = f.rotor_node;
  p.phase_bins = f.phase_bins;
  p.checkpoint_path = f.checkpoint;
  p.resume = f.resume;
  p.progress = !f.quiet && !f.json && ::isatty(2);
  // An explicit count (--threads, or OMP_NUM_THREADS) is the user's; otherwise the work decides.
  if (f.threads > 0) {
    p.threads = f.threads;
  } else if (std::getenv("OMP_NUM_THREADS") != nullptr) {
    p.threads = omp_get_max_threads();
  }
  return p;
}

nlohmann::json point_json(const PointResult& p, double Kc) {
  const double B = static_cast<double>(p.R_mean.size());
  double mean = 0.0, var = 0.0, err = 0.0, drift = 0.0;
  for (std::size_t b = 0; b < p.R_mean.size(); ++b) {
    mean += p.R_mean[b] / B;
    var += p.R_sem[b] * p.R_sem[b] / (B * B);
    err = std::max(err, p.energy_rel_error_max[b]);
    drift = std::max(drift, p.momentum_drift[b]);
  }
  return {{"K", p.K},
          {"K_over_Kc", p.K / Kc},
          {"R_mean", mean},
          {"R_sem", std::sqrt(var)},
          {"R_mean_replicas", p.R_mean},
          {"R_sem_replicas", p.R_sem},
          {"energy_rel_error_max", err},
          {"momentum_drift", drift}};
}

void run(const SimulateFlags& f) {
  SimulateHooks hooks;
  prepare_simulate(f);
  const DistributedInput input = f.read.read_distributed(f.input);
  hooks.before_integration = install_interrupt_handlers;
  const SimulateReport r = simulate_report(f, input, hooks);
  if (is_root()) std::cout << (f.json ? r.report.json + '\n' : r.report.text) << std::flush;
}

}  // namespace

void prepare_simulate(const SimulateFlags& f) {
  if (f.threads > 0) {
    omp_set_num_threads(f.threads);
  } else if (ParallelSession::ranks() > 1 && std::getenv("OMP_NUM_THREADS") == nullptr) {
    // At most "all cores" shared by the ranks (assumed on one machine; set --threads otherwise);
    // the run takes fewer when its work per step is small (thread_choice.hpp).
    omp_set_num_threads(std::max(1, omp_get_num_procs() / ParallelSession::ranks()));
  }
  if (!f.output.empty()) require_writable_destination(f.output);
  if (!f.checkpoint.empty()) require_writable_destination(f.checkpoint);
  require_distinct_files({{"input", f.input}},
                         {{"--output", f.output}, {"--checkpoint", f.checkpoint}});
  make_integrator(f.integrator);  // unknown names fail here, before any work
  // Every range that does not need the network, before it is read: K_c only scales
  // --K-over-Kc, so 1 stands in for it here.
  validate(parameters(f, 1.0));
}

SimulateReport simulate_report(const SimulateFlags& f, const DistributedInput& input,
                               const SimulateHooks& hooks) {
  const CompleteGraph* complete = input.complete ? &*input.complete : nullptr;
  const DistributedNetwork* distributed = input.network.get();
  const double lambda =
      complete != nullptr ? complete->lambda() : perron_eigenpair(*distributed).lambda;
  const NodeIndex n = distributed->global_size();
  const EdgeOffset nnz = distributed->global_nnz();
  const EdgeOffset edges = (nnz + distributed->global_self_loops()) / 2;
  const double Kc =
      critical_coupling(parse_momentum_distribution(f.momenta, "--momenta"), f.sigma0, n, lambda);
  const SimulationParameters params = parameters(f, Kc);
  // Before any work: every output location must hold what the run will write (a checkpoint in
  // the same directory as the results counts against the same space).
  const std::uintmax_t results_bytes = f.output.empty() ? 0 : estimated_run_file_bytes(params, n);
  const std::uintmax_t checkpoint_bytes =
      f.checkpoint.empty() ? 0 : estimated_checkpoint_bytes(params, n);
  if (!f.output.empty()) require_free_space(f.output, results_bytes + checkpoint_bytes);
  if (!f.checkpoint.empty()) require_free_space(f.checkpoint, results_bytes + checkpoint_bytes);
  auto force = choose_force(f, input, *distributed);
  const std::vector<double> degrees =
      complete != nullptr ? std::vector<double>(static_cast<std::size_t>(n), complete->degree())
                          : distributed->gather(distributed->local_degrees());
  if (hooks.before_integration) hooks.before_integration();
  SimulateReport report;
  report.result = simulate(*distributed, degrees, *force, params);
  const SimulationResult& result = report.result;
  if (result.interrupted) {
    const int signal = interrupt_signal();
    throw RunInterrupted(
        signal, std::string(signal == SIGINT ? "SIGINT" : "SIGTERM") + " after " +
                    std::to_string(result.steps) + " steps; " +
                    (f.checkpoint.empty() ? "no results written (add --checkpoint F to make runs "
                                            "resumable)"
                                          : "checkpoint " + f.checkpoint +
                                                " written: rerun with --resume to continue"));
  }

  nlohmann::json out;
  out["n"] = n;
  out["nnz"] = nnz;
  out["lambda"] = lambda;
  out["Kc"] = Kc;
  out["momenta"] = f.momenta;
  out["force"] = result.force_name;
  out["integrator"] = step_at(params, 0).integrator;
  out["steps"] = result.steps;
  out["integration_seconds"] = result.integration_seconds;
  // Aggregate over replicas: each step reads every stored entry once per replica's sum.
  out["nnz_steps_per_second"] = static_cast<double>(result.nnz_per_evaluation) *
                                static_cast<double>(result.steps) *
                                static_cast<double>(result.lanes) / result.integration_seconds;
  out["resumed"] = result.resumed;
  out["threads"] = result.threads;
  out["thread_rule_work"] = result.thread_rule_work;
  out["ranks"] = ParallelSession::ranks();
  const std::vector<double> peak_mb = ParallelSession::peak_memory_mb();
  out["peak_rss_mb_per_rank"] = peak_mb;
  // What each force evaluation imports: [cos, sin] of every lane for each ghost column, as
  // doubles (docs/scaling.md: the communication per step against the rank count).
  std::vector<double> ghosts(static_cast<std::size_t>(ParallelSession::ranks()), 0.0);
  ghosts[static_cast<std::size_t>(ParallelSession::rank())] =
      static_cast<double>(distributed->ghost_count());
  ParallelSession::sum_in_place(ghosts);
  out["ghosts_per_rank"] = ghosts;
  std::vector<double> bytes = ghosts;
  for (double& b : bytes) b *= 2.0 * static_cast<double>(result.lanes) * sizeof(double);
  out["bytes_imported_per_evaluation_per_rank"] = bytes;
  for (const auto& p : result.points) out["points"].push_back(point_json(p, Kc));
  if (!f.output.empty()) {
    RunMetadata meta;
    meta.inputs_json =
        nlohmann::json{{"input", f.input}, {"force", f.force}, {"precision", f.precision}}.dump();
    meta.network_json =
        nlohmann::json{{"n", n}, {"nnz", nnz}, {"edges", edges}, {"lambda", lambda}, {"Kc", Kc}}
            .dump();
    nlohmann::json prov =
        nlohmann::json::parse(provenance("simulate", run_parameters(params, meta.inputs_json)));
    prov["ranks"] = ParallelSession::ranks();
    prov["threads"] = result.threads;
    prov["peak_rss_mb_per_rank"] = peak_mb;
    prov["wall_seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - hooks.started).count();
    meta.provenance_json = prov.dump();
    meta.Kc = Kc;
    if (is_root()) write_run_file(f.output, result, params, meta);
  }
  report.report.json = out.dump();
  std::ostringstream text;
  text << "N = " << n << ", nnz = " << nnz << ", lambda = " << lambda << ", K_c = " << Kc << " ("
       << result.force_name << " force, " << out["nnz_steps_per_second"].get<double>() / 1e9
       << " Gnnz*steps/s)\n"
       << "       K    K/K_c     <R>_t       sem   max dE/E  P drift\n";
  for (const auto& p : out["points"]) {
    char line[128];
    std::snprintf(line, sizeof line, "%8.4g %8.4f %9.5f %9.2e %10.2e %8.1e\n", p["K"].get<double>(),
                  p["K_over_Kc"].get<double>(), p["R_mean"].get<double>(), p["R_sem"].get<double>(),
                  p["energy_rel_error_max"].get<double>(), p["momentum_drift"].get<double>());
    text << line;
  }
  report.report.text = text.str();
  return report;
}

void add_simulate_command(CLI::App& app) {
  static SimulateFlags f;
  add_simulate_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli
