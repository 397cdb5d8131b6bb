#pragma once
// Networks with closed-form spectra for tests:
//   star S_N            lambda = sqrt(N-1), bipartite
//   complete K_N        lambda = N-1 (with self-loops: N)
//   complete bipartite  K_{a,b}: lambda = sqrt(ab), bipartite
//   ring / circulant    d-regular: lambda = d
//   two disjoint cliques disconnected
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "network/network.hpp"

namespace hmfnet::test {

inline Network star(NodeIndex n) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 1; i < n; ++i) e.emplace_back(0, i);
  return Network::from_undirected_edges(n, e);
}

inline Network complete(NodeIndex n, bool self_loops = false) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < n; ++i)
    for (NodeIndex j = self_loops ? i : i + 1; j < n; ++j) e.emplace_back(i, j);
  return Network::from_undirected_edges(n, e);
}

inline Network complete_bipartite(NodeIndex a, NodeIndex b) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < a; ++i)
    for (NodeIndex j = 0; j < b; ++j) e.emplace_back(i, a + j);
  return Network::from_undirected_edges(a + b, e);
}

/// Circulant graph: node i linked to i +- 1, ..., i +- half_degree (mod n): 2*half_degree-regular.
inline Network circulant(NodeIndex n, NodeIndex half_degree) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < n; ++i)
    for (NodeIndex s = 1; s <= half_degree; ++s) e.emplace_back(i, (i + s) % n);
  return Network::from_undirected_edges(n, e);
}

/// A ring (i linked to i +- 1 mod n, n >= 3) whose weights differ from edge to edge (a
/// symmetric function of the two ends, in [0.5, 1.5]).
inline Network weighted_ring(NodeIndex n) {
  std::vector<EdgeOffset> row_ptr{0};
  std::vector<NodeIndex> cols;
  std::vector<double> weights;
  for (NodeIndex i = 0; i < n; ++i) {
    for (const NodeIndex j : {(i + n - 1) % n, (i + 1) % n}) {
      cols.push_back(j);
      weights.push_back(1.0 + 0.5 * std::sin(0.1 * (std::min(i, j) + 3.0 * std::max(i, j))));
    }
    if (cols[cols.size() - 2] > cols.back()) {
      std::swap(cols[cols.size() - 2], cols.back());
      std::swap(weights[weights.size() - 2], weights.back());
    }
    row_ptr.push_back(static_cast<EdgeOffset>(cols.size()));
  }
  return Network::from_csr(n, std::move(row_ptr), std::move(cols), std::move(weights));
}

/// Two cliques K_a and K_b with no edge between them.
inline Network two_cliques(NodeIndex a, NodeIndex b) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < a; ++i)
    for (NodeIndex j = i + 1; j < a; ++j) e.emplace_back(i, j);
  for (NodeIndex i = 0; i < b; ++i)
    for (NodeIndex j = i + 1; j < b; ++j) e.emplace_back(a + i, a + j);
  return Network::from_undirected_edges(a + b, e);
}

/// The links i < j of a network, in row order: the input of from_undirected_edges.
inline std::vector<std::pair<NodeIndex, NodeIndex>> upper_edges(const Network& net) {
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 0; i < net.size(); ++i)
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k)
      if (net.col(k) > i) e.emplace_back(i, net.col(k));
  return e;
}

/// The same links with symmetric weights in [1, 2] (a function of the unordered pair), so that
/// a weighted kernel path (and its float32 weights) is exercised on a given pattern.
inline Network pair_weighted(const Network& net) {
  std::vector<EdgeOffset> row_ptr{0};
  std::vector<NodeIndex> cols;
  std::vector<double> w;
  for (NodeIndex i = 0; i < net.size(); ++i) {
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      const NodeIndex j = net.col(k), a = std::min(i, j), b = std::max(i, j);
      cols.push_back(j);
      w.push_back(1.0 + static_cast<double>((7 * a + 13 * b) % 11) / 10.0);
    }
    row_ptr.push_back(static_cast<EdgeOffset>(cols.size()));
  }
  return Network::from_csr(net.size(), std::move(row_ptr), std::move(cols), std::move(w));
}

}  // namespace hmfnet::test
