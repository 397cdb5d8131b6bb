#include "network/adjacency_product.hpp"

#include <numeric>

#include "core/error.hpp"
#include "network/sparse_product.hpp"

namespace hmfnet {

void NetworkProduct::apply(const std::vector<double>& x, std::vector<double>& y) const {
  multiply(m_network, x, y);
}

double mean_degree(const AdjacencyProduct& product) {
  if (product.size() == 0) throw ParameterError("mean degree: network", "0 nodes", "N >= 1");
  const auto& d = product.degrees();
  return std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
}

}  // namespace hmfnet
