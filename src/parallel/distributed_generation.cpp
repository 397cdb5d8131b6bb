#include "parallel/distributed_generation.hpp"

#include <Tpetra_Core.hpp>
#include <Tpetra_Distributor.hpp>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }

// One stored entry (row, col) in 64 bits, row high: what travels to the owner of the row.
long long pack(NodeIndex row, NodeIndex col) {
  return static_cast<long long>((static_cast<std::uint64_t>(row) << 32) |
                                static_cast<std::uint32_t>(col));
}
NodeIndex row_of(long long entry) { return static_cast<NodeIndex>(entry >> 32); }
NodeIndex col_of(long long entry) {
  return static_cast<NodeIndex>(static_cast<std::uint64_t>(entry) & 0xffffffffULL);
}

// This rank's units [first, last) and how many edges each emits (first pass, which also counts
// every node's degree over all ranks).
struct UnitShare {
  std::int64_t first = 0;
  std::int64_t last = 0;
  std::vector<std::uint32_t> edges;  // a unit emits fewer than N < 2^31 edges
};

UnitShare count_degrees(const EdgeSource& source, std::vector<std::uint64_t>& degree) {
  const auto starts = balanced_unit_starts(source, ParallelSession::ranks());
  UnitShare share;
  // Allocations and the source may throw on one rank: all ranks learn it before the reduction.
  ParallelSession::agree([&] {
    share.first = starts[at(ParallelSession::rank())];
    share.last = starts[at(ParallelSession::rank()) + 1];
    share.edges.resize(at(share.last - share.first));
    degree.assign(at(source.nodes()), 0);
    std::vector<Edge> edges;
    for (std::int64_t k = share.first; k < share.last; ++k) {
      edges.clear();
      source.emit(k, edges);
      share.edges[at(k - share.first)] = static_cast<std::uint32_t>(edges.size());
      for (const auto& [u, v] : edges) {
        if (u == v) {
          throw std::logic_error("distributed generation: unit " + std::to_string(k) +
                                 " emitted a self-loop at node " + std::to_string(u));
        }
        ++degree[at(u)];
        ++degree[at(v)];
      }
    }
  });
  ParallelSession::sum_in_place(degree);
  return share;
}

// The empty block of this rank's rows: pointers from the global degrees, columns allocated.
RowBlock allocate_block(const std::vector<std::uint64_t>& degree,
                        std::vector<NodeIndex>& row_starts) {
  const std::size_t n = degree.size();
  const std::vector<EdgeOffset> row_ptr = row_pointers_from_counts(degree);
  row_starts = balanced_row_starts(row_ptr, ParallelSession::ranks());
  RowBlock block;
  block.n = static_cast<NodeIndex>(n);
  block.first_row = row_starts[at(ParallelSession::rank())];
  const NodeIndex last = row_starts[at(ParallelSession::rank()) + 1];
  const EdgeOffset begin = row_ptr[at(block.first_row)];
  block.row_ptr.assign(row_ptr.begin() + block.first_row, row_ptr.begin() + last + 1);
  for (auto& p : block.row_ptr) p -= begin;
  block.cols.resize(at(block.row_ptr.back()));
  return block;
}

// Unit ranges of this rank holding at most `chunk` edges each (a unit is never split).
std::vector<std::int64_t> round_starts(const UnitShare& share, std::int64_t chunk) {
  std::vector<std::int64_t> starts{share.first};
  std::int64_t in_round = 0;
  for (std::int64_t k = share.first; k < share.last; ++k) {
    const std::int64_t e = share.edges[at(k - share.first)];
    if (in_round > 0 && in_round + e > chunk) {
      starts.push_back(k);
      in_round = 0;
    }
    in_round += e;
  }
  if (share.last > share.first) starts.push_back(share.last);
  return starts;
}

