#pragma once
// The complete graph K_N held in O(1) space: A_nm = 1 for every n != m, and with self-loops also
// A_nn = 1 (A = 1 1^T). It is the paper's all-to-all limit (eq:hamiltonianNetworkCase with
// A = all ones reduces to the HMF of Antoni & Ruffo 1995), a rank-one network A = a a^T with
// a = 1 (minus the identity without self-loops). Every quantity the commands need has a closed
// form, so N = 10^6 (10^12 stored entries) costs nothing to hold; `simulate` uses the O(N)
// rank-one force (dynamics/rank_one_force.hpp) and `theory` the one-node quotient below.
#include <cstdint>

#include "network/network.hpp"

namespace hmfnet {

struct CompleteGraph {
  NodeIndex n = 0;
  bool self_loops = false;

  /// Throws ParameterError naming `--n` unless 2 <= n <= 2^31 - 1 (the node index range).
  static CompleteGraph make(std::int64_t n, bool self_loops);

  /// n (n - 1) stored entries, plus n self-loops.
  EdgeOffset nnz() const;
  /// Unordered pairs n (n - 1) / 2, plus n self-loops (Network's convention: a loop counts once).
  EdgeOffset edges() const;
  /// Every node's degree: n - 1, or n with self-loops (the graph is regular).
  double degree() const;
  /// The largest eigenvalue, exactly: 1 1^T has n, 1 1^T - I has n - 1 (eq:criticalKFirstOrder).
  double lambda() const { return degree(); }
  /// The second largest eigenvalue, exactly: every vector orthogonal to 1 is an eigenvector, with
  /// eigenvalue 0 (self-loops) or -1 (without): multiplicity n - 1.
  double lambda2() const { return self_loops ? 0.0 : -1.0; }
  /// Only K_2 without self-loops (one edge) is bipartite.
  bool bipartite() const { return n == 2 && !self_loops; }

  /// The stored CSR form, for cross-checks on small n; refuses n (n - 1) > 2^28 stored entries
  /// (2 GB of column indices) with a ParameterError.
  Network materialise() const;

  /// The quotient of the equitable partition {all nodes}: one node with a self-loop of weight
  /// degree() / n. The theory's map (eq:rSigmaBesselMain) on K_N takes uniform vectors to uniform
  /// vectors, and every fixed point is uniform (r_n = (1/N) sum_m A_nm v_m is the same for all n
  /// with self-loops, and r_n + v(r_n / eta) / N is the same for all n without, a strictly
  /// increasing function of r_n), so on this network the same map gives the same r, sigma^2 and R
  /// at every K. Its N / lambda = 1 / weight equals K_N's, so K_c is the same too.
  Network quotient() const;
};

}  // namespace hmfnet
