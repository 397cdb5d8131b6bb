#pragma once
// Writing the row blocks of all ranks into one hmfnet HDF5 network file, the same file
// write_network_hdf5 writes for the whole network, without gathering any O(nnz) array: rank 0
// creates the file under a temporary name (attributes from the totals over the ranks, datasets
// allocated), the ranks write their hyperslabs one after the other (serial HDF5: one writer at
// a time), and rank 0 renames it when every block is in. An error on any rank ends every rank
// with one CollectiveError and leaves no file under the final name.
#include <string>
#include <vector>

#include "network/row_block.hpp"

namespace hmfnet {

/// Collective. The blocks must tile the rows in rank order (as every reader and generator here
/// cuts them); `provenance` is JSON text, taken from rank 0. A non-empty `original_index` (N
/// entries, rank 0's) is written as /network/original_index: node i of this file was node
/// original_index[i] of the one it was renumbered from.
void write_distributed_network_hdf5(const std::string& path, const RowBlock& block,
                                    const std::string& provenance = "{}",
                                    const std::vector<NodeIndex>& original_index = {});

}  // namespace hmfnet