// Both entries of each edge, grouped by the rank owning their row (what createFromSends wants).
void pack_by_owner(const std::vector<Edge>& edges, const std::vector<NodeIndex>& row_starts,
                   std::vector<int>& owner, std::vector<long long>& packets) {
  const auto owner_of = [&](NodeIndex row) {
    return static_cast<int>(std::upper_bound(row_starts.begin(), row_starts.end(), row) -
                            row_starts.begin()) -
           1;
  };
  const std::size_t ranks = row_starts.size() - 1;
  std::vector<std::size_t> next(ranks + 1, 0);
  for (const auto& [u, v] : edges) {
    ++next[at(owner_of(u)) + 1];
    ++next[at(owner_of(v)) + 1];
  }
  for (std::size_t p = 0; p < ranks; ++p) next[p + 1] += next[p];
  owner.resize(2 * edges.size());
  packets.resize(2 * edges.size());
  for (const auto& [u, v] : edges) {
    for (const auto& [row, col] : {Edge{u, v}, Edge{v, u}}) {
      const int p = owner_of(row);
      const std::size_t slot = next[at(p)]++;
      owner[slot] = p;
      packets[slot] = pack(row, col);
    }
  }
}

void place(const std::vector<long long>& received, RowBlock& block,
           std::vector<EdgeOffset>& cursor) {
  for (const long long entry : received) {
    const auto r = at(row_of(entry) - block.first_row);
    if (r >= cursor.size() || cursor[r] >= block.row_ptr[r + 1]) {
      throw std::logic_error("distributed generation: an entry of row " +
                             std::to_string(row_of(entry)) +
                             " beyond the degree counted for it (a source that is not "
                             "deterministic?)");
    }
    block.cols[at(cursor[r]++)] = col_of(entry);
  }
}

}  // namespace

RowBlock generate_distributed(const EdgeSource& source, std::int64_t chunk_edges) {
  std::vector<std::uint64_t> degree;
  const UnitShare share = count_degrees(source, degree);
  std::vector<NodeIndex> row_starts;
  RowBlock block;
  ParallelSession::agree([&] { block = allocate_block(degree, row_starts); });
  degree = {};
  std::vector<EdgeOffset> cursor(block.row_ptr.begin(), block.row_ptr.end() - 1);

  const std::vector<std::int64_t> rounds_here =
      round_starts(share, std::max<std::int64_t>(chunk_edges, 1));
  const auto mine = static_cast<double>(rounds_here.size()) - 1.0;
  const auto rounds = static_cast<std::int64_t>(ParallelSession::max(std::max(mine, 0.0)));
  const auto comm = Tpetra::getDefaultComm();
  std::vector<Edge> edges;
  std::vector<int> owner;
  std::vector<long long> packets;
  std::vector<long long> received;
  for (std::int64_t round = 0; round < rounds; ++round) {
    ParallelSession::agree([&] {
      edges.clear();
      if (round + 1 < static_cast<std::int64_t>(rounds_here.size())) {
        for (std::int64_t k = rounds_here[at(round)]; k < rounds_here[at(round) + 1]; ++k) {
          source.emit(k, edges);
        }
      }
      pack_by_owner(edges, row_starts, owner, packets);
    });
    Tpetra::Distributor distributor(comm);
    received.resize(distributor.createFromSends(Teuchos::ArrayView<const int>(owner)));
    distributor.doPostsAndWaits<long long>(Teuchos::ArrayView<const long long>(packets), 1,
                                           Teuchos::ArrayView<long long>(received));
    ParallelSession::agree([&] { place(received, block, cursor); });
  }
  ParallelSession::agree([&] {
    for (std::size_t r = 0; r < cursor.size(); ++r) {
      if (cursor[r] != block.row_ptr[r + 1]) {
        throw std::logic_error("distributed generation: row " +
                               std::to_string(block.first_row + static_cast<NodeIndex>(r)) +
                               " received fewer entries than its degree");
      }
    }
  });
#pragma omp parallel for schedule(dynamic, 1024)
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    std::sort(block.cols.begin() + block.row_ptr[at(r)],
              block.cols.begin() + block.row_ptr[at(r) + 1]);
  }
  // A pair emitted twice (by two units, or twice by one) would be a duplicate entry.
  ParallelSession::agree([&] {
    const std::string why = check_row_block(block);
    if (!why.empty()) throw std::logic_error("distributed generation: " + why);
  });
  return block;
}

}  // namespace hmfnet
