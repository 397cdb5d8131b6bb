#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/network_summary.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {
NetworkSummary summary_of(const Network& net, double sigma0 = 0.0) {
  const DistributedNetwork d(net);
  return summarise(net, perron_eigenpair(d), sigma0);
}
}  // namespace

TEST_CASE("Summary JSON has every key the CLI promises", "[summary]") {
  const auto j = nlohmann::json::parse(to_json(summary_of(erdos_renyi({500, 0.05, 1}), 0.35)));
  for (const char* key : {"n", "edges", "nnz", "self_loops", "mean_degree", "lambda",
                          "lambda_residual", "rho", "G", "components", "bipartite", "Kc"}) {
    INFO(key);
    REQUIRE(j.contains(key));
  }
  REQUIRE(j["Kc"].get<double>() == Approx(2 * 0.35 * 0.35 * 500 / j["lambda"].get<double>()));
}

TEST_CASE("Summary reports a disconnected and a bipartite network as such", "[summary]") {
  const NetworkSummary two = summary_of(test::two_cliques(4, 7));
  REQUIRE(two.components == 2);
  REQUIRE(two.warnings.size() >= 1);
  const NetworkSummary star = summary_of(test::star(50));
  REQUIRE(star.bipartite);
  REQUIRE_FALSE(star.warnings.empty());
  const NetworkSummary ring = summary_of(test::circulant(101, 2));
  REQUIRE(ring.warnings.empty());
  REQUIRE(ring.G == Approx(std::sqrt(0.4)).epsilon(1e-8));  // regular: G = sqrt(2/5)
}
