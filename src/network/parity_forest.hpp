#pragma once
// Union-find with parity (a disjoint-set forest where each node also knows whether its colour
// differs from its root's): connected components and 2-colourability in one pass over the
// entries, O(nnz alpha(N)), and forests built from different entry sets (the row blocks of
// different ranks) merge into the forest of their union. Path halving, union by size.
#include <cstdint>
#include <vector>

#include "network/network.hpp"

namespace hmfnet {

class ParityForest {
 public:
  explicit ParityForest(NodeIndex n);

  /// Records an entry (u, v): u and v are connected and, for 2-colouring, of different colours.
  /// A self-loop (u == v) or an odd cycle makes the graph not bipartite.
  void link(NodeIndex u, NodeIndex v) { unite(u, v, 1); }

  /// Every node's root and colour relative to it, encoded 2 root + parity (what merge reads).
  std::vector<std::int64_t> labels();
  /// Adds what another forest over the same nodes knows, given as its labels().
  void merge(const std::vector<std::int64_t>& other_labels, bool other_bipartite);

  NodeIndex components() const { return m_components; }
  NodeIndex largest() const;
  bool bipartite() const { return m_bipartite; }

 private:
  struct Found {
    NodeIndex root;
    std::uint8_t parity;  ///< colour of the node xor colour of its root
  };
  Found find(NodeIndex v);
  /// u and v joined so that colour(u) xor colour(v) = parity.
  void unite(NodeIndex u, NodeIndex v, std::uint8_t parity);

  std::vector<NodeIndex> m_parent;
  std::vector<std::uint8_t> m_parity;  ///< relative to the parent
  std::vector<NodeIndex> m_size;       ///< meaningful at roots
  NodeIndex m_components;
  bool m_bipartite = true;
};

}  // namespace hmfnet
