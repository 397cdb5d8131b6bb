#include "app/theory_service.hpp"

#include <memory>

#include "core/error.hpp"
#include "network/adjacency_product.hpp"
#include "network/degree_statistics.hpp"
#include "network/structure.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/distributed_product.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/growth_rate.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/linear_stability.hpp"
#include "theory/onset_amplitude.hpp"
#include "theory/self_consistent.hpp"

namespace hmfnet::app {

namespace {

// The network the solvers run on, and the numbers the outcome quotes. Stored rows stay
// distributed over the ranks: the solvers run replicated on every rank (their iterates are
// O(N)) and only their products A x are shared out (parallel/distributed_product.hpp), so each
// rank holds its own rows only. For K_N the solvers run on its one-node quotient
// (network/complete_graph.hpp: the same map, the same r, sigma^2 and R at every K, and the same
// K_c), so the theory costs O(1) at any N; the outcome quotes K_N's own N, lambda and mean degree.
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

TheoryPoint point(const SelfConsistentSolution& s, const TheoryOutcome& o,
                  MomentumDistribution momenta) {
  TheoryPoint p;
  p.K = s.K;
  p.K_over_Kc = s.K / o.Kc;
  p.linearly_stable = p.K_over_Kc < 1.0;
  p.R = s.R;
  p.R_onset = onset_order_parameter(o.G, s.K / o.Kc_equilibrium);
  p.sigma2 = s.sigma2;
  p.status = solve_status_name(s.status);
  p.iterations = s.iterations;
  p.residual = s.residual;
  p.gamma = above_threshold(p) ? growth_rate(momenta, p.K_over_Kc, o.sigma0) : 0.0;
  return p;
}

// One line naming every K that did not converge, or "".
std::string convergence_failures(const std::vector<SelfConsistentSolution>& solutions,
                                 const LargeKLimit& large_k) {
  std::string failed;
  for (const SelfConsistentSolution& s : solutions) {
    if (s.status == SolveStatus::failed) {
      failed += " K = " + std::to_string(s.K) + ": " + s.message + ";";
    }
  }
  if (large_k.status == SolveStatus::failed) failed += " K -> infinity: " + large_k.message + ";";
  if (failed.empty()) return failed;
  failed.pop_back();
  return "self-consistent state (paper eq. (33)):" + failed;
}

}  // namespace

TheoryOutcome theory(const TheoryRequest& request, const DistributedInput& input) {
  validate(request);
  // Step 1: the network and its Perron pair (collective over MPI ranks).
  const TheoryNetwork net = theory_network(input);
  const PerronResult& perron = net.solved_pair;
  // Step 2: K_c, G, the couplings asked for.
  TheoryOutcome o;
  o.n = net.n;
  o.nnz = net.nnz;
  o.lambda = net.lambda;
  o.mean_degree = net.mean_degree;
  o.sigma0 = request.sigma0;
  const MomentumDistribution momenta = parse_momentum_distribution(request.momenta, "--momenta");
  o.momenta = name_of(momenta);
  const auto n = static_cast<double>(net.n);
  o.Kc = critical_coupling(momenta, request.sigma0, n, net.lambda);
  o.Kc_equilibrium = critical_coupling(request.sigma0, n, net.lambda);
  o.G = onset_amplitude(perron.lambda, mean_degree(*net.product), perron.u);
  if (!perron.nonnegative) {
    o.warnings.push_back(request.input +
                         ": warning: the eigenvector of lambda changes sign (A reducible): "
                         "G and the first guesses assume a positive Perron vector");
  }
  std::vector<double> Ks = request.K;
  for (const double kappa : request.K_over_Kc) Ks.push_back(kappa * o.Kc);
  // Step 3: the synchronized state along K (warm-started), and the K -> infinity limit. Every
  // rank takes the same steps (the products give every rank the same vectors), so an error is
  // raised on all of them alike and reported once.
  SelfConsistentOptions options;
  options.tolerance = request.tolerance;
  std::vector<SelfConsistentSolution> solutions;
  LargeKLimit large_k;
  ParallelSession::agree([&] {
    const SelfConsistentSystem system(*net.product, net.components, perron.lambda, request.sigma0,
                                      0.0, perron.u);
    solutions = system.sweep(Ks, options);
    large_k = solve_large_k_limit(*net.product, options);
  });
  for (const SelfConsistentSolution& s : solutions) o.points.push_back(point(s, o, momenta));
  o.R_hat_iteration = large_k.R_hat;
  o.R_hat_iterations = large_k.iterations;
  o.R_hat_residual = large_k.residual;
  o.R_hat_degree_approx = degree_approximation_R_hat(net.product->degrees());
  o.not_converged = convergence_failures(solutions, large_k);
  o.ranks = ParallelSession::ranks();
  o.peak_rss_mb_per_rank = ParallelSession::peak_memory_mb();  // collective
  return o;
}

}  // namespace hmfnet::app
