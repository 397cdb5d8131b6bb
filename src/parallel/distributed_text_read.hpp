#pragma once
// Reading a Matrix Market or edge-list file in parallel (docs/scaling.md): no rank holds the
// whole file or the whole matrix. Every rank parses the header itself (a prefix of the file),
// then the entry lines of its own byte range (the body cut into equal byte ranges, each moved
// to the next line start; line numbers from a sum of the ranges' line counts, so errors still
// read FILE:LINE). The entries travel through a Tpetra::Distributor to the ranks owning their
// row and their column (both: the checks of network/network_builder.hpp need, for each row, every
// entry that touches it: a duplicate, the transpose of a `general` entry), each rank builds its
// rows with build_rows, and the counts that decide warnings and refusals (zeros, entries
// without transpose, emptiness, 0/1 weights) are summed over the ranks. Rows are cut by the
// stored entries counted from the file, which for a valid symmetric file are the degrees: the
// blocks are those a reader of the converted HDF5 file would cut.
//
// Memory per rank: its share of the file's bytes, then ~48 B per entry it parsed (entries and
// their packets), then 24 B per entry received (each entry reaches at most two ranks), then its
// rows; O(N) 16 B per node for the row counts.
#include <string>
#include <vector>

#include "io/read_options.hpp"
#include "network/row_block.hpp"

namespace hmfnet {

struct TextRows {
  RowBlock block;                     ///< this rank's rows
  std::vector<std::string> warnings;  ///< the serial reader's warnings, the same on every rank
};

/// Collective. An error on any rank (a malformed line in its range, a file it cannot open, a
/// duplicate among its rows) ends every rank with one CollectiveError carrying FILE:LINE of the
/// lowest rank that found one. The block equals the rows of read_network(path, options).
TextRows read_text_rows(const std::string& path, const ReadOptions& options);

}  // namespace hmfnet
