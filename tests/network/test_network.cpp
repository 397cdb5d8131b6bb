#include <catch2/catch.hpp>

#include "network/network.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

TEST_CASE("Network counts edges / self-loops and nnz by the documented convention", "[network]") {
  // Triangle 0-1-2 plus a self-loop on 0: edges 4, self-loops 1, nnz 2*3 + 1.
  const Network net = Network::from_undirected_edges(3, {{0, 1}, {1, 2}, {2, 0}, {0, 0}});
  REQUIRE(net.size() == 3);
  REQUIRE(net.nnz() == 7);
  REQUIRE(net.self_loops() == 1);
  REQUIRE(net.edges() == 4);
  const auto d = net.degrees();
  REQUIRE(d == std::vector<double>{3.0, 2.0, 2.0});  // a self-loop counts once in d_n
  REQUIRE(Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights()).empty());
}

TEST_CASE("Network degrees are weighted row sums", "[network]") {
  const Network net = Network::from_csr(3, {0, 1, 3, 4}, {1, 0, 2, 1}, {0.5, 0.5, 2.0, 2.0});
  REQUIRE(net.weighted());
  REQUIRE(net.degrees() == std::vector<double>{0.5, 2.5, 2.0});
}

TEST_CASE("Network::from_csr rejects each broken invariant with its description", "[network]") {
  using V = std::vector<EdgeOffset>;
  using C = std::vector<NodeIndex>;
  SECTION("asymmetric") {
    REQUIRE_THROWS_WITH(Network::from_csr(2, V{0, 1, 1}, C{1}), Catch::Contains("no transpose"));
  }
  SECTION("unsorted row") {
    REQUIRE_THROWS_WITH(Network::from_csr(3, V{0, 2, 3, 4}, C{2, 1, 0, 0}),
                        Catch::Contains("unsorted"));
  }
  SECTION("column out of range") {
    REQUIRE_THROWS_WITH(Network::from_csr(2, V{0, 1, 2}, C{5, 0}), Catch::Contains("out of range"));
  }
  SECTION("row_ptr length") {
    REQUIRE_THROWS_WITH(Network::from_csr(3, V{0, 1, 2}, C{1, 0}), Catch::Contains("row_ptr"));
  }
  SECTION("weights of unequal transpose") {
    REQUIRE_THROWS_WITH(Network::from_csr(2, V{0, 1, 2}, C{1, 0}, {1.0, 2.0}),
                        Catch::Contains("different weights"));
  }
  SECTION("non-positive weight") {
    REQUIRE_THROWS_WITH(Network::from_csr(2, V{0, 1, 2}, C{1, 0}, {-1.0, -1.0}),
                        Catch::Contains("weight"));
  }
}

TEST_CASE("Network::from_undirected_edges rejects a repeated pair in either orientation",
          "[network]") {
  REQUIRE_THROWS(Network::from_undirected_edges(3, {{0, 1}, {1, 0}}));
  REQUIRE_THROWS(Network::from_undirected_edges(3, {{0, 5}}));
}

TEST_CASE("Small closed-form networks have the expected edge counts", "[network]") {
  REQUIRE(test::star(10).edges() == 9);
  REQUIRE(test::complete(6).edges() == 15);
  REQUIRE(test::complete(6, true).self_loops() == 6);
  REQUIRE(test::complete_bipartite(3, 4).edges() == 12);
  REQUIRE(test::circulant(20, 3).degrees() == std::vector<double>(20, 6.0));
}
