#pragma once
// Structural facts that decide whether the theory applies: the Perron-Frobenius assumption
// behind eq:criticalKFirstOrder needs an irreducible A (one connected component), and on a
// bipartite network -lambda is an eigenvalue too (lambda_min = -lambda), so the Perron mode has a
// twin of equal magnitude.
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

struct Components {
  NodeIndex count = 0;
  std::vector<NodeIndex> label;  ///< component of each node, 0..count-1 by first node
  NodeIndex largest = 0;         ///< size of the largest component
};

/// Connected components by breadth-first search, O(N + nnz). Isolated nodes are components.
Components connected_components(const Network& network);

/// True if the nodes can be 2-coloured along every stored entry (no odd cycle, no self-loop).
/// Isolated nodes do not matter. Equivalent, for a non-negative symmetric A with at least one
/// edge, to the spectrum being symmetric about 0 (lambda_min = -lambda) on some component.
bool is_bipartite(const Network& network);

}  // namespace hmfnet
