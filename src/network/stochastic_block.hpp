#pragma once
// Two-block stochastic block model: two communities of `half` nodes each; each unordered pair
// is linked with probability p_in inside a community and p_out between them. The networks that
// break the theory's single-mode picture (Sec. approxOnsetSynchrony assumes a simple, isolated
// lambda): p_out << p_in gives a near-degenerate lambda (lambda ~ half (p_in + p_out), lambda_2
// ~ half (p_in - p_out)); p_out = 0 two disconnected communities; p_in = 0 a random bipartite
// network (-lambda is an eigenvalue). O(N^2) draws (pair by pair, row n from random stream n of
// `seed`, so the network does not depend on visiting order): meant for N up to ~10^4.
#include <cstdint>
#include <memory>

#include "network/edge_source.hpp"
#include "network/network.hpp"

namespace hmfnet {

struct TwoBlockParameters {
  NodeIndex half = 0;  ///< nodes per community, >= 1
  double p_in = 0.0;   ///< link probability inside a community, in [0, 1]
  double p_out = 0.0;  ///< link probability between the communities, in [0, 1]
  std::uint64_t seed = 0;
};

/// Nodes 0 .. half-1 form the first community. Throws ParameterError for half < 1, 2 half
/// beyond NodeIndex, or a probability outside [0, 1].
Network two_block_sbm(const TwoBlockParameters& params);

/// The same network unit by unit (unit i: row i's pairs {i, j > i}). Throws as two_block_sbm.
std::unique_ptr<EdgeSource> two_block_sbm_source(const TwoBlockParameters& params);

}  // namespace hmfnet
