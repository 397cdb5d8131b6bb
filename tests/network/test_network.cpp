#include <catch2/catch.hpp>
#include <utility>
#include <vector>

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

TEST_CASE("Network::row visits (column, weight) in storage order, weight 1 in a 0/1 network",
          "[network]") {
  // Path 0-1-2 with weights 2 and 3 and a self-loop of weight 5 on node 2.
  const Network weighted =
      Network::from_csr(3, {0, 1, 3, 5}, {1, 0, 2, 1, 2}, {2.0, 2.0, 3.0, 3.0, 5.0});
  std::vector<std::pair<NodeIndex, double>> seen;
  for (const auto [j, w] : weighted.row(1)) seen.emplace_back(j, w);
  REQUIRE(seen == std::vector<std::pair<NodeIndex, double>>{{0, 2.0}, {2, 3.0}});
  seen.clear();
  for (const auto [j, w] : weighted.row(2)) seen.emplace_back(j, w);
  REQUIRE(seen == std::vector<std::pair<NodeIndex, double>>{{1, 3.0}, {2, 5.0}});
  REQUIRE(weighted.row(0).size() == 1);

  const Network pattern = Network::from_undirected_edges(4, {{0, 1}, {1, 2}, {2, 2}});
  seen.clear();
  for (const auto [j, w] : pattern.row(2)) seen.emplace_back(j, w);
  REQUIRE(seen == std::vector<std::pair<NodeIndex, double>>{{1, 1.0}, {2, 1.0}});
  REQUIRE(pattern.row(3).empty());
  REQUIRE(pattern.row(3).begin() == pattern.row(3).end());
}
