#include <catch2/catch.hpp>

#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

namespace {
// eq:rhodef written as the paper does: averages over edges, each undirected edge in both
// directions (ordered pairs with A_nm != 0), for a 0/1 network.
double rho_by_edge_averages(const Network& net) {
  const auto d = net.degrees();
  double dd = 0.0, dn = 0.0, dm = 0.0, count = 0.0;
  for (NodeIndex n = 0; n < net.size(); ++n) {
    for (EdgeOffset k = net.row_begin(n); k < net.row_end(n); ++k) {
      const NodeIndex m = net.col(k);
      dd += d[std::size_t(n)] * d[std::size_t(m)];
      dn += d[std::size_t(n)];
      dm += d[std::size_t(m)];
      count += 1.0;
    }
  }
  return (dd / count) / ((dn / count) * (dm / count));
}
}  // namespace

TEST_CASE("rho equals the edge-average definition of eq:rhodef", "[degree_statistics]") {
  for (const Network& net :
       {test::star(12), erdos_renyi({800, 0.02, 3}), test::two_cliques(5, 9)}) {
    REQUIRE_THAT(degree_correlation(net),
                 Catch::Matchers::WithinRel(rho_by_edge_averages(net), test::k_sum_rel));
  }
}

TEST_CASE("rho closed forms: 1 on a regular graph / 4(N-1)/N^2 on a star", "[degree_statistics]") {
  REQUIRE_THAT(degree_correlation(test::circulant(50, 4)), Catch::Matchers::WithinRel(1.0, 1e-14));
  const double n = 12;
  REQUIRE_THAT(degree_correlation(test::star(12)),
               Catch::Matchers::WithinRel(4 * (n - 1) / (n * n), 1e-14));
}

TEST_CASE("Mean degree is 2 edges / N for a 0/1 network without self-loops",
          "[degree_statistics]") {
  const Network net = erdos_renyi({1000, 0.05, 2});
  REQUIRE_THAT(mean_degree(net),
               Catch::Matchers::WithinRel(2.0 * static_cast<double>(net.edges()) / 1000.0, 1e-14));
}
