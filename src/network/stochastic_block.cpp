#include "network/stochastic_block.hpp"

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/random.hpp"

namespace hmfnet {

namespace {

void require_probability(const char* name, double p) {
  if (!(p >= 0.0 && p <= 1.0)) throw ParameterError(name, std::to_string(p), "0 <= p <= 1");
}

}  // namespace

Network two_block_sbm(const TwoBlockParameters& p) {
  if (p.half < 1 || p.half > std::numeric_limits<NodeIndex>::max() / 2) {
    throw ParameterError("half", std::to_string(p.half), "1 <= half <= 2^30");
  }
  require_probability("p_in", p.p_in);
  require_probability("p_out", p.p_out);
  const NodeIndex n = 2 * p.half;
  std::vector<std::pair<NodeIndex, NodeIndex>> edges;
  for (NodeIndex i = 0; i < n; ++i) {
    Rng rng(p.seed, static_cast<std::uint64_t>(i));
    for (NodeIndex j = i + 1; j < n; ++j) {
      const bool same = (i < p.half) == (j < p.half);
      if (rng.uniform() < (same ? p.p_in : p.p_out)) edges.emplace_back(i, j);
    }
  }
  return Network::from_undirected_edges(n, edges);  // pairs in increasing (i, j): sorted rows
}

}  // namespace hmfnet
