#pragma once
// Reading a network file into row blocks over the ranks, so that no rank holds the whole matrix
// where the format allows it: hmfnet HDF5 CSR files are read by hyperslabs (each rank its own
// balanced block, io/network_hdf5.hpp); the complete graph stored implicitly needs no rows;
// text formats (Matrix Market, edge lists) are parsed by byte ranges, each rank its own, and
// their entries sent to the ranks owning them (parallel/distributed_text_read.hpp; `hmfnet
// convert` does it once for a file read many times).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/read_options.hpp"
#include "network/complete_graph.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// This rank's rows as read, before a DistributedNetwork takes them (what `convert` writes).
struct DistributedRows {
  RowBlock block;                         ///< no rows when `complete` is set
  std::optional<CompleteGraph> complete;  ///< set when the file holds K_N implicitly
  std::vector<std::string> warnings;      ///< the text readers' (ReadResult::warnings)
};

/// Collective; errors as read_distributed_input.
DistributedRows read_distributed_rows(const std::string& path, const ReadOptions& options = {});

struct DistributedInput {
  std::unique_ptr<DistributedNetwork> network;
  std::optional<CompleteGraph> complete;  ///< set when the file holds K_N implicitly
  std::vector<std::string> warnings;      ///< the text readers' (ReadResult::warnings)
};

/// Collective. An error on any rank (a file it cannot open, a corrupted entry in its block, an
/// asymmetric pair across blocks) ends every rank with one CollectiveError naming the file.
DistributedInput read_distributed_input(const std::string& path, const ReadOptions& options = {});

/// Checks that the blocks of all ranks form a symmetric matrix: for every node v, the entries
/// of row v and of column v are the same multiset (index, weight). Compared through 64-bit
/// signatures summed over the ranks (O(nnz / ranks) work, O(N) memory): a missing or
/// different transpose changes node v's signature except with probability ~2^-64. Collective;
/// throws CollectiveError on every rank naming `where` and the first such node.
void require_symmetric(const RowBlock& block, const std::string& where);

}  // namespace hmfnet
