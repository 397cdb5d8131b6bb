// The theory's products on rows distributed over ranks (parallel/distributed_product.hpp) and
// the components they need (distributed_components): equal to the serial ones bit for bit on
// every rank count (label mpi: 1-3 ranks), and so is what the solvers compute from them. Bit for
// bit because each row is summed in the same ascending column order and the gather adds only
// zeros from the ranks that do not own a row.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/random.hpp"
#include "network/adjacency_product.hpp"
#include "network/erdos_renyi.hpp"
#include "network/structure.hpp"
#include "parallel/distributed_product.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
#include "support/bit_difference.hpp"
#include "support/small_networks.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;

namespace {

std::vector<double> random_vector(NodeIndex n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& v : x) v = rng.uniform() - 0.25;
  return x;
}

}  // namespace

TEST_CASE("Distributed products and degrees equal the Network's bit for bit [ER, weighted ring]",
          "[distributed][theory]") {
  const Network cases[] = {erdos_renyi({2500, 0.01, 4}), test::weighted_ring(301)};
  for (const Network& net : cases) {
    const DistributedNetwork d(net);
    const DistributedProduct distributed(d);
    const NetworkProduct serial(net);
    INFO("N = " << net.size() << ", ranks " << ParallelSession::ranks());
    CHECK(distributed.size() == serial.size());
    CHECK(test::bit_difference(distributed.degrees(), serial.degrees()) == "");
    const std::vector<double> x = random_vector(net.size(), 17);
    std::vector<double> y_distributed, y_serial;
    distributed.apply(x, y_distributed);
    serial.apply(x, y_serial);
    CHECK(test::bit_difference(y_distributed, y_serial) == "");
  }
}

TEST_CASE("Components from row blocks equal the serial ones, labels included",
          "[distributed][theory]") {
  const Network cases[] = {erdos_renyi({3000, 0.0006, 8}), test::two_cliques(20, 60),
                           test::circulant(301, 1)};
  for (const Network& net : cases) {
    const Components distributed = distributed_components(DistributedNetwork(net));
    const Components serial = connected_components(net);
    CHECK(distributed.count == serial.count);
    CHECK(distributed.largest == serial.largest);
    CHECK(test::bit_difference(distributed.label, serial.label) == "");
  }
}

TEST_CASE("The self-consistent solutions on distributed rows equal the serial ones bit for bit",
          "[distributed][theory]") {
  // ER above and near onset, and two cliques (a disconnected network: per-component thresholds).
  const Network cases[] = {erdos_renyi({2000, 0.015, 9}), test::two_cliques(20, 60)};
  for (const Network& net : cases) {
    const DistributedNetwork d(net);
    const PerronResult perron = perron_eigenpair(d);
    const double sigma0 = 1.0;
    const double Kc = 2.0 * sigma0 * sigma0 * net.size() / perron.lambda;
    const std::vector<double> Ks{1.05 * Kc, 1.5 * Kc, 3.0 * Kc};
    const DistributedProduct product(d);
    const SelfConsistentSystem distributed(product, distributed_components(d), perron.lambda,
                                           sigma0, 0.0, perron.u);
    const SelfConsistentSystem serial(net, perron.lambda, sigma0, 0.0, perron.u);
    const auto a = distributed.sweep(Ks);
    const auto b = serial.sweep(Ks);
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      INFO("N = " << net.size() << ", K/K_c = " << Ks[k] / Kc);
      CHECK(a[k].status == b[k].status);
      CHECK(a[k].R == b[k].R);
      CHECK(a[k].sigma2 == b[k].sigma2);
      CHECK(a[k].iterations == b[k].iterations);
    }
    const LargeKLimit large_distributed = solve_large_k_limit(product);
    const LargeKLimit large_serial = solve_large_k_limit(net);
    CHECK(large_distributed.R_hat == large_serial.R_hat);
    CHECK(large_distributed.iterations == large_serial.iterations);
  }
}
