#pragma once
// One rank's share of a network: the rows [first_row, first_row + rows()) of the symmetric CSR
// matrix of network.hpp, with global column indices. What a rank reads (io/network_hdf5.hpp reads
// a block by hyperslabs) or slices from a replicated Network; DistributedNetwork takes it over,
// so no rank ever needs the whole matrix.
//
// The blocks of a network are contiguous and cover the rows in rank order; balanced_row_starts
// cuts them so that every rank holds about the same number of stored entries (a hub's row is
// never split, so a rank may hold more than nnz / parts by at most one row, and a later rank may
// be left with no rows when one row holds more than its share: a star whose hub is the last
// node, on 3 ranks, gives blocks of 666, 334 and 0 rows).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

struct RowBlock {
  NodeIndex n = 0;                     ///< nodes of the whole network
  NodeIndex first_row = 0;             ///< global index of the first row held here
  std::vector<EdgeOffset> row_ptr{0};  ///< local: row_ptr[0] = 0, rows() + 1 entries
  std::vector<NodeIndex> cols;         ///< global column indices, ascending within a row
  std::vector<double> weights;         ///< empty: a 0/1 block (every stored entry is 1)

  NodeIndex rows() const { return static_cast<NodeIndex>(row_ptr.size() - 1); }
  EdgeOffset nnz() const { return static_cast<EdgeOffset>(cols.size()); }
  bool weighted() const { return !weights.empty(); }
  /// Local row r (global row first_row + r): its entries in ascending column order.
  RowView row(NodeIndex r) const;
  /// Diagonal entries A_ii stored in these rows.
  EdgeOffset self_loops() const;
  /// d_i = sum_j A_ij of the rows held here, in row order.
  std::vector<double> degrees() const;
};

/// Rows [first, first + count) of a replicated network, copied.
RowBlock slice_rows(const Network& network, NodeIndex first, NodeIndex count);

/// The first violated invariant of the block (shape, then check_row_entries), or "".
std::string check_row_block(const RowBlock& block);

/// Starts of `parts` contiguous row blocks of n rows (parts + 1 entries: starts[0] = 0,
/// starts[parts] = n) that hold about equal stored entries: block p starts at the first row i
/// with entries_before(i) >= ceil(p nnz / parts). entries_before(i) is the number of stored
/// entries in rows [0, i) (non-decreasing; entries_before(n) = nnz). With no entries at all the
/// rows are split evenly.
std::vector<NodeIndex> balanced_row_starts(
    NodeIndex n, int parts, const std::function<EdgeOffset(NodeIndex)>& entries_before);
/// The same, from the global CSR row pointers (n + 1 entries).
std::vector<NodeIndex> balanced_row_starts(const std::vector<EdgeOffset>& row_ptr, int parts);

/// CSR row pointers (counts.size() + 1 entries, starting at 0) of rows holding counts[i] stored
/// entries each: what the parallel builders cut rows from once the counts are summed over ranks.
std::vector<EdgeOffset> row_pointers_from_counts(const std::vector<std::uint64_t>& counts);

}  // namespace hmfnet
