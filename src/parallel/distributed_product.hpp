#pragma once
// AdjacencyProduct on rows distributed over MPI ranks: each rank sums its own rows from the whole
// x (every rank holds it: O(N), as the theory's iterates are), in ascending global column order
// like a Network's product, and the row results are gathered on every rank. The same y bit for
// bit on any rank count, so the solvers above it take the same steps on every rank and every
// rank count (they run replicated; only the products are shared out).
#include <vector>

#include "network/adjacency_product.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

class DistributedProduct final : public AdjacencyProduct {
 public:
  /// Collective (gathers the degrees). The network must store rows and outlive this.
  explicit DistributedProduct(const DistributedNetwork& network);
  NodeIndex size() const override { return m_network.global_size(); }
  /// Collective.
  void apply(const std::vector<double>& x, std::vector<double>& y) const override;
  const std::vector<double>& degrees() const override { return m_degrees; }

 private:
  const DistributedNetwork& m_network;
  std::vector<NodeIndex> m_globals;  // global index of each column-space entry
  std::vector<double> m_degrees;
  mutable std::vector<double> m_columns;  // x in the column space
  mutable std::vector<double> m_local;    // this rank's rows of y
};

}  // namespace hmfnet
