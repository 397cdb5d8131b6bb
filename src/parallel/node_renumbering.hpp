#pragma once
// Renaming the nodes of a network distributed by rows, so that the nodes of each part of a
// partition (parallel/graph_partition.hpp) get consecutive indices and the contiguous row
// blocks every reader cuts follow the parts. The new index of every node is an O(N) vector held
// by every rank (as the degrees are); the entries travel to their new owners through
// parallel/entry_exchange.hpp, so no rank holds more than its rows.
#include <vector>

#include "network/row_block.hpp"

namespace hmfnet {

struct PartOrder {
  std::vector<NodeIndex> new_index;   ///< node i becomes new_index[i] (all N, on every rank)
  std::vector<NodeIndex> part_start;  ///< part p holds the new indices [start[p], start[p+1])
};

/// Collective. Part 0's nodes first, then part 1's, ..., each part in the old order; `part`
/// holds the part of each row of `block`.
PartOrder order_by_part(const RowBlock& block, const std::vector<int>& part, int parts);

/// Collective. This rank's rows of the network with node i renamed new_index[i] (a
/// permutation), cut by stored entries as a reader cuts them (balanced_row_starts).
RowBlock renumber_rows(const RowBlock& block, const std::vector<NodeIndex>& new_index);

/// Collective. Stored entries (i, j) of the whole network with i and j in different parts
/// (the new indices of `order`), summed over the ranks: twice the edges the partition cuts.
std::int64_t cut_entries(const RowBlock& renumbered, const PartOrder& order);

}  // namespace hmfnet
