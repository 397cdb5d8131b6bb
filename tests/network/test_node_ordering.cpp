// Node orders for the force kernel's cache (network/node_ordering.hpp): reverse Cuthill-McKee
// recovers the band of a network with locality whose labels were shuffled, by degree puts the
// hubs first; both are permutations and deterministic.
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "network/node_ordering.hpp"

namespace hmfnet {
namespace {

using Edges = std::vector<std::pair<NodeIndex, NodeIndex>>;

// A side x side grid (4 neighbours), node labels permuted by `seed` (0: row-major labels).
Edges grid(NodeIndex side, unsigned seed) {
  std::vector<NodeIndex> label(static_cast<std::size_t>(side * side));
  std::iota(label.begin(), label.end(), NodeIndex{0});
  if (seed != 0) std::shuffle(label.begin(), label.end(), std::mt19937(seed));
  Edges e;
  const auto at = [&](NodeIndex r, NodeIndex c) {
    return label[static_cast<std::size_t>(r * side + c)];
  };
  for (NodeIndex r = 0; r < side; ++r) {
    for (NodeIndex c = 0; c < side; ++c) {
      if (c + 1 < side) e.emplace_back(at(r, c), at(r, c + 1));
      if (r + 1 < side) e.emplace_back(at(r, c), at(r + 1, c));
    }
  }
  return e;
}

RowBlock whole(NodeIndex n, const Edges& edges) {
  const Network net = Network::from_undirected_edges(n, edges);
  return slice_rows(net, 0, n);
}

bool is_permutation_of_n(const std::vector<NodeIndex>& p) {
  std::vector<NodeIndex> sorted = p;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (sorted[i] != static_cast<NodeIndex>(i)) return false;
  return true;
}

std::vector<NodeIndex> identity(NodeIndex n) {
  std::vector<NodeIndex> id(static_cast<std::size_t>(n));
  std::iota(id.begin(), id.end(), NodeIndex{0});
  return id;
}

}  // namespace

TEST_CASE("reverse Cuthill-McKee recovers the band of a shuffled grid", "[node_ordering]") {
  const NodeIndex side = 40;
  const NodeIndex n = side * side;
  const RowBlock shuffled = whole(n, grid(side, 7));
  const std::vector<NodeIndex> rcm = reverse_cuthill_mckee(shuffled);
  REQUIRE(is_permutation_of_n(rcm));
  // Shuffled, the band is ~N; any order has band >= side (a grid's bandwidth is side), and a
  // breadth-first order from a corner has anti-diagonal levels of <= side nodes: band <= 2 side.
  CHECK(bandwidth(shuffled, identity(n)) > n / 2);
  const NodeIndex band = bandwidth(shuffled, rcm);
  CHECK(band >= side);
  CHECK(band <= 2 * side);
  CHECK(reverse_cuthill_mckee(shuffled) == rcm);  // deterministic
}

TEST_CASE("reverse Cuthill-McKee orders a shuffled path with band 1", "[node_ordering]") {
  const NodeIndex n = 500;
  std::vector<NodeIndex> label = identity(n);
  std::shuffle(label.begin(), label.end(), std::mt19937(3));
  Edges e;
  for (NodeIndex i = 0; i + 1 < n; ++i)
    e.emplace_back(label[static_cast<std::size_t>(i)], label[static_cast<std::size_t>(i) + 1]);
  const RowBlock path = whole(n, e);
  CHECK(bandwidth(path, reverse_cuthill_mckee(path)) == 1);
}

TEST_CASE("reverse Cuthill-McKee keeps each component contiguous", "[node_ordering]") {
  // Two grids of 100 nodes with interleaved labels and an isolated node.
  Edges e;
  for (const auto& [a, b] : grid(10, 0)) e.emplace_back(2 * a, 2 * b);
  for (const auto& [a, b] : grid(10, 0)) e.emplace_back(2 * a + 1, 2 * b + 1);
  const RowBlock two = whole(201, e);
  const std::vector<NodeIndex> rcm = reverse_cuthill_mckee(two);
  REQUIRE(is_permutation_of_n(rcm));
  std::vector<NodeIndex> even, odd;
  for (NodeIndex i = 0; i < 200; ++i)
    (i % 2 == 0 ? even : odd).push_back(rcm[static_cast<std::size_t>(i)]);
  const auto span = [](const std::vector<NodeIndex>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  CHECK(span(even) == 99);
  CHECK(span(odd) == 99);
  CHECK(bandwidth(two, rcm) <= 20);
}

TEST_CASE("reverse Cuthill-McKee needs every row", "[node_ordering]") {
  const Network net = Network::from_undirected_edges(10, Edges{{0, 1}, {2, 3}, {8, 9}});
  const RowBlock part = slice_rows(net, 0, 5);
  CHECK_THROWS_AS(reverse_cuthill_mckee(part), ParameterError);
}

TEST_CASE("by degree: hubs first, ties in the old order", "[node_ordering]") {
  const std::vector<double> entries{3, 7, 1, 7, 0, 3};
  const std::vector<NodeIndex> order = degree_order(entries);
  REQUIRE(is_permutation_of_n(order));
  CHECK(order == std::vector<NodeIndex>{2, 0, 4, 1, 5, 3});
  const std::vector<NodeIndex> original = inverse_permutation(order);
  for (std::size_t k = 1; k < original.size(); ++k) {
    const double before = entries[static_cast<std::size_t>(original[k - 1])];
    const double here = entries[static_cast<std::size_t>(original[k])];
    CHECK(before >= here);
    if (before == here) CHECK(original[k - 1] < original[k]);
  }
}

TEST_CASE("order names", "[node_ordering]") {
  CHECK(parse_node_order("rcm", "--order") == NodeOrder::rcm);
  CHECK(std::string(name_of(NodeOrder::degree)) == "degree");
  CHECK_THROWS_WITH(parse_node_order("band", "--order"), Catch::Contains("--order"));
}

}  // namespace hmfnet
