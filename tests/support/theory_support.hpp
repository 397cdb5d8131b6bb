#pragma once
// Helpers for the theory tests: networks with closed-form self-consistent solutions, and a check
// of eq:rSigmaBesselMain written out independently of src/theory/self_consistent_map.cpp.
#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "network/network.hpp"
#include "theory/bessel_ratio.hpp"

namespace hmfnet::test {

/// A = a a^T (weighted, complete with self-loops): lambda = |a|^2, Perron vector a, and
/// eq:rSigmaBesselMain reduces to one scalar equation (r_n = a_n S / N).
inline Network rank_one(const std::vector<double>& a) {
  const auto n = static_cast<NodeIndex>(a.size());
  std::vector<EdgeOffset> row_ptr{0};
  std::vector<NodeIndex> cols;
  std::vector<double> w;
  for (NodeIndex i = 0; i < n; ++i) {
    for (NodeIndex j = 0; j < n; ++j) {
      cols.push_back(j);
      w.push_back(a[std::size_t(i)] * a[std::size_t(j)]);
    }
    row_ptr.push_back(static_cast<EdgeOffset>(cols.size()));
  }
  return Network::from_csr(n, row_ptr, cols, w);
}

/// Bipartite random graph: parts of a and b nodes, each cross pair linked with probability q.
inline Network random_bipartite(NodeIndex a, NodeIndex b, double q, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::bernoulli_distribution link(q);
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < a; ++i)
    for (NodeIndex j = 0; j < b; ++j)
      if (link(engine)) e.emplace_back(i, a + j);
  return Network::from_undirected_edges(a + b, e);
}

/// Largest relative violation of eq:rSigmaBesselMain (index corrected) by (r, mu):
/// max over n of |r_n - (1/N) sum_m A_nm v(K r_m/mu)| / max r, and the same for mu, with
/// 2 U0 / N = -K c0.
inline double equation_residual(const Network& net, double K, double sigma0, double c0,
                                const std::vector<double>& r, double mu) {
  const double n = static_cast<double>(net.size());
  double worst = 0.0, largest = 0.0, energy = 0.0;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    double sum = 0.0;
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      sum += net.weight(k) * bessel_ratio(K * r[std::size_t(net.col(k))] / mu);
    }
    worst = std::max(worst, std::abs(r[std::size_t(i)] - sum / n));
    largest = std::max(largest, std::abs(r[std::size_t(i)]));
    energy += r[std::size_t(i)] * bessel_ratio(K * r[std::size_t(i)] / mu);
  }
  const double mu_rhs = sigma0 * sigma0 + K * energy / n - K * c0;
  return std::max(worst / largest, std::abs(mu - mu_rhs) / mu);
}

}  // namespace hmfnet::test
