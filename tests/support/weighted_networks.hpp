#pragma once
// Weighted networks for tests whose weights must survive a path bit for bit (files, row blocks,
// exchanges between ranks): ER with a weight per edge that differs from edge to edge.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "network/erdos_renyi.hpp"

namespace hmfnet::test {

/// ER G(n, q) with w_ij = 1 + 0.5 sin(0.37 (min(i,j) + 3 max(i,j))), a symmetric function of the
/// two ends in [0.5, 1.5] with all 53 bits in use.
inline Network weighted_er(NodeIndex n, double q, std::uint64_t seed) {
  const Network net = erdos_renyi({n, q, seed});
  std::vector<double> weights;
  for (NodeIndex i = 0; i < n; ++i) {
    for (const auto [j, w] : net.row(i)) {
      weights.push_back(w * (1.0 + 0.5 * std::sin(0.37 * (std::min(i, j) + 3.0 * std::max(i, j)))));
    }
  }
  return Network::from_csr(n, net.row_ptr(), net.cols(), std::move(weights));
}

}  // namespace hmfnet::test
