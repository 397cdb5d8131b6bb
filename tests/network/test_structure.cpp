#include <catch2/catch.hpp>

#include "network/structure.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

TEST_CASE("Connected components of two cliques and an isolated node", "[structure]") {
  const Network two = test::two_cliques(4, 6);
  const Components c = connected_components(two);
  REQUIRE(c.count == 2);
  REQUIRE(c.largest == 6);
  REQUIRE(c.label[0] == c.label[3]);
  REQUIRE(c.label[0] != c.label[4]);
  const Network with_isolated = Network::from_undirected_edges(4, {{0, 1}, {1, 2}});
  REQUIRE(connected_components(with_isolated).count == 2);
  REQUIRE(connected_components(test::star(30)).count == 1);
}

TEST_CASE("Bipartite detection: stars and K_ab yes / odd cycles and self-loops no", "[structure]") {
  REQUIRE(is_bipartite(test::star(10)));
  REQUIRE(is_bipartite(test::complete_bipartite(3, 5)));
  REQUIRE(is_bipartite(test::circulant(10, 1)));        // even ring
  REQUIRE_FALSE(is_bipartite(test::circulant(11, 1)));  // odd ring
  REQUIRE_FALSE(is_bipartite(test::complete(3)));
  REQUIRE_FALSE(is_bipartite(Network::from_undirected_edges(2, {{0, 1}, {1, 1}})));
}
