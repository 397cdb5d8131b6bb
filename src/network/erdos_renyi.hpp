#pragma once
// Erdos-Renyi G(N, q): each unordered pair {n, m}, n != m, is linked with probability q, so the
// mean degree is (N-1) q (paper, Sec. numericalExperiments). Generated in O(N + M) by geometric
// skipping over the pairs of each row (Batagelj & Brandes, Phys. Rev. E 71, 036113 (2005)).
// Row n draws its pairs {n, m > n} from random stream n of `seed`: the network does not depend
// on thread count or visiting order.
#include <cstdint>
#include <memory>

#include "network/edge_source.hpp"
#include "network/network.hpp"

namespace hmfnet {

struct ErdosRenyiParameters {
  NodeIndex n = 0;  ///< nodes, >= 1
  double q = 0.0;   ///< link probability, 0 <= q <= 1
  std::uint64_t seed = 0;
};

/// q giving mean degree `mean_degree` on n nodes: q = ||d|| / (N - 1).
/// Throws ParameterError unless 0 <= mean_degree <= n - 1.
double erdos_renyi_probability(NodeIndex n, double mean_degree);

/// Throws ParameterError for n < 1 or q outside [0, 1].
Network erdos_renyi(const ErdosRenyiParameters& params);

/// The same network unit by unit (unit n: row n's pairs {n, m > n}), for generating it by rows
/// over ranks. Throws as erdos_renyi.
std::unique_ptr<EdgeSource> erdos_renyi_source(const ErdosRenyiParameters& params);

}  // namespace hmfnet
