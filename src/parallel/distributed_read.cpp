#include "parallel/distributed_read.hpp"

#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "core/random.hpp"
#include "io/network_file.hpp"
#include "io/network_hdf5.hpp"
#include "parallel/distributed_text_read.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

// Signature of an entry as seen from one of its ends: the other end and the weight, mixed by
// the splitmix64 finaliser (a bijection of 64 bits, so distinct (other, weight) rarely collide).
std::uint64_t entry_hash(NodeIndex other, double weight) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &weight, sizeof bits);
  std::uint64_t state = (static_cast<std::uint64_t>(other) << 32) ^ bits;
  return splitmix64(state);
}

bool is_hdf5_with_rows(const std::string& path) {
  return !read_implicit_network_hdf5(path).has_value();
}

}  // namespace

void require_symmetric(const RowBlock& block, const std::string& where) {
  // difference[v] = sig(row v) - sig(column v): row v's entries seen from v, minus the entries
  // (u, v) of every row u seen from v. Zero for every v iff symmetric (up to hash collisions).
  std::vector<std::uint64_t> difference(static_cast<std::size_t>(block.n), 0);
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    const NodeIndex u = block.first_row + r;
    for (const auto [v, w] : block.row(r)) {
      difference[static_cast<std::size_t>(u)] += entry_hash(v, w);
      difference[static_cast<std::size_t>(v)] -= entry_hash(u, w);
    }
  }
  ParallelSession::sum_in_place(difference);
  ParallelSession::agree([&] {
    for (std::size_t v = 0; v < difference.size(); ++v) {
      if (difference[v] == 0) continue;
      throw InputError(where, 0,
                       "the matrix is not symmetric: row " + std::to_string(v) + " and column " +
                           std::to_string(v) +
                           " differ (an entry without its transpose, or with a different weight)");
    }
  });
}

DistributedRows read_distributed_rows(const std::string& path, const ReadOptions& options) {
  DistributedRows rows;
  bool by_blocks = false;
  bool text = false;
  ParallelSession::agree([&] {
    text = format_from_extension(path) != NetworkFormat::hdf5;
    by_blocks = !text && is_hdf5_with_rows(path);
  });
  if (by_blocks) {
    ParallelSession::agree([&] {
      rows.block = read_network_hdf5_rows(path, ParallelSession::rank(), ParallelSession::ranks());
    });
    require_symmetric(rows.block, path);
  } else if (text) {
    TextRows read = read_text_rows(path, options);
    rows.block = std::move(read.block);
    rows.warnings = std::move(read.warnings);
  } else {
    // An hmfnet HDF5 file without rows: the complete graph held implicitly.
    ParallelSession::agree([&] { rows.complete = read_implicit_network_hdf5(path); });
  }
  return rows;
}

DistributedInput read_distributed_input(const std::string& path, const ReadOptions& options) {
  DistributedRows rows = read_distributed_rows(path, options);
  DistributedInput input;
  input.warnings = std::move(rows.warnings);
  input.complete = rows.complete;
  input.network = rows.complete ? std::make_unique<DistributedNetwork>(*rows.complete)
                                : std::make_unique<DistributedNetwork>(std::move(rows.block));
  return input;
}

}  // namespace hmfnet
