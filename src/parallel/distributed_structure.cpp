#include "parallel/distributed_structure.hpp"

#include <algorithm>

#include "network/parity_forest.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

ParityForest local_forest(const DistributedNetwork& network) {
  ParityForest forest(network.global_size());
  const auto& a = network.local_adjacency();
  const std::vector<NodeIndex> globals = network.column_globals();
  for (std::size_t r = 0; r + 1 < a.row_ptr.size(); ++r) {
    const NodeIndex i = network.first_row() + static_cast<NodeIndex>(r);
    for (auto k = static_cast<std::size_t>(a.row_ptr[r]);
         k < static_cast<std::size_t>(a.row_ptr[r + 1]); ++k) {
      const NodeIndex j = globals[static_cast<std::size_t>(a.cols[k])];
      if (j >= i) forest.link(i, j);  // each pair once: (j, i) is the same link
    }
  }
  return forest;
}

// Rank 0's forest of the whole network: the right partner at each level of a binary tree hands
// its forest to the left one and is done (the other ranks return partial forests).
ParityForest merged_forest(const DistributedNetwork& network) {
  ParityForest forest = local_forest(network);
  const int rank = ParallelSession::rank(), ranks = ParallelSession::ranks();
  for (int step = 1; step < ranks; step *= 2) {
    if (rank % (2 * step) == step) {
      std::vector<std::int64_t> message = forest.labels();
      message.push_back(forest.bipartite() ? 1 : 0);
      ParallelSession::send(message, rank - step);
      break;
    }
    if (rank % (2 * step) == 0 && rank + step < ranks) {
      std::vector<std::int64_t> message = ParallelSession::receive(rank + step);
      const bool bipartite = message.back() == 1;
      message.pop_back();
      forest.merge(message, bipartite);
    }
  }
  return forest;
}

}  // namespace

NetworkStructure distributed_structure(const DistributedNetwork& network) {
  if (!network.stores_rows()) {  // K_N held implicitly: one component; an odd cycle once n > 2
    const NodeIndex n = network.global_size();
    return {1, n, n == 2 && network.global_self_loops() == 0};
  }
  ParityForest forest = merged_forest(network);
  std::vector<std::int64_t> facts{forest.components(), forest.largest(),
                                  forest.bipartite() ? 1 : 0};
  ParallelSession::broadcast(facts, 0);
  return {static_cast<NodeIndex>(facts[0]), static_cast<NodeIndex>(facts[1]), facts[2] == 1};
}

Components distributed_components(const DistributedNetwork& network) {
  const NodeIndex n = network.global_size();
  Components c;
  if (!network.stores_rows()) {
    c.count = 1;
    c.label.assign(static_cast<std::size_t>(n), 0);
    c.largest = n;
    return c;
  }
  ParityForest forest = merged_forest(network);
  std::vector<std::int64_t> labels;
  if (ParallelSession::rank() == 0) {
    // Roots numbered by their first node, as connected_components numbers its components.
    const std::vector<std::int64_t> roots = forest.labels();  // 2 root + parity
    std::vector<std::int64_t> number(static_cast<std::size_t>(n), -1);
    labels.resize(static_cast<std::size_t>(n));
    std::int64_t next = 0;
    for (std::size_t v = 0; v < labels.size(); ++v) {
      auto& k = number[static_cast<std::size_t>(roots[v] / 2)];
      if (k < 0) k = next++;
      labels[v] = k;
    }
  }
  ParallelSession::broadcast(labels, 0);
  c.label.assign(labels.begin(), labels.end());
  std::int64_t count = 0;
  for (const auto l : labels) count = std::max(count, l + 1);
  c.count = static_cast<NodeIndex>(count);
  std::vector<NodeIndex> sizes(static_cast<std::size_t>(count), 0);
  for (const auto l : labels) ++sizes[static_cast<std::size_t>(l)];
  for (const NodeIndex size : sizes) c.largest = std::max(c.largest, size);
  return c;
}

}  // namespace hmfnet
