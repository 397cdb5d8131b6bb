#pragma once
// The one network type: a symmetric sparse adjacency matrix A in CSR form
// (eq:hamiltonianNetworkCase: A symmetric, A_nm >= 0, weights allowed).
//
// Conventions (kept everywhere in hmfnet):
//  - rows and columns are 0-based int32 node indices; row pointers are int64 (nnz may pass 2^31);
//  - columns within a row are strictly increasing (no duplicate entries);
//  - a 0/1 network stores no values (weights() is empty, every stored entry is 1);
//  - the matrix is stored in full (both (i,j) and (j,i)); a self-loop A_nn is one stored entry;
//  - degree d_n = sum_m A_nm (weighted; a self-loop counted once);
//  - edges() counts unordered pairs, a self-loop once: nnz = 2 (edges - self_loops) + self_loops.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace hmfnet {

using NodeIndex = std::int32_t;
using EdgeOffset = std::int64_t;

/// One stored entry A_ij of a row: its column j and weight A_ij (1.0 in a 0/1 network).
struct RowEntry {
  NodeIndex col;
  double weight;
};

/// The stored entries of one row, in storage order (ascending column), as a range:
/// `for (auto [j, w] : network.row(i))`. A sum over it adds in the same order as a CSR loop
/// over row_begin(i)..row_end(i). Borrows the network's arrays: valid while the network lives
/// unchanged.
class RowView {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = RowEntry;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = RowEntry;

    iterator(const NodeIndex* col, const double* weight) : m_col(col), m_weight(weight) {}
    RowEntry operator*() const { return {*m_col, m_weight != nullptr ? *m_weight : 1.0}; }
    iterator& operator++() {
      ++m_col;
      if (m_weight != nullptr) ++m_weight;
      return *this;
    }
    bool operator==(const iterator& other) const { return m_col == other.m_col; }
    bool operator!=(const iterator& other) const { return m_col != other.m_col; }

   private:
    const NodeIndex* m_col;
    const double* m_weight;  ///< nullptr: a 0/1 network, every weight 1.0
  };

  RowView(const NodeIndex* cols, const double* weights, std::size_t count)
      : m_cols(cols), m_weights(weights), m_count(count) {}
  iterator begin() const { return {m_cols, m_weights}; }
  iterator end() const {
    return {m_cols + m_count, m_weights != nullptr ? m_weights + m_count : nullptr};
  }
  std::size_t size() const { return m_count; }
  bool empty() const { return m_count == 0; }

 private:
  const NodeIndex* m_cols;
  const double* m_weights;
  std::size_t m_count;
};

/// The first violated per-row invariant of rows [first_row, first_row + row_ptr.size() - 1) of a
/// network of n nodes (columns in [0, n), strictly increasing within a row, weights finite and
/// > 0), or an empty string. row_ptr is local (row_ptr[0] = 0) and already bounded by cols.size().
/// Symmetry spans rows, so it is not checked here (Network::check_csr; across ranks,
/// require_symmetric in parallel/distributed_read.hpp).
std::string check_row_entries(NodeIndex n, NodeIndex first_row,
                              const std::vector<EdgeOffset>& row_ptr,
                              const std::vector<NodeIndex>& cols,
                              const std::vector<double>& weights);

class Network {
 public:
  Network() = default;

  /// Takes ownership of CSR arrays and checks every invariant above (size, ordering, range,
  /// symmetry, finite positive weights). Throws ParameterError describing the first
  /// violation. `weights` empty means a 0/1 network.
  static Network from_csr(NodeIndex n, std::vector<EdgeOffset> row_ptr, std::vector<NodeIndex> cols,
                          std::vector<double> weights = {});

  /// As from_csr, without the O(nnz log d) checks: for generators whose output satisfies the
  /// invariants by construction (their tests run check_csr on what they produce).
  static Network from_trusted_csr(NodeIndex n, std::vector<EdgeOffset> row_ptr,
                                  std::vector<NodeIndex> cols, std::vector<double> weights = {});

  /// Unweighted network from unordered pairs {u, v} (u != v allowed as self-loop when u == v).
  /// Each pair must appear once (in either orientation); O(N + M) counting sort. Pairs generated
  /// in increasing (min, max) order produce sorted rows without sorting.
  static Network from_undirected_edges(NodeIndex n,
                                       const std::vector<std::pair<NodeIndex, NodeIndex>>& edges);

  /// First violated invariant, or an empty string when the arrays form a valid network.
  static std::string check_csr(NodeIndex n, const std::vector<EdgeOffset>& row_ptr,
                               const std::vector<NodeIndex>& cols,
                               const std::vector<double>& weights);

  NodeIndex size() const { return m_n; }
  EdgeOffset nnz() const { return static_cast<EdgeOffset>(m_cols.size()); }
  bool weighted() const { return !m_weights.empty(); }

  const std::vector<EdgeOffset>& row_ptr() const { return m_row_ptr; }
  const std::vector<NodeIndex>& cols() const { return m_cols; }
  const std::vector<double>& weights() const { return m_weights; }
  EdgeOffset row_begin(NodeIndex i) const { return m_row_ptr[static_cast<std::size_t>(i)]; }
  EdgeOffset row_end(NodeIndex i) const { return m_row_ptr[static_cast<std::size_t>(i) + 1]; }
  NodeIndex col(EdgeOffset k) const { return m_cols[static_cast<std::size_t>(k)]; }
  double weight(EdgeOffset k) const {
    return m_weights.empty() ? 1.0 : m_weights[static_cast<std::size_t>(k)];
  }
  /// Row i's stored entries (column, weight) in ascending column order; see RowView.
  RowView row(NodeIndex i) const {
    const auto first = static_cast<std::size_t>(row_begin(i));
    const auto count = static_cast<std::size_t>(row_end(i) - row_begin(i));
    return {m_cols.data() + first, m_weights.empty() ? nullptr : m_weights.data() + first, count};
  }

  EdgeOffset self_loops() const;
  EdgeOffset edges() const { return (nnz() + self_loops()) / 2; }
  /// d_n = sum_m A_nm.
  std::vector<double> degrees() const;
  /// True if A_ij is stored (binary search in row i).
  bool has_entry(NodeIndex i, NodeIndex j) const;

 private:
  NodeIndex m_n = 0;
  std::vector<EdgeOffset> m_row_ptr{0};
  std::vector<NodeIndex> m_cols;
  std::vector<double> m_weights;
};

}  // namespace hmfnet
