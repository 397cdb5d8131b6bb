#pragma once
// Everything `hmfnet spectrum` reports about a network: sizes, degrees, rho (eq:rhodef),
// structure (components, bipartiteness), lambda and its residual, G (eq:globalOrderRInDeltaK),
// and K_c (eq:criticalKFirstOrder) when sigma0 is given.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "network/complete_graph.hpp"
#include "network/network.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"

namespace hmfnet {

struct NetworkSummary {
  NodeIndex n = 0;
  EdgeOffset edges = 0;
  EdgeOffset nnz = 0;
  EdgeOffset self_loops = 0;
  bool weighted = false;
  double mean_degree = 0.0;
  double max_degree = 0.0;
  double rho = 0.0;
  NodeIndex components = 0;
  NodeIndex largest_component = 0;
  bool bipartite = false;
  double lambda = 0.0;
  double lambda_residual = 0.0;
  bool perron_nonnegative = true;
  /// lambda_2 (second largest eigenvalue) when the Perron solve was asked for it, else NaN;
  /// second_mode_ratio = lambda / lambda_2 (the second mode of A goes unstable at that multiple
  /// of K_c); eigenvector_error_bound = residual lambda / (lambda - lambda_2) (sin of the angle
  /// between the computed and the exact u, Davis-Kahan).
  double lambda2 = std::numeric_limits<double>::quiet_NaN();
  double second_mode_ratio = std::numeric_limits<double>::quiet_NaN();
  double eigenvector_error_bound = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no gap
  /// When lambda_2 was bounded instead of converged (PerronOptions::bound_lambda2_first): its
  /// bounds, the upper one with probability >= 1 - lambda2_bound_failure over the seeded start,
  /// and what they imply (second_mode_ratio >= lambda / upper; the error bound uses upper).
  double lambda2_lower = std::numeric_limits<double>::quiet_NaN();
  double lambda2_upper = std::numeric_limits<double>::quiet_NaN();
  double lambda2_bound_failure = 0.0;
  int lambda2_bound_steps = 0;
  int eigen_iterations = 0;
  double eigen_seconds = 0.0;
  double G = 0.0;
  double sigma0 = 0.0;  ///< 0: not given, Kc not computed
  double Kc = 0.0;
  /// Why the theory's assumptions fail here (disconnected, bipartite, sign-changing u, a second
  /// mode close to lambda); empty if they hold.
  std::vector<std::string> warnings;
};

/// A second eigenvalue this close to lambda is reported: lambda / lambda_2 < this means the second
/// mode of A goes unstable below 1.1 K_c, inside the range where the paper measures the onset
/// (the single-mode onset of eq:globalOrderRInDeltaK describes only K < (lambda / lambda_2) K_c).
constexpr double k_near_degenerate_ratio = 1.1;

/// Combines the structural facts with a Perron pair computed on the same network.
NetworkSummary summarise(const Network& network, const PerronResult& perron, double sigma0 = 0.0);
/// The same from the rows each rank holds (degrees and A d from the row blocks, structure by
/// merged forests: parallel/distributed_structure.hpp). Collective; every rank gets the summary.
NetworkSummary summarise(const DistributedNetwork& network, const PerronResult& perron,
                         double sigma0 = 0.0);

/// The same from K_N's closed forms, in O(1) at any N: rho = 1, one component, lambda and
/// lambda_2 exact (residual 0), G from the uniform Perron vector (sqrt(2/5), as every regular
/// graph's).
NetworkSummary summarise(const CompleteGraph& graph, double sigma0 = 0.0);

/// The summary's fields under the names `spectrum --json` gives them, one list for the CLI's JSON
/// and Python's dict: `v.field(name, value)` for each. lambda_2 is given converged or as bounds,
/// whichever was found; an upper bound not yet finite stays infinite (JSON writes it as null).
template <class Visitor>
void visit_network_summary_fields(Visitor& v, const NetworkSummary& s) {
  v.field("n", s.n);
  v.field("edges", s.edges);
  v.field("nnz", s.nnz);
  v.field("self_loops", s.self_loops);
  v.field("weighted", s.weighted);
  v.field("mean_degree", s.mean_degree);
  v.field("max_degree", s.max_degree);
  v.field("lambda", s.lambda);
  v.field("lambda_residual", s.lambda_residual);
  v.field("rho", s.rho);
  v.field("G", s.G);
  v.field("components", s.components);
  v.field("largest_component", s.largest_component);
  v.field("bipartite", s.bipartite);
  v.field("perron_nonnegative", s.perron_nonnegative);
  if (std::isfinite(s.lambda2)) {
    v.field("lambda2", s.lambda2);
    if (std::isfinite(s.second_mode_ratio)) v.field("second_mode_ratio", s.second_mode_ratio);
  } else if (std::isfinite(s.lambda2_lower)) {
    v.field("lambda2_bounds", std::vector<double>{s.lambda2_lower, s.lambda2_upper});
    v.field("lambda2_bound_failure_probability", s.lambda2_bound_failure);
    v.field("lambda2_bound_steps", s.lambda2_bound_steps);
    if (std::isfinite(s.second_mode_ratio)) {
      v.field("second_mode_ratio_at_least", s.second_mode_ratio);
    }
  }
  if ((std::isfinite(s.lambda2) || std::isfinite(s.lambda2_lower)) &&
      std::isfinite(s.eigenvector_error_bound)) {
    v.field("eigenvector_error_bound", s.eigenvector_error_bound);
  }
  v.field("eigensolver_iterations", s.eigen_iterations);
  v.field("eigensolver_seconds", s.eigen_seconds);
  if (s.sigma0 > 0.0) {
    v.field("sigma0", s.sigma0);
    v.field("Kc", s.Kc);
  }
  v.field("warnings", s.warnings);
}

/// One JSON object (visit_network_summary_fields).
std::string to_json(const NetworkSummary& summary);

}  // namespace hmfnet
