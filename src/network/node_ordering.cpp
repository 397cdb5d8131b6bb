#include "network/node_ordering.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "core/error.hpp"

namespace hmfnet {

namespace {

using Index = std::size_t;

EdgeOffset row_length(const RowBlock& g, NodeIndex v) {
  return g.row_ptr[static_cast<Index>(v) + 1] - g.row_ptr[static_cast<Index>(v)];
}

// Cuthill-McKee's tie rule: fewer stored entries first, then the lower old index.
bool fewer_entries(const RowBlock& g, NodeIndex a, NodeIndex b) {
  const EdgeOffset la = row_length(g, a);
  const EdgeOffset lb = row_length(g, b);
  return la != lb ? la < lb : a < b;
}

struct Search {
  Index last_level_start = 0;  ///< where the farthest level starts in `order`
  Index levels = 0;            ///< eccentricity of the start + 1
};

// Breadth-first search from `start` over the unvisited part of its component, appending the
// visited nodes to `order` level by level, each node's new neighbours by fewer_entries.
Search breadth_first(const RowBlock& g, NodeIndex start, std::vector<char>& seen,
                     std::vector<NodeIndex>& order) {
  Index head = order.size();
  order.push_back(start);
  seen[static_cast<Index>(start)] = 1;
  Search s{head, 1};
  Index level_end = order.size();
  std::vector<NodeIndex> next;
  while (head < order.size()) {
    if (head == level_end) {  // the level above is done: the next one starts here
      s.last_level_start = level_end;
      level_end = order.size();
      ++s.levels;
    }
    const NodeIndex v = order[head++];
    next.clear();
    for (EdgeOffset k = g.row_ptr[static_cast<Index>(v)]; k < g.row_ptr[static_cast<Index>(v) + 1];
         ++k) {
      const NodeIndex w = g.cols[static_cast<Index>(k)];
      if (!seen[static_cast<Index>(w)]) {
        seen[static_cast<Index>(w)] = 1;
        next.push_back(w);
      }
    }
    std::sort(next.begin(), next.end(),
              [&g](NodeIndex a, NodeIndex b) { return fewer_entries(g, a, b); });
    order.insert(order.end(), next.begin(), next.end());
  }
  return s;
}

// Gibbs-Poole-Stockmeyer's start: from the least-entries node of the farthest level, search
// again; move there while that reaches farther.
NodeIndex pseudo_peripheral(const RowBlock& g, NodeIndex start, std::vector<char>& seen) {
  std::vector<NodeIndex> order;
  const auto search = [&](NodeIndex s) {
    order.clear();
    const Search result = breadth_first(g, s, seen, order);
    for (const NodeIndex v : order) seen[static_cast<Index>(v)] = 0;
    return result;
  };
  Search reach = search(start);
  for (int round = 0; round < 16; ++round) {  // a few rounds in practice; the cap bounds the cost
    const NodeIndex far = *std::min_element(
        order.begin() + static_cast<std::ptrdiff_t>(reach.last_level_start), order.end(),
        [&g](NodeIndex a, NodeIndex b) { return fewer_entries(g, a, b); });
    const Search from_far = search(far);
    if (from_far.levels <= reach.levels) break;
    start = far;
    reach = from_far;
  }
  return start;
}

}  // namespace

NodeOrder parse_node_order(const std::string& name, const std::string& option) {
  if (name == "original") return NodeOrder::original;
  if (name == "rcm") return NodeOrder::rcm;
  if (name == "degree") return NodeOrder::degree;
  throw ParameterError(option, name, "original, rcm or degree");
}

const char* name_of(NodeOrder order) {
  switch (order) {
    case NodeOrder::rcm:
      return "rcm";
    case NodeOrder::degree:
      return "degree";
    case NodeOrder::original:
      break;
  }
  return "original";
}

std::vector<NodeIndex> reverse_cuthill_mckee(const RowBlock& block) {
  if (block.first_row != 0 || block.rows() != block.n) {
    throw ParameterError(
        "rcm",
        "a block of " + std::to_string(block.rows()) + " of " + std::to_string(block.n) + " rows",
        "every row on one rank (the search is sequential)");
  }
  const auto n = static_cast<Index>(block.n);
  std::vector<char> seen(n, 0);
  std::vector<NodeIndex> order;
  order.reserve(n);
  for (Index s = 0; s < n; ++s) {
    if (seen[s]) continue;
    const NodeIndex start = pseudo_peripheral(block, static_cast<NodeIndex>(s), seen);
    breadth_first(block, start, seen, order);
  }
  std::reverse(order.begin(), order.end());  // Cuthill-McKee reversed (George)
  return inverse_permutation(order);
}

std::vector<NodeIndex> degree_order(const std::vector<double>& entries) {
  std::vector<NodeIndex> order(entries.size());
  std::iota(order.begin(), order.end(), NodeIndex{0});
  std::stable_sort(order.begin(), order.end(), [&entries](NodeIndex a, NodeIndex b) {
    return entries[static_cast<Index>(a)] > entries[static_cast<Index>(b)];
  });
  return inverse_permutation(order);  // order[k] is the node placed k-th
}

std::vector<NodeIndex> inverse_permutation(const std::vector<NodeIndex>& new_index) {
  std::vector<NodeIndex> original(new_index.size());
  for (Index i = 0; i < new_index.size(); ++i)
    original[static_cast<Index>(new_index[i])] = static_cast<NodeIndex>(i);
  return original;
}

NodeIndex bandwidth(const RowBlock& block, const std::vector<NodeIndex>& new_index) {
  NodeIndex band = 0;
  for (NodeIndex r = 0; r < block.rows(); ++r) {
    const NodeIndex i = new_index[static_cast<Index>(block.first_row) + static_cast<Index>(r)];
    for (EdgeOffset k = block.row_ptr[static_cast<Index>(r)];
         k < block.row_ptr[static_cast<Index>(r) + 1]; ++k) {
      band = std::max(
          band, std::abs(i - new_index[static_cast<Index>(block.cols[static_cast<Index>(k)])]));
    }
  }
  return band;
}

}  // namespace hmfnet
