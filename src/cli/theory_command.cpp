// `hmfnet theory`: the paper's predictions for one network and momentum spread sigma0:
// K_c (eq:criticalKFirstOrder), G (eq:globalOrderRInDeltaK), the growth rate gamma (eq:gammaKKc)
// and the synchronized state R(K) (eq:rSigmaBesselMain) at each K, and the K -> infinity limit
// R_hat (eq:KtoInfinity and its degree approximation eq:rd).
//
// Two thresholds: K_c, the linear (Vlasov) threshold of the incoherent start for the chosen
// momentum distribution (theory/linear_stability.hpp), which --K-over-Kc multiplies and gamma
// follows; and Kc_equilibrium = 2 sigma0^2 N / lambda, where eq:rSigmaBesselMain leaves R = 0 at
// the incoherent start's energy (the equilibrium depends on g only through sigma0^2 and U0 = 0).
// They coincide for Gaussian momenta; the water-bag's K_c is 3 Kc_equilibrium, and between the two
// the incoherent start is linearly stable although the equilibrium is synchronised.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command_options.hpp"
#include "cli/command_reports.hpp"
#include "cli/commands.hpp"
#include "cli/read_flags.hpp"
#include "cli/validators.hpp"
#include "core/error.hpp"
#include "network/adjacency_product.hpp"
#include "network/degree_statistics.hpp"
#include "network/structure.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/distributed_product.hpp"
#include "parallel/distributed_read.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/growth_rate.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/linear_stability.hpp"
#include "theory/onset_amplitude.hpp"
#include "theory/self_consistent.hpp"

