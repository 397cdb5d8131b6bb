#pragma once
// The structural facts of network/structure.hpp (components, the largest one, bipartiteness)
// for a network distributed by rows: each rank links the entries of its own rows in a
// ParityForest, and the forests merge up a binary tree of ranks (log2 P steps, 8 bytes per node
// per message), so no rank holds another's rows.
#include "network/structure.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

struct NetworkStructure {
  NodeIndex components = 0;  ///< isolated nodes count as components
  NodeIndex largest = 0;     ///< nodes in the largest component
  bool bipartite = true;     ///< 2-colourable along every stored entry (no self-loop)
};

/// Collective; the same answer on every rank. The complete graph held implicitly: its closed
/// forms (one component of n; bipartite only for n = 2 without self-loops).
NetworkStructure distributed_structure(const DistributedNetwork& network);

/// The components themselves (labels numbered by first node, as connected_components numbers
/// them: the same Components), on every rank (8 bytes per node travel from rank 0). Collective.
Components distributed_components(const DistributedNetwork& network);

}  // namespace hmfnet
