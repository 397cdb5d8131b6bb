// ParityForest: components and 2-colourability equal the breadth-first answers of
// network/structure.hpp, and forests of split entry sets merge into the forest of the union.
#include <catch2/catch.hpp>

#include "network/erdos_renyi.hpp"
#include "network/parity_forest.hpp"
#include "network/structure.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

// The forest of the rows [first, last) of a network.
ParityForest forest_of_rows(const Network& net, NodeIndex first, NodeIndex last) {
  ParityForest forest(net.size());
  for (NodeIndex i = first; i < last; ++i)
    for (const auto [j, w] : net.row(i)) forest.link(i, j);
  return forest;
}

}  // namespace

TEST_CASE(
    "Parity forest equals breadth-first components and bipartiteness, whole or split in "
    "three and merged [small networks, sparse ER]",
    "[parity_forest]") {
  const std::vector<std::pair<const char*, Network>> cases{
      {"star", test::star(50)},
      {"K_{3,4}", test::complete_bipartite(3, 4)},
      {"K_7", test::complete(7)},
      {"K_7 with loops", test::complete(7, true)},
      {"ring of 9 (odd)", test::circulant(9, 1)},
      {"ring of 10 (even)", test::circulant(10, 1)},
      {"two cliques", test::two_cliques(5, 8)},
      {"sparse ER (many components)", erdos_renyi({2000, 0.0007, 3})},
      {"path", Network::from_undirected_edges(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}})},
      {"self-loop only", Network::from_undirected_edges(4, {{0, 1}, {2, 2}})}};
  for (const auto& [name, net] : cases) {
    const Components expected = connected_components(net);
    const bool expected_bipartite = is_bipartite(net);
    INFO(name << ": " << expected.count << " components, largest " << expected.largest
              << ", bipartite " << expected_bipartite);
    ParityForest whole = forest_of_rows(net, 0, net.size());
    CHECK(whole.components() == expected.count);
    CHECK(whole.largest() == expected.largest);
    CHECK(whole.bipartite() == expected_bipartite);
    const NodeIndex a = net.size() / 3, b = 2 * net.size() / 3;
    ParityForest first = forest_of_rows(net, 0, a);
    ParityForest second = forest_of_rows(net, a, b);
    const ParityForest third = forest_of_rows(net, b, net.size());
    ParityForest third_copy = third;
    second.merge(third_copy.labels(), third_copy.bipartite());
    first.merge(second.labels(), second.bipartite());
    CHECK(first.components() == expected.count);
    CHECK(first.largest() == expected.largest);
    CHECK(first.bipartite() == expected_bipartite);
  }
}