namespace hmfnet::cli {

namespace {

struct TheoryReport {
  double lambda = 0.0;
  MomentumDistribution momenta = MomentumDistribution::gaussian;
  double Kc = 0.0;              ///< linear threshold of `momenta`
  double Kc_equilibrium = 0.0;  ///< where eq:rSigmaBesselMain leaves R = 0
  double G = 0.0;
  double mean_degree = 0.0;
  std::vector<SelfConsistentSolution> points;
  LargeKLimit large_k;
  double R_hat_degree = 0.0;
};

nlohmann::json to_json(const TheoryReport& t, const TheoryFlags& f, NodeIndex n) {
  nlohmann::json j;
  j["n"] = n;
  j["mean_degree"] = t.mean_degree;
  j["sigma0"] = f.sigma0;
  j["lambda"] = t.lambda;
  j["momenta"] = name_of(t.momenta);
  j["Kc"] = t.Kc;
  j["Kc_equilibrium"] = t.Kc_equilibrium;
  j["G"] = t.G;
  j["R_hat_iteration"] = t.large_k.R_hat;
  j["R_hat_iterations"] = t.large_k.iterations;
  j["R_hat_residual"] = t.large_k.residual;
  j["R_hat_degree_approx"] = t.R_hat_degree;
  j["gamma"] = nlohmann::json::array();
  j["points"] = nlohmann::json::array();
  for (const auto& p : t.points) {
    const double kappa = p.K / t.Kc;
    if (kappa > 1.0) {
      j["gamma"].push_back(
          {{"K_over_Kc", kappa}, {"gamma", growth_rate(t.momenta, kappa, f.sigma0)}});
    }
    j["points"].push_back({{"K", p.K},
                           {"K_over_Kc", kappa},
                           {"linearly_stable", kappa < 1.0},
                           {"R", p.R},
                           {"R_onset", onset_order_parameter(t.G, p.K / t.Kc_equilibrium)},
                           {"sigma2", p.sigma2},
                           {"status", solve_status_name(p.status)},
                           {"iterations", p.iterations},
                           {"residual", p.residual}});
  }
  return j;
}

void print_text(std::ostream& out, const TheoryReport& t, const TheoryFlags& f) {
  out << std::setprecision(6) << "lambda             " << t.lambda << "\n"
      << "K_c                " << t.Kc << " (linear threshold, " << name_of(t.momenta)
      << " momenta, sigma0 = " << f.sigma0 << ")\n"
      << "K_c equilibrium    " << t.Kc_equilibrium << " (eq:rSigmaBesselMain leaves R = 0)\n"
      << "G                  " << t.G << "\n"
      << "R_hat (K -> inf)   " << t.large_k.R_hat << " (eq:KtoInfinity, " << t.large_k.iterations
      << " iterations), " << t.R_hat_degree << " (degree approximation eq:rd)\n\n"
      << std::setw(12) << "K" << std::setw(10) << "K/K_c" << std::setw(12) << "R" << std::setw(12)
      << "G*sqrt" << std::setw(12) << "sigma^2" << std::setw(12) << "gamma" << std::setw(7)
      << "iter" << std::setw(12) << "residual"
      << "  status\n";
  for (const auto& p : t.points) {
    const double kappa = p.K / t.Kc;
    out << std::setw(12) << p.K << std::setw(10) << kappa << std::setw(12) << p.R << std::setw(12)
        << onset_order_parameter(t.G, p.K / t.Kc_equilibrium) << std::setw(12) << p.sigma2
        << std::setw(12) << (kappa > 1.0 ? growth_rate(t.momenta, kappa, f.sigma0) : 0.0)
        << std::setw(7) << p.iterations << std::setw(12) << p.residual << "  "
        << solve_status_name(p.status) << "\n";
  }
}

// One line naming every K that did not converge, or "" (the caller prints the results first).
std::string convergence_failures(const TheoryReport& t) {
  std::string failed;
  for (const auto& p : t.points) {
    if (p.status == SolveStatus::failed)
      failed += " K = " + std::to_string(p.K) + ": " + p.message + ";";
  }
  if (t.large_k.status == SolveStatus::failed)
    failed += " K -> infinity: " + t.large_k.message + ";";
  if (failed.empty()) return failed;
  failed.pop_back();
  return "eq:rSigmaBesselMain:" + failed;
}

// The network the solvers run on, and the numbers the report quotes. Stored rows stay
// distributed over the ranks: the solvers run replicated on every rank (their iterates are
// O(N)) and only their products A x are shared out (parallel/distributed_product.hpp), so each
// rank holds its own rows only. For K_N the solvers run on its one-node quotient
// (network/complete_graph.hpp: the same map, the same r, sigma^2 and R at every K, and the same
// K_c), so the theory costs O(1) at any N; the report quotes K_N's own N, lambda and mean degree.
struct TheoryNetwork {
  std::unique_ptr<Network> quotient;          ///< K_N's quotient, or null
  std::unique_ptr<AdjacencyProduct> product;  ///< what the solvers run on
  Components components;                      ///< of what the solvers run on
  PerronResult solved_pair;                   ///< of what the solvers run on
  NodeIndex n = 0;                            ///< of the input
  EdgeOffset nnz = 0;                         ///< of the input
  double lambda = 0.0;                        ///< of the input
  double mean_degree = 0.0;                   ///< of the input
};

TheoryNetwork theory_network(const DistributedInput& input) {
  TheoryNetwork t;
  if (input.complete) {
    t.quotient = std::make_unique<Network>(input.complete->quotient());
    t.product = std::make_unique<NetworkProduct>(*t.quotient);
    t.components = connected_components(*t.quotient);
    t.solved_pair.lambda = t.quotient->weights().front();  // a 1 x 1 matrix: its one entry
    t.solved_pair.u = {1.0};
    t.n = input.complete->n;
    t.nnz = input.complete->nnz();
    t.lambda = input.complete->lambda();
    t.mean_degree = input.complete->degree();
    return t;
  }
  const DistributedNetwork& rows = *input.network;
  t.product = std::make_unique<DistributedProduct>(rows);
  t.components = distributed_components(rows);
  t.solved_pair = perron_eigenpair(rows);
  t.n = rows.global_size();
  t.nnz = rows.global_nnz();
  t.lambda = t.solved_pair.lambda;
  t.mean_degree = mean_degree(*t.product);
  return t;
}

void run(const TheoryFlags& f) {
  const CommandReport report = theory_report(f, f.read.read_distributed(f.input));
  if (!is_root()) return;  // rank 0 prints the report, then the failure once
  std::cout << (f.json ? report.json + '\n' : report.text) << std::flush;
  if (!report.not_converged.empty()) throw ConvergenceError(report.not_converged);
}

}  // namespace

CommandReport theory_report(const TheoryFlags& f, const DistributedInput& input) {
  // Step 1: the network and its Perron pair (collective over MPI ranks).
  const TheoryNetwork net = theory_network(input);
  const PerronResult& perron = net.solved_pair;
  // Step 2: K_c, G, the couplings asked for.
  TheoryReport t;
  t.lambda = net.lambda;
  t.mean_degree = net.mean_degree;
  t.momenta = parse_momentum_distribution(f.momenta, "--momenta");
  const auto n = static_cast<double>(net.n);
  t.Kc = critical_coupling(t.momenta, f.sigma0, n, net.lambda);
  t.Kc_equilibrium = critical_coupling(f.sigma0, n, net.lambda);
  t.G = onset_amplitude(perron.lambda, mean_degree(*net.product), perron.u);
  if (!perron.nonnegative && is_root()) {
    std::cerr << f.input << ": warning: the eigenvector of lambda changes sign (A reducible): "
              << "G and the first guesses assume a positive Perron vector\n";
  }
  std::vector<double> Ks = f.K;
  for (const double kappa : f.K_over_Kc) Ks.push_back(kappa * t.Kc);
  // Step 3: the synchronized state along K (warm-started), and the K -> infinity limit. Every
  // rank takes the same steps (the products give every rank the same vectors), so an error is
  // raised on all of them alike and reported once.
  SelfConsistentOptions options;
  options.tolerance = f.tolerance;
  ParallelSession::agree([&] {
    const SelfConsistentSystem system(*net.product, net.components, perron.lambda, f.sigma0, 0.0,
                                      perron.u);
    t.points = system.sweep(Ks, options);
    t.large_k = solve_large_k_limit(*net.product, options);
  });
  t.R_hat_degree = degree_approximation_R_hat(net.product->degrees());
  const std::vector<double> peak_mb = ParallelSession::peak_memory_mb();
  CommandReport report;
  nlohmann::json j = to_json(t, f, net.n);
  j["nnz"] = net.nnz;
  j["ranks"] = ParallelSession::ranks();
  j["peak_rss_mb_per_rank"] = peak_mb;
  report.json = j.dump();
  std::ostringstream text;
  print_text(text, t, f);
  report.text = text.str();
  report.not_converged = convergence_failures(t);
  return report;
}

void add_theory_command(CLI::App& app) {
  static TheoryFlags f;
  add_theory_options(app, f, [] { run(f); });
}

}  // namespace hmfnet::cli
