#include "network/structure.hpp"

#include <algorithm>

#include "core/index_cast.hpp"

namespace hmfnet {

Components connected_components(const Network& network) {
  Components c;
  c.label.assign(idx(network.size()), -1);
  std::vector<NodeIndex> queue;
  queue.reserve(idx(network.size()));
  for (NodeIndex start = 0; start < network.size(); ++start) {
    if (c.label[idx(start)] >= 0) continue;
    queue.clear();
    queue.push_back(start);
    c.label[idx(start)] = c.count;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const NodeIndex i = queue[head];
      for (const RowEntry entry : network.row(i)) {
        const NodeIndex j = entry.col;
        if (c.label[idx(j)] < 0) {
          c.label[idx(j)] = c.count;
          queue.push_back(j);
        }
      }
    }
    c.largest = std::max(c.largest, static_cast<NodeIndex>(queue.size()));
    ++c.count;
  }
  return c;
}

bool is_bipartite(const Network& network) {
  std::vector<signed char> colour(idx(network.size()), -1);
  std::vector<NodeIndex> queue;
  for (NodeIndex start = 0; start < network.size(); ++start) {
    if (colour[idx(start)] >= 0) continue;
    colour[idx(start)] = 0;
    queue.assign(1, start);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const NodeIndex i = queue[head];
      for (const RowEntry entry : network.row(i)) {
        const NodeIndex j = entry.col;
        if (colour[idx(j)] < 0) {
          colour[idx(j)] = static_cast<signed char>(1 - colour[idx(i)]);
          queue.push_back(j);
        } else if (colour[idx(j)] == colour[idx(i)]) {
          return false;  // odd cycle, or a self-loop (j == i)
        }
      }
    }
  }
  return network.nnz() > 0;
}

}  // namespace hmfnet
