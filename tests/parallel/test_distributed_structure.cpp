// Structure and summary from row blocks: components, the largest one, bipartiteness (merged
// parity forests) and rho equal the serial answers on every rank count (label mpi: 1-3 ranks).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "analysis/network_summary.hpp"
#include "network/degree_statistics.hpp"
#include "network/erdos_renyi.hpp"
#include "network/structure.hpp"
#include "parallel/distributed_structure.hpp"
#include "parallel/parallel_session.hpp"
#include "spectral/perron.hpp"
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
  // The same terms summed per rank and then over ranks: sums of 3000 positive terms differ from
  // the serial order by at most ~3000 eps relative (6.7e-13 bound; 1e-13 is what a random-walk
  // rounding of ~sqrt(3000) eps reaches with room), for the three sums and their quotient.
  CHECK(std::abs(s.rho - degree_correlation(er)) <= 1e-13 * degree_correlation(er));
  // The degrees are gathered and summed in the serial order: equal up to the last bits.
  CHECK(s.mean_degree == Approx(mean_degree(er)).epsilon(1e-14));
  CHECK(s.edges == er.edges());
}

TEST_CASE(
    "A trailing hub leaves the last rank without rows, and products, structure and lambda "
    "still agree [star N=1000 with the hub last, pair N=2]",
    "[distributed][summary]") {
  std::vector<std::pair<NodeIndex, NodeIndex>> spokes;
  for (NodeIndex i = 0; i < 999; ++i) spokes.emplace_back(i, 999);
  const Network star = Network::from_undirected_edges(1000, spokes);
  const Network pair = Network::from_undirected_edges(2, {{0, 1}});
  for (const Network* net : {&star, &pair}) {
    const DistributedNetwork d(*net);
    INFO("ranks " << ParallelSession::ranks() << ", N = " << net->size() << ", rows here "
                  << d.local_size());
    std::vector<double> x_local(std::size_t(d.local_size())), y_local;
    for (std::size_t r = 0; r < x_local.size(); ++r)
      x_local[r] = 1.0 + double(d.first_row()) + double(r);
    d.apply(x_local, y_local);
    const std::vector<double> y = d.gather(y_local);
    double worst = 0.0;
    for (NodeIndex i = 0; i < net->size(); ++i) {
      double s = 0.0;
      for (const auto [j, w] : net->row(i)) s += w * (1.0 + double(j));
      worst = std::max(worst, std::abs(s - y[std::size_t(i)]));
    }
    CHECK(worst <= 1e-9);  // sums of at most 999 integers below 1000: exact in double
    const NetworkStructure s = distributed_structure(d);
    CHECK(s.components == 1);
    CHECK(s.largest == net->size());
    CHECK(s.bipartite);
    // lambda of a star S_N: sqrt(N - 1) (the pair is S_2); the solver is asked for a relative
    // residual of 1e-10 (PerronOptions::tolerance), which bounds the eigenvalue error.
    const double expected = std::sqrt(double(net->size() - 1));
    CHECK(std::abs(perron_eigenpair(d).lambda - expected) <= 1e-10 * expected);
  }
}
