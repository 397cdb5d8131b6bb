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
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hmfnet {

using NodeIndex = std::int32_t;
using EdgeOffset = std::int64_t;

class Network {
 public:
  Network() = default;

  /// Takes ownership of CSR arrays and checks every invariant above (size, ordering, range,
  /// symmetry, finite positive weights). Throws std::invalid_argument describing the first
  /// violation. `weights` empty means a 0/1 network.
  static Network from_csr(NodeIndex n, std::vector<EdgeOffset> row_ptr,
                          std::vector<NodeIndex> cols, std::vector<double> weights = {});

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
