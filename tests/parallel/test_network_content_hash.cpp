// The network's content hash (parallel/network_content_hash.hpp), which checkpoints carry so that a
// run resumes only on its own network: the same value on any rank count (pinned, so that the
// 2- and 3-rank runs of this file compare against the 1-rank value) and a different value for
// every change a user could make to a file: one entry moved, one weight changed, two nodes
// relabelled, another random graph of the same size and entry count.
#include <catch2/catch.hpp>
#include <utility>
#include <vector>

#include "network/complete_graph.hpp"
#include "network/erdos_renyi.hpp"
#include "network/random_regular.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/network_content_hash.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

using Edges = std::vector<std::pair<NodeIndex, NodeIndex>>;

using test::upper_edges;

bool has_edge(const Edges& e, NodeIndex a, NodeIndex b) {
  for (const auto& [i, j] : e)
    if ((i == a && j == b) || (i == b && j == a)) return true;
  return false;
}

std::uint64_t hash_of(const Network& net) { return network_content_hash(DistributedNetwork(net)); }

}  // namespace

TEST_CASE("The content hash is the same on any rank count [ER N=300, pinned]",
          "[distributed][hash]") {
  const Network net = erdos_renyi({300, 0.05, 6});
  // Pinned from the 1-rank run: the 2- and 3-rank runs of this test require the same bits.
  REQUIRE(hash_hex(hash_of(net)) == "1d63d7f38fcc9293");
}

TEST_CASE("One entry moved, one weight changed or two nodes relabelled change the hash [N=300]",
          "[distributed][hash]") {
  const Network net = erdos_renyi({300, 0.05, 6});
  const std::uint64_t base = hash_of(net);
  Edges edges = upper_edges(net);
  REQUIRE(hash_of(Network::from_undirected_edges(net.size(), edges)) == base);

  SECTION("one edge moved to a free pair: the same N and nnz") {
    Edges moved = edges;
    NodeIndex c = 0;
    while (has_edge(edges, moved[0].first, c) || c == moved[0].first) ++c;
    moved[0].second = c;
    const Network other = Network::from_undirected_edges(net.size(), moved);
    REQUIRE(other.nnz() == net.nnz());
    REQUIRE(hash_of(other) != base);
  }
  SECTION("two nodes of different neighbourhoods relabelled") {
    Edges swapped = edges;
    const auto relabel = [](NodeIndex v) { return v == 0 ? 1 : (v == 1 ? 0 : v); };
    for (auto& [i, j] : swapped) {
      i = relabel(i);
      j = relabel(j);
    }
    REQUIRE(hash_of(Network::from_undirected_edges(net.size(), swapped)) != base);
  }
  SECTION("one weight changed by one unit in the last place") {
    const Network ring = test::weighted_ring(50);
    std::vector<EdgeOffset> row_ptr;
    std::vector<NodeIndex> cols;
    std::vector<double> weights;
    for (NodeIndex i = 0; i <= ring.size(); ++i) row_ptr.push_back(ring.row_begin(i));
    for (EdgeOffset k = 0; k < ring.nnz(); ++k) {
      cols.push_back(ring.col(k));
      weights.push_back(ring.weight(k));
    }
    // Entry (0, 1) and its mirror (1, 0): the matrix stays symmetric.
    for (EdgeOffset k = 0; k < ring.nnz(); ++k) {
      const NodeIndex row = k < ring.row_end(0) ? 0 : (k < ring.row_end(1) ? 1 : 2);
      if ((row == 0 && cols[std::size_t(k)] == 1) || (row == 1 && cols[std::size_t(k)] == 0))
        weights[std::size_t(k)] = std::nextafter(weights[std::size_t(k)], 10.0);
    }
    const Network changed = Network::from_csr(ring.size(), row_ptr, cols, weights);
    REQUIRE(hash_of(changed) != hash_of(ring));
  }
}

TEST_CASE("Random regular graphs of two seeds differ in hash, not in size [N=2000, d=10]",
          "[distributed][hash]") {
  const Network a = random_regular({2000, 10, 1});
  const Network b = random_regular({2000, 10, 2});
  REQUIRE(a.nnz() == b.nnz());
  REQUIRE(hash_of(a) != hash_of(b));
}

TEST_CASE("The complete graph held implicitly hashes its size and self-loops",
          "[distributed][hash][complete]") {
  const auto h = [](NodeIndex n, bool loops) {
    return network_content_hash(DistributedNetwork(CompleteGraph::make(n, loops)));
  };
  REQUIRE(h(100, false) == h(100, false));
  REQUIRE(h(100, false) != h(100, true));
  REQUIRE(h(100, false) != h(101, false));
}
