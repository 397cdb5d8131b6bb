#include "network/parity_forest.hpp"

#include <algorithm>
#include <numeric>

#include "core/index_cast.hpp"

namespace hmfnet {

ParityForest::ParityForest(NodeIndex n)
    : m_parent(idx(n)), m_parity(idx(n), 0), m_size(idx(n), 1), m_components(n) {
  std::iota(m_parent.begin(), m_parent.end(), 0);
}

ParityForest::Found ParityForest::find(NodeIndex v) {
  // Two passes: the root and v's parity to it, then every node on the path hung on the root
  // with its own parity (full compression keeps later finds O(1)).
  NodeIndex root = v;
  std::uint8_t parity = 0;
  while (m_parent[idx(root)] != root) {
    parity ^= m_parity[idx(root)];
    root = m_parent[idx(root)];
  }
  std::uint8_t remaining = parity;  // parity of the current node to the root
  while (m_parent[idx(v)] != root && v != root) {
    const NodeIndex next = m_parent[idx(v)];
    const std::uint8_t step = m_parity[idx(v)];
    m_parent[idx(v)] = root;
    m_parity[idx(v)] = remaining;
    remaining ^= step;
    v = next;
  }
  return {root, parity};
}

void ParityForest::unite(NodeIndex u, NodeIndex v, std::uint8_t parity) {
  const Found a = find(u), b = find(v);
  if (a.root == b.root) {
    if ((a.parity ^ b.parity) != parity) m_bipartite = false;
    return;
  }
  // colour(u) = colour(ra) ^ pa, colour(v) = colour(rb) ^ pb, colour(u) ^ colour(v) = parity:
  // so colour(ra) ^ colour(rb) = parity ^ pa ^ pb.
  const std::uint8_t roots = parity ^ a.parity ^ b.parity;
  NodeIndex big = a.root, small = b.root;
  if (m_size[idx(big)] < m_size[idx(small)]) std::swap(big, small);
  m_parent[idx(small)] = big;
  m_parity[idx(small)] = roots;
  m_size[idx(big)] += m_size[idx(small)];
  --m_components;
}

std::vector<std::int64_t> ParityForest::labels() {
  std::vector<std::int64_t> out(m_parent.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    const Found f = find(static_cast<NodeIndex>(v));
    out[v] = 2 * static_cast<std::int64_t>(f.root) + f.parity;
  }
  return out;
}

void ParityForest::merge(const std::vector<std::int64_t>& other_labels, bool other_bipartite) {
  m_bipartite = m_bipartite && other_bipartite;
  for (std::size_t v = 0; v < other_labels.size(); ++v) {
    const auto root = static_cast<NodeIndex>(other_labels[v] / 2);
    const auto parity = static_cast<std::uint8_t>(other_labels[v] % 2);
    if (root != static_cast<NodeIndex>(v)) unite(static_cast<NodeIndex>(v), root, parity);
  }
}

NodeIndex ParityForest::largest() const {
  NodeIndex best = 0;
  for (std::size_t v = 0; v < m_parent.size(); ++v) {
    if (m_parent[v] == static_cast<NodeIndex>(v)) best = std::max(best, m_size[v]);
  }
  return best;
}

}  // namespace hmfnet
