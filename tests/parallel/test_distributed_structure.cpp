// Structure and summary from row blocks: components, the largest one, bipartiteness (merged
// parity forests) and rho equal the serial answers on every rank count (label mpi: 1-3 ranks).
#include <catch2/catch.hpp>
#include <cmath>

#include "analysis/network_summary.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "network/structure.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

TEST_CASE(
    "The summary from row blocks equals the serial structure on every rank count "
    "[sparse ER with many components, odd ring, K_{3,4}]",
    "[distributed][summary]") {
  const std::vector<Network> cases{erdos_renyi({3000, 0.0006, 8}), test::circulant(301, 1),
                                   test::complete_bipartite(3, 4)};
  for (const Network& net : cases) {
    const DistributedNetwork d(net);
    const NetworkStructure s = distributed_structure(d);
    const Components c = connected_components(net);
    INFO("ranks " << ParallelSession::ranks() << ", N = " << net.size());
    CHECK(s.components == c.count);
    CHECK(s.largest == c.largest);
    CHECK(s.bipartite == is_bipartite(net));
  }
  // rho (eq:rhodef) from the row blocks against the serial formula of degree_statistics.
  const Network er = erdos_renyi({3000, 0.01, 8});
  PerronResult perron;
  perron.lambda = 1.0;
  perron.u.assign(std::size_t(er.size()), 1.0 / std::sqrt(double(er.size())));
  const NetworkSummary s = summarise(DistributedNetwork(er), perron);
  CHECK(std::abs(s.rho - degree_correlation(er)) <= 1e-13 * degree_correlation(er));
  CHECK(s.mean_degree == Approx(mean_degree(er)).epsilon(1e-14));
  CHECK(s.edges == er.edges());
}
