#include "analysis/network_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "core/json_fields.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/onset_amplitude.hpp"

namespace hmfnet {

namespace {
std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}
}  // namespace

namespace {

// lambda, its residual and gap, G and K_c from a Perron pair (s.n and s.mean_degree set first).
void add_spectrum(NetworkSummary& s, const PerronResult& perron, double sigma0) {
  s.lambda = perron.lambda;
  s.lambda_residual = perron.residual;
  s.perron_nonnegative = perron.nonnegative;
  s.lambda2 = perron.lambda2;
  // lambda_2 = 0 (K_N with self-loops, a star's middle eigenvalue): no finite ratio to report.
  if (perron.lambda2 != 0.0) s.second_mode_ratio = perron.lambda / perron.lambda2;
  if (perron.lambda2 < perron.lambda)  // false for NaN and for a degenerate lambda (no gap)
    s.eigenvector_error_bound = perron.residual * perron.lambda / (perron.lambda - perron.lambda2);
  if (std::isnan(perron.lambda2) && std::isfinite(perron.lambda2_lower)) {
    s.lambda2_lower = perron.lambda2_lower;
    s.lambda2_upper = perron.lambda2_upper;
    s.lambda2_bound_failure = perron.lambda2_bound_failure;
    s.lambda2_bound_steps = perron.lambda2_bound_steps;
    if (perron.lambda2_upper > 0.0 && std::isfinite(perron.lambda2_upper)) {
      s.second_mode_ratio = perron.lambda / perron.lambda2_upper;
    }
    if (perron.lambda2_upper < perron.lambda) {
      s.eigenvector_error_bound =
          perron.residual * perron.lambda / (perron.lambda - perron.lambda2_upper);
    }
  }
  s.eigen_iterations = perron.iterations;
  s.eigen_seconds = perron.seconds;
  s.G = onset_amplitude(perron.lambda, s.mean_degree, perron.u);
  if (sigma0 > 0.0) {
    s.sigma0 = sigma0;
    s.Kc = critical_coupling(sigma0, s.n, s.lambda);
  }
}

void add_warnings(NetworkSummary& s) {
  if (s.components > 1) {
    s.warnings.push_back(std::to_string(s.components) +
                         " connected components: A is reducible, the Perron-Frobenius assumption "
                         "of the theory fails (lambda and u belong to one component)");
  }
  if (s.bipartite) {
    s.warnings.push_back("bipartite network: -lambda is also an eigenvalue (lambda_min = -lambda)");
  }
  if (std::isfinite(s.lambda2) && s.lambda2 > 0.0 &&
      s.second_mode_ratio < k_near_degenerate_ratio) {
    s.warnings.push_back(
        "near-degenerate lambda: lambda_2 = " + short_number(s.lambda2) +
        ", lambda / lambda_2 = " + short_number(s.second_mode_ratio) +
        ": a second mode goes unstable at that multiple of K_c (e.g. two weakly linked "
        "communities), so the single-mode onset theory holds only below it; Perron vector "
        "error <= " +
        short_number(s.eigenvector_error_bound));
  }
  // Bounds alone that prove it (the converged solve that should follow them failed).
  if (std::isnan(s.lambda2) && s.lambda2_lower >= s.lambda / k_near_degenerate_ratio) {
    s.warnings.push_back("near-degenerate lambda: lambda_2 >= " + short_number(s.lambda2_lower) +
                         " (a Lanczos lower bound; lambda_2 itself not converged), lambda / "
                         "lambda_2 <= " +
                         short_number(s.lambda / s.lambda2_lower) +
                         ": a second mode goes unstable at that multiple of K_c");
  }
  if (!s.perron_nonnegative) {
    s.warnings.push_back("the eigenvector of lambda changes sign: lambda is degenerate");
  }
}

}  // namespace

NetworkSummary summarise(const Network& network, const PerronResult& perron, double sigma0) {
  return summarise(DistributedNetwork(network), perron, sigma0);
}

namespace {

// eq:rhodef: rho = (d^T A d) (sum d) / (sum d^2)^2 from the rows held here, reduced over ranks.
double degree_correlation(const DistributedNetwork& network, const std::vector<double>& d_local) {
  std::vector<double> ad;
  network.apply(d_local, ad);
  std::vector<double> sums(3, 0.0);  // sum d, sum d^2, d^T A d
  for (std::size_t r = 0; r < d_local.size(); ++r) {
    sums[0] += d_local[r];
    sums[1] += d_local[r] * d_local[r];
    sums[2] += d_local[r] * ad[r];
  }
  ParallelSession::sum_in_place(sums);
  if (sums[1] == 0.0) {
    throw ParameterError("degree correlation: network", "no edges", "a network with edges");
  }
  return sums[2] * sums[0] / (sums[1] * sums[1]);
}

}  // namespace

NetworkSummary summarise(const DistributedNetwork& network, const PerronResult& perron,
                         double sigma0) {
  NetworkSummary s;
  s.n = network.global_size();
  s.nnz = network.global_nnz();
  s.self_loops = network.global_self_loops();
  s.edges = (s.nnz + s.self_loops) / 2;
  s.weighted = network.weighted();
  const std::vector<double> d_local = network.local_degrees();
  const std::vector<double> d = network.gather(d_local);
  s.mean_degree = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
  s.max_degree = *std::max_element(d.begin(), d.end());
  s.rho = degree_correlation(network, d_local);
  const NetworkStructure structure = distributed_structure(network);
  s.components = structure.components;
  s.largest_component = structure.largest;
  s.bipartite = structure.bipartite;
  add_spectrum(s, perron, sigma0);
  add_warnings(s);
  return s;
}

NetworkSummary summarise(const CompleteGraph& graph, double sigma0) {
  NetworkSummary s;
  s.n = graph.n;
  s.edges = graph.edges();
  s.nnz = graph.nnz();
  s.self_loops = graph.self_loops ? graph.n : 0;
  s.mean_degree = graph.degree();
  s.max_degree = graph.degree();
  s.rho = 1.0;  // eq:rhodef on a regular graph: <d d>_e / (<d>_e <d>_e) = d^2 / d^2
  s.components = 1;
  s.largest_component = graph.n;
  s.bipartite = graph.bipartite();
  // The exact pair; eq:globalOrderRInDeltaK uses u only through node averages of its powers, so
  // one entry of the uniform vector stands for all N.
  PerronResult perron;
  perron.lambda = graph.lambda();
  perron.lambda2 = graph.lambda2();
  perron.u = {1.0};
  add_spectrum(s, perron, sigma0);
  add_warnings(s);
  return s;
}

std::string to_json(const NetworkSummary& s) {
  nlohmann::json j;
  JsonFields fields{j};
  visit_network_summary_fields(fields, s);
  return j.dump();
}

}  // namespace hmfnet
