#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "network/chung_lu.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "network/rewiring.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {
Network scale_free() {
  return chung_lu(power_law_targets(3000, {2.5, 8.0}, 3), LinkProbability::capped, 3);
}
}  // namespace

TEST_CASE("Rewiring raises rho to the target and keeps every degree [SF N=3000]", "[rewiring]") {
  const Network net = scale_free();
  const double rho0 = degree_correlation(net);
  const RewiringResult r = rewire_to_correlation(net, {rho0 + 0.15, 7, 0});
  INFO("rho " << rho0 << " -> " << r.final_rho << " in " << r.swaps << " swaps");
  REQUIRE(r.initial_rho == Approx(rho0));
  REQUIRE(r.final_rho >= rho0 + 0.15);
  REQUIRE(r.final_rho == Approx(degree_correlation(r.network)));
  REQUIRE(test::bit_difference(r.network.degrees(), net.degrees()) == "");
  REQUIRE(r.network.edges() == net.edges());
  REQUIRE(r.network.self_loops() == 0);
  REQUIRE(Network::check_csr(r.network.size(), r.network.row_ptr(), r.network.cols(), {}).empty());
  REQUIRE(r.network.cols() != net.cols());
}

TEST_CASE("Rewiring lowers rho when the target is below it [SF N=3000]", "[rewiring]") {
  const Network net = scale_free();
  const double rho0 = degree_correlation(net);
  const RewiringResult r = rewire_to_correlation(net, {rho0 - 0.1, 7, 0});
  REQUIRE(r.final_rho <= rho0 - 0.1);
  REQUIRE(test::bit_difference(r.network.degrees(), net.degrees()) == "");
}

TEST_CASE("Rewiring the same network with the same seed gives the same network", "[rewiring]") {
  const Network net = scale_free();
  const double target = degree_correlation(net) + 0.1;
  REQUIRE(rewire_to_correlation(net, {target, 9, 0}).network.cols() ==
          rewire_to_correlation(net, {target, 9, 0}).network.cols());
}

TEST_CASE("Rewiring reports an unreachable target instead of returning short of it", "[rewiring]") {
  const Network net = scale_free();
  REQUIRE_THROWS_AS(rewire_to_correlation(net, {50.0, 1, 20000}), ConvergenceError);
}

TEST_CASE("Rewiring refuses weighted networks and self-loops", "[rewiring]") {
  const Network weighted = Network::from_csr(3, {0, 1, 3, 4}, {1, 0, 2, 1}, {2., 2., 2., 2.});
  REQUIRE_THROWS_AS(rewire_to_correlation(weighted, {1.0, 1, 0}), ParameterError);
  const Network loop = Network::from_undirected_edges(3, {{0, 1}, {1, 2}, {2, 2}});
  REQUIRE_THROWS_AS(rewire_to_correlation(loop, {1.0, 1, 0}), ParameterError);
}

TEST_CASE("Rewiring refuses a network past its stated size, naming the limit", "[rewiring]") {
  // K_4473 held as rows: 4473 * 4472 = 20,003,256 stored entries, just past the limit.
  const Network big = erdos_renyi({4473, 1.0, 1});
  REQUIRE(big.nnz() == k_max_rewiring_entries + 3256);
  CHECK_THROWS_WITH(rewire_to_correlation(big, {1.5, 1, 0}),
                    Catch::Matchers::Contains("at most 20000000") &&
                        Catch::Matchers::Contains("not distributed"));
}
