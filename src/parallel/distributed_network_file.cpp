#include "parallel/distributed_network_file.hpp"

#include <memory>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "io/network_hdf5.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

// Per rank: rows, stored entries, self-loops, weighted (0/1); summed so every rank has all.
struct BlockCounts {
  std::vector<std::uint64_t> rows, nnz, self_loops, weighted;
};

BlockCounts gather_counts(const RowBlock& block) {
  const auto gather = [](std::int64_t mine) {
    const std::vector<std::int64_t> all = ParallelSession::all_gather(mine);
    return std::vector<std::uint64_t>(all.begin(), all.end());
  };
  return {gather(block.rows()), gather(block.nnz()), gather(block.self_loops()),
          gather(block.weighted() ? 1 : 0)};
}

}  // namespace

void write_distributed_network_hdf5(const std::string& path, const RowBlock& block,
                                    const std::string& provenance,
                                    const std::vector<NodeIndex>& original_index) {
  const BlockCounts counts = gather_counts(block);
  const int me = ParallelSession::rank();
  NetworkTotals totals{block.n, 0, 0, false};
  EdgeOffset entries_before = 0;
  std::uint64_t rows_before = 0;
  for (std::size_t p = 0; p < counts.rows.size(); ++p) {
    if (static_cast<int>(p) < me) {
      entries_before += static_cast<EdgeOffset>(counts.nnz[p]);
      rows_before += counts.rows[p];
    }
    totals.nnz += static_cast<EdgeOffset>(counts.nnz[p]);
    totals.self_loops += static_cast<EdgeOffset>(counts.self_loops[p]);
    // A block without entries cannot say whether the network is weighted.
    totals.weighted = totals.weighted || counts.weighted[p] != 0;
  }
  ParallelSession::agree([&] {
    if (rows_before != static_cast<std::uint64_t>(block.first_row) ||
        (me + 1 == ParallelSession::ranks() &&
         rows_before + static_cast<std::uint64_t>(block.rows()) !=
             static_cast<std::uint64_t>(block.n))) {
      throw InputError(path, 0,
                       "the row blocks do not tile the " + std::to_string(block.n) +
                           " rows in rank order (this block starts at row " +
                           std::to_string(block.first_row) + ")");
    }
    if (totals.weighted && !block.weighted() && block.nnz() > 0) {
      throw InputError(path, 0, "some row blocks are weighted and some are not");
    }
  });
  std::unique_ptr<AtomicFile> out;
  std::string temp;
  ParallelSession::agree([&] {
    if (me != 0) return;
    out = std::make_unique<AtomicFile>(path);
    create_network_hdf5(out->temp_path(), totals, provenance);
    if (!original_index.empty()) write_original_index(out->temp_path(), original_index);
    temp = out->temp_path();
  });
  ParallelSession::broadcast(temp, 0);
  for (int writer = 0; writer < ParallelSession::ranks(); ++writer) {
    ParallelSession::agree([&] {
      if (me == writer) write_network_hdf5_rows(temp, block, entries_before);
    });
  }
  ParallelSession::agree([&] {
    if (me == 0) out->commit();
  });
}

}  // namespace hmfnet
