#pragma once
// Orders of the nodes that make the force kernel's gathers local (docs/performance.md): the kernel
// reads [cos, sin] of each stored entry's column, so rows whose columns sit close together reuse
// cache lines. Reverse Cuthill-McKee (Cuthill & McKee 1969, reversed as George 1971) narrows the
// band of a matrix with locality (lattices, geometric and spatial networks); by degree puts the
// hubs, the columns most rows read, side by side at the front (scale-free networks). Neither can
// help a network without structure (ER): any order of it has a band of ~N.
// Each returns new_index: node i becomes new_index[i] (a permutation of 0..n-1).
#include <string>
#include <vector>

#include "network/row_block.hpp"

namespace hmfnet {

enum class NodeOrder { original, rcm, degree };

/// "original", "rcm", "degree"; throws ParameterError naming `option` otherwise.
NodeOrder parse_node_order(const std::string& name, const std::string& option);
const char* name_of(NodeOrder order);

/// Reverse Cuthill-McKee over the whole network (`block` must hold every row): each connected
/// component from a pseudo-peripheral node of least degree (the end of repeated breadth-first
/// searches, Gibbs-Poole-Stockmeyer's start), breadth first with neighbours by increasing
/// degree (ties: old index), components in the order of their smallest node; the result
/// reversed. Deterministic. O(nnz) per search.
std::vector<NodeIndex> reverse_cuthill_mckee(const RowBlock& block);

/// Decreasing stored entries per row (the degree of a 0/1 network), ties in the old order;
/// `entries` of every node.
std::vector<NodeIndex> degree_order(const std::vector<double>& entries);

/// The inverse: original[new_index[i]] = i (what /network/original_index stores).
std::vector<NodeIndex> inverse_permutation(const std::vector<NodeIndex>& new_index);

/// max |new_index[i] - new_index[j]| over the stored entries (i, j) of the block: the band.
NodeIndex bandwidth(const RowBlock& block, const std::vector<NodeIndex>& new_index);

}  // namespace hmfnet
