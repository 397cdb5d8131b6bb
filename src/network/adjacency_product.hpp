#pragma once
// The operations of a network that the theory's solvers need (theory/self_consistent_map.hpp,
// self_consistent.hpp, large_k_limit.hpp, spectral/component_radii.hpp): y = A x for vectors
// with one entry per node, held whole by the caller, and the degrees. NetworkProduct does them on
// a Network; parallel/distributed_product.hpp on rows distributed over MPI ranks (each rank sums
// its own rows, the results gathered), so `theory` runs on either with the same solver code.
// Every implementation sums each row in ascending column order, one row per thread: y does not
// depend on the thread count nor on the rank count, bit for bit.
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

class AdjacencyProduct {
 public:
  AdjacencyProduct() = default;
  virtual ~AdjacencyProduct() = default;
  AdjacencyProduct(const AdjacencyProduct&) = delete;
  AdjacencyProduct& operator=(const AdjacencyProduct&) = delete;

  virtual NodeIndex size() const = 0;
  /// y = A x; x has size() entries, y is resized. Collective for distributed rows.
  virtual void apply(const std::vector<double>& x, std::vector<double>& y) const = 0;
  /// d = A 1 (row sums of the weights).
  virtual const std::vector<double>& degrees() const = 0;
};

/// On a Network, which must outlive it (network/sparse_product.hpp's multiply).
class NetworkProduct final : public AdjacencyProduct {
 public:
  explicit NetworkProduct(const Network& network)
      : m_network(network), m_degrees(network.degrees()) {}
  NodeIndex size() const override { return m_network.size(); }
  void apply(const std::vector<double>& x, std::vector<double>& y) const override;
  const std::vector<double>& degrees() const override { return m_degrees; }

 private:
  const Network& m_network;
  std::vector<double> m_degrees;
};

/// ||d|| = sum d / N of a product's degrees.
double mean_degree(const AdjacencyProduct& product);

}  // namespace hmfnet
