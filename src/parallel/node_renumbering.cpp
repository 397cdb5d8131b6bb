#include "parallel/node_renumbering.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>

#include "parallel/entry_exchange.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {
std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }
}  // namespace

PartOrder order_by_part(const RowBlock& block, const std::vector<int>& part, int parts) {
  const auto ranks = at(ParallelSession::ranks());
  const auto me = at(ParallelSession::rank());
  // count[p * ranks + q]: rows of rank q in part p.
  std::vector<std::uint64_t> count(at(parts) * ranks, 0);
  for (const int p : part) ++count[at(p) * ranks + me];
  ParallelSession::sum_in_place(count);
  PartOrder order;
  order.part_start.assign(at(parts) + 1, 0);
  std::vector<std::uint64_t> next(at(parts), 0);  // this rank's first new index in each part
  std::uint64_t before = 0;
  for (std::size_t p = 0; p < at(parts); ++p) {
    order.part_start[p] = static_cast<NodeIndex>(before);
    for (std::size_t q = 0; q < ranks; ++q) {
      if (q == me) next[p] = before;
      before += count[p * ranks + q];
    }
  }
  order.part_start[at(parts)] = static_cast<NodeIndex>(before);
  std::vector<std::uint64_t> index(at(block.n), 0);
  for (NodeIndex r = 0; r < block.rows(); ++r)
    index[at(block.first_row + r)] = next[at(part[at(r)])]++;
  ParallelSession::sum_in_place(index);
  order.new_index.assign(index.begin(), index.end());
  return order;
}

RowBlock renumber_rows(const RowBlock& block, const std::vector<NodeIndex>& new_index) {
  // The renamed network's degrees, then its rows cut by stored entries.
  std::vector<std::uint64_t> degree(at(block.n), 0);
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    degree[at(new_index[at(block.first_row + r)])] =
        static_cast<std::uint64_t>(block.row_ptr[at(r) + 1] - block.row_ptr[at(r)]);
  }
  ParallelSession::sum_in_place(degree);
  const std::vector<EdgeOffset> row_ptr = row_pointers_from_counts(degree);
  degree = {};
  const std::vector<NodeIndex> starts = balanced_row_starts(row_ptr, ParallelSession::ranks());
  const bool weighted = ParallelSession::max(block.weighted() ? 1.0 : 0.0) > 0.0;

  std::vector<MatrixEntry> entries;
  entries.reserve(at(block.nnz()));
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    const NodeIndex row = new_index[at(block.first_row + r)];
    for (const auto [col, w] : block.row(r)) entries.push_back({row, new_index[at(col)], w, 0});
  }
  std::vector<MatrixEntry> mine = send_to_owners(entries, starts, Destinations::row_owner);
  entries = {};
  std::sort(mine.begin(), mine.end(), [](const MatrixEntry& a, const MatrixEntry& b) {
    return std::tie(a.row, a.col) < std::tie(b.row, b.col);
  });

  RowBlock out;
  out.n = block.n;
  out.first_row = starts[at(ParallelSession::rank())];
  const NodeIndex last = starts[at(ParallelSession::rank()) + 1];
  out.row_ptr.assign(at(last - out.first_row) + 1, 0);
  for (NodeIndex r = out.first_row; r < last; ++r) {
    out.row_ptr[at(r - out.first_row) + 1] =
        out.row_ptr[at(r - out.first_row)] + row_ptr[at(r) + 1] - row_ptr[at(r)];
  }
  out.cols.reserve(mine.size());
  for (const auto& e : mine) {
    out.cols.push_back(e.col);
    if (weighted) out.weights.push_back(e.weight);
  }
  ParallelSession::agree([&] {
    const std::string why = check_row_block(out);
    if (!why.empty()) throw std::logic_error("renumbering: " + why);
  });
  return out;
}

std::int64_t cut_entries(const RowBlock& renumbered, const PartOrder& order) {
  const auto part_of = [&](NodeIndex i) {
    return std::upper_bound(order.part_start.begin(), order.part_start.end(), i) -
           order.part_start.begin();
  };
  double cut = 0.0;
  for (NodeIndex r = 0; r < renumbered.rows(); ++r) {
    const auto p = part_of(renumbered.first_row + r);
    for (const auto [col, w] : renumbered.row(r)) cut += part_of(col) != p ? 1.0 : 0.0;
  }
  return static_cast<std::int64_t>(ParallelSession::sum(cut));
}

}  // namespace hmfnet
