#include "network/row_block.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/index_cast.hpp"

namespace hmfnet {

RowView RowBlock::row(NodeIndex r) const {
  const auto first = static_cast<std::size_t>(row_ptr[idx(r)]);
  const auto count = static_cast<std::size_t>(row_ptr[idx(r) + 1]) - first;
  return {cols.data() + first, weights.empty() ? nullptr : weights.data() + first, count};
}

EdgeOffset RowBlock::self_loops() const {
  EdgeOffset count = 0;
  for (NodeIndex r = 0; r < rows(); ++r) {
    const RowView entries = row(r);
    const NodeIndex i = first_row + r;
    count +=
        std::any_of(entries.begin(), entries.end(), [i](RowEntry e) { return e.col == i; }) ? 1 : 0;
  }
  return count;
}

std::vector<double> RowBlock::degrees() const {
  std::vector<double> d(idx(rows()), 0.0);
  for (NodeIndex r = 0; r < rows(); ++r) {
    double sum = 0.0;
    for (const auto entry : row(r)) sum += entry.weight;
    d[idx(r)] = sum;
  }
  return d;
}

RowBlock slice_rows(const Network& network, NodeIndex first, NodeIndex count) {
  if (first < 0 || count < 0 || first > network.size() - count) {
    throw ParameterError("row block", std::to_string(first) + " + " + std::to_string(count),
                         "inside [0, " + std::to_string(network.size()) + "]");
  }
  RowBlock block;
  block.n = network.size();
  block.first_row = first;
  const EdgeOffset begin = network.row_ptr()[idx(first)];
  const EdgeOffset end = network.row_ptr()[idx(first + count)];
  block.row_ptr.resize(idx(count) + 1);
  for (NodeIndex r = 0; r <= count; ++r) {
    block.row_ptr[idx(r)] = network.row_ptr()[idx(first + r)] - begin;
  }
  block.cols.assign(network.cols().begin() + begin, network.cols().begin() + end);
  if (network.weighted()) {
    block.weights.assign(network.weights().begin() + begin, network.weights().begin() + end);
  }
  return block;
}

std::string check_row_block(const RowBlock& block) {
  if (block.n < 0 || block.first_row < 0 || block.rows() < 0 ||
      block.first_row > block.n - block.rows()) {
    return "rows [" + std::to_string(block.first_row) + ", +" + std::to_string(block.rows()) +
           ") outside the " + std::to_string(block.n) + " nodes";
  }
  if (block.row_ptr.front() != 0) return "local row_ptr[0] is not 0";
  for (std::size_t r = 1; r < block.row_ptr.size(); ++r) {
    if (block.row_ptr[r] < block.row_ptr[r - 1] || block.row_ptr[r] > block.nnz()) {
      return "row_ptr of row " + std::to_string(block.first_row + static_cast<NodeIndex>(r) - 1) +
             " is outside [its predecessor, the block's nnz]";
    }
  }
  if (block.row_ptr.back() != block.nnz()) return "row_ptr does not end at the block's nnz";
  if (block.weighted() && block.weights.size() != block.cols.size()) {
    return "weights and columns differ in length";
  }
  return check_row_entries(block.n, block.first_row, block.row_ptr, block.cols, block.weights);
}

std::vector<NodeIndex> balanced_row_starts(
    NodeIndex n, int parts, const std::function<EdgeOffset(NodeIndex)>& entries_before) {
  if (parts < 1) throw ParameterError("row blocks", std::to_string(parts), ">= 1");
  const EdgeOffset nnz = entries_before(n);
  std::vector<NodeIndex> starts(idx(parts) + 1, n);
  starts[0] = 0;
  for (int p = 1; p < parts; ++p) {
    if (nnz == 0) {
      starts[idx(p)] = static_cast<NodeIndex>(static_cast<EdgeOffset>(n) * p / parts);
      continue;
    }
    // ceil(p nnz / parts) without overflow for nnz up to 2^62 / parts.
    const EdgeOffset target = (nnz * p + parts - 1) / parts;
    NodeIndex low = starts[idx(p) - 1], high = n;  // the first i with entries_before(i) >= target
    while (low < high) {
      const NodeIndex mid = low + (high - low) / 2;
      if (entries_before(mid) >= target) {
        high = mid;
      } else {
        low = mid + 1;
      }
    }
    starts[idx(p)] = low;
  }
  return starts;
}

std::vector<NodeIndex> balanced_row_starts(const std::vector<EdgeOffset>& row_ptr, int parts) {
  const auto n = static_cast<NodeIndex>(row_ptr.size() - 1);
  return balanced_row_starts(n, parts, [&row_ptr](NodeIndex i) { return row_ptr[idx(i)]; });
}

std::vector<EdgeOffset> row_pointers_from_counts(const std::vector<std::uint64_t>& counts) {
  std::vector<EdgeOffset> row_ptr(counts.size() + 1, 0);
  for (std::size_t i = 0; i < counts.size(); ++i)
    row_ptr[i + 1] = row_ptr[i] + static_cast<EdgeOffset>(counts[i]);
  return row_ptr;
}

}  // namespace hmfnet
