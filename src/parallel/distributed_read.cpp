#include "parallel/distributed_read.hpp"

#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "core/random.hpp"
#include "io/network_file.hpp"
#include "io/network_hdf5.hpp"
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
  return format_from_extension(path) == NetworkFormat::hdf5 &&
         !read_implicit_network_hdf5(path).has_value();
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

DistributedInput read_distributed_input(const std::string& path, const ReadOptions& options) {
  DistributedInput input;
  bool by_blocks = false;
  ParallelSession::agree([&] { by_blocks = is_hdf5_with_rows(path); });
  if (by_blocks) {
    RowBlock block;
    ParallelSession::agree([&] {
      block = read_network_hdf5_rows(path, ParallelSession::rank(), ParallelSession::ranks());
    });
    require_symmetric(block, path);
    input.network = std::make_unique<DistributedNetwork>(std::move(block));
    return input;
  }
  NetworkInput whole;
  ParallelSession::agree([&] { whole = read_network_input(path, options); });
  input.warnings = std::move(whole.warnings);
  if (const auto* complete = whole.complete()) {
    input.complete = *complete;
    input.network = std::make_unique<DistributedNetwork>(*complete);
  } else {
    input.network = std::make_unique<DistributedNetwork>(whole.stored());
  }
  return input;
}

}  // namespace hmfnet
