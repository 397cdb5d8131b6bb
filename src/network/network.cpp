#include "network/network.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/index_cast.hpp"

namespace hmfnet {

namespace {

// Position of column j in row i, or -1. Rows are sorted, so binary search.
EdgeOffset find_in_row(const std::vector<EdgeOffset>& row_ptr, const std::vector<NodeIndex>& cols,
                       NodeIndex i, NodeIndex j) {
  const auto first = cols.begin() + row_ptr[idx(i)];
  const auto last = cols.begin() + row_ptr[idx(i) + 1];
  const auto it = std::lower_bound(first, last, j);
  return (it != last && *it == j) ? static_cast<EdgeOffset>(it - cols.begin()) : -1;
}

std::string entry_name(NodeIndex i, NodeIndex j) {
  return "(" + std::to_string(i) + "," + std::to_string(j) + ")";
}

std::string check_shape(NodeIndex n, const std::vector<EdgeOffset>& row_ptr,
                        const std::vector<NodeIndex>& cols, const std::vector<double>& weights) {
  if (n < 0) return "negative node count " + std::to_string(n);
  if (row_ptr.size() != idx(n) + 1) {
    return "row_ptr has " + std::to_string(row_ptr.size()) +
           " entries, expected n+1 = " + std::to_string(idx(n) + 1);
  }
  if (row_ptr.front() != 0) return "row_ptr[0] = " + std::to_string(row_ptr.front()) + ", not 0";
  if (row_ptr.back() != static_cast<EdgeOffset>(cols.size())) {
    return "row_ptr[n] = " + std::to_string(row_ptr.back()) + " but there are " +
           std::to_string(cols.size()) + " column indices";
  }
  for (std::size_t i = 0; i < idx(n); ++i) {
    if (row_ptr[i + 1] < row_ptr[i] || row_ptr[i + 1] > row_ptr.back()) {
      return "row_ptr[" + std::to_string(i + 1) + "] = " + std::to_string(row_ptr[i + 1]) +
             " is outside [row_ptr[" + std::to_string(i) + "], nnz]";
    }
  }
  if (!weights.empty() && weights.size() != cols.size()) {
    return "weights has " + std::to_string(weights.size()) + " entries, cols has " +
           std::to_string(cols.size());
  }
  return {};
}

std::string check_symmetry(NodeIndex n, const std::vector<EdgeOffset>& row_ptr,
                           const std::vector<NodeIndex>& cols, const std::vector<double>& weights) {
  for (NodeIndex i = 0; i < n; ++i) {
    for (EdgeOffset k = row_ptr[idx(i)]; k < row_ptr[idx(i) + 1]; ++k) {
      const NodeIndex j = cols[idx(k)];
      if (j <= i) continue;
      const EdgeOffset t = find_in_row(row_ptr, cols, j, i);
      if (t < 0) return "entry " + entry_name(i, j) + " has no transpose " + entry_name(j, i);
      if (!weights.empty() && weights[idx(t)] != weights[idx(k)]) {
        return "entry " + entry_name(i, j) + " and its transpose have different weights";
      }
    }
  }
  return {};
}

}  // namespace

std::string check_row_entries(NodeIndex n, NodeIndex first_row,
                              const std::vector<EdgeOffset>& row_ptr,
                              const std::vector<NodeIndex>& cols,
                              const std::vector<double>& weights) {
  const auto rows = static_cast<NodeIndex>(row_ptr.size() - 1);
  for (NodeIndex r = 0; r < rows; ++r) {
    const NodeIndex i = first_row + r;
    const EdgeOffset b = row_ptr[idx(r)], e = row_ptr[idx(r) + 1];
    for (EdgeOffset k = b; k < e; ++k) {
      const NodeIndex j = cols[idx(k)];
      if (j < 0 || j >= n) {
        return "column index " + std::to_string(j) + " in row " + std::to_string(i) +
               " out of range [0," + std::to_string(n) + ")";
      }
      if (k > b && cols[idx(k - 1)] >= j) {
        return "row " + std::to_string(i) + " has unsorted or duplicate column " +
               std::to_string(j);
      }
      if (!weights.empty()) {
        const double w = weights[idx(k)];
        if (!std::isfinite(w) || w <= 0.0) {
          return "entry " + entry_name(i, j) + " has weight " + std::to_string(w) +
                 " (weights must be finite and > 0)";
        }
      }
    }
  }
  return {};
}

std::string Network::check_csr(NodeIndex n, const std::vector<EdgeOffset>& row_ptr,
                               const std::vector<NodeIndex>& cols,
                               const std::vector<double>& weights) {
  std::string why = check_shape(n, row_ptr, cols, weights);
  if (why.empty()) why = check_row_entries(n, 0, row_ptr, cols, weights);
  if (why.empty()) why = check_symmetry(n, row_ptr, cols, weights);
  return why;
}

Network Network::from_csr(NodeIndex n, std::vector<EdgeOffset> row_ptr, std::vector<NodeIndex> cols,
                          std::vector<double> weights) {
  const std::string why = check_csr(n, row_ptr, cols, weights);
  if (!why.empty()) {
    throw ParameterError("CSR network", why,
                         "sorted in-range columns, symmetric, finite weights > 0");
  }
  return from_trusted_csr(n, std::move(row_ptr), std::move(cols), std::move(weights));
}

Network Network::from_trusted_csr(NodeIndex n, std::vector<EdgeOffset> row_ptr,
                                  std::vector<NodeIndex> cols, std::vector<double> weights) {
  Network net;
  net.m_n = n;
  net.m_row_ptr = std::move(row_ptr);
  net.m_cols = std::move(cols);
  net.m_weights = std::move(weights);
  return net;
}

Network Network::from_undirected_edges(NodeIndex n,
                                       const std::vector<std::pair<NodeIndex, NodeIndex>>& edges) {
  Network net;
  net.m_n = n;
  net.m_row_ptr.assign(idx(n) + 1, 0);
  for (const auto& [u, v] : edges) {
    if (u < 0 || u >= n || v < 0 || v >= n) {
      throw ParameterError("edge " + entry_name(u, v), "node index out of range",
                           "0 <= u, v < n = " + std::to_string(n));
    }
    ++net.m_row_ptr[idx(u) + 1];
    if (u != v) ++net.m_row_ptr[idx(v) + 1];
  }
  for (std::size_t i = 0; i < idx(n); ++i) net.m_row_ptr[i + 1] += net.m_row_ptr[i];
  net.m_cols.resize(idx(net.m_row_ptr.back()));
  std::vector<EdgeOffset> fill(net.m_row_ptr.begin(), net.m_row_ptr.end() - 1);
  for (const auto& [u, v] : edges) {
    net.m_cols[idx(fill[idx(u)]++)] = v;
    if (u != v) net.m_cols[idx(fill[idx(v)]++)] = u;
  }
  for (NodeIndex i = 0; i < n; ++i) {
    const auto first = net.m_cols.begin() + net.row_begin(i);
    const auto last = net.m_cols.begin() + net.row_end(i);
    if (!std::is_sorted(first, last)) std::sort(first, last);
    if (std::adjacent_find(first, last) != last) {
      throw ParameterError("edge list", "repeats a pair at node " + std::to_string(i),
                           "each pair once, in either orientation");
    }
  }
  return net;
}

EdgeOffset Network::self_loops() const {
  EdgeOffset count = 0;
  for (NodeIndex i = 0; i < m_n; ++i) count += has_entry(i, i) ? 1 : 0;
  return count;
}

std::vector<double> Network::degrees() const {
  std::vector<double> d(idx(m_n), 0.0);
  for (NodeIndex i = 0; i < m_n; ++i) {
    if (m_weights.empty()) {
      d[idx(i)] = static_cast<double>(row_end(i) - row_begin(i));
      continue;
    }
    double sum = 0.0;
    for (EdgeOffset k = row_begin(i); k < row_end(i); ++k) sum += m_weights[idx(k)];
    d[idx(i)] = sum;
  }
  return d;
}

bool Network::has_entry(NodeIndex i, NodeIndex j) const {
  return find_in_row(m_row_ptr, m_cols, i, j) >= 0;
}

}  // namespace hmfnet
