// Edge sources (network/edge_source.hpp): each unit's edges depend on the unit alone, so the
// network does not depend on the order or the split in which units are emitted (what lets ranks
// generate their shares independently), and the ER source gives the threaded generator's network.
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>

#include "core/error.hpp"
#include "network/chung_lu.hpp"
#include "network/edge_source.hpp"
#include "network/erdos_renyi.hpp"
#include "network/stochastic_block.hpp"

using namespace hmfnet;

namespace {

bool same_network(const Network& a, const Network& b) {
  return a.size() == b.size() && a.row_ptr() == b.row_ptr() && a.cols() == b.cols() &&
         a.weights() == b.weights();
}

// Units emitted last to first, each into its own list, then joined.
Network reversed(const EdgeSource& source) {
  std::vector<Edge> edges;
  std::vector<Edge> unit;
  for (std::int64_t k = source.units() - 1; k >= 0; --k) {
    unit.clear();
    source.emit(k, unit);
    edges.insert(edges.end(), unit.begin(), unit.end());
  }
  return Network::from_undirected_edges(source.nodes(), edges);
}

void check_source(const EdgeSource& source) {
  const Network net = network_from_source(source);
  CHECK(Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights()).empty());
  CHECK(net.self_loops() == 0);
  CHECK(same_network(reversed(source), net));
  for (const int parts : {1, 2, 3, 7}) {
    const auto starts = balanced_unit_starts(source, parts);
    REQUIRE(starts.size() == static_cast<std::size_t>(parts) + 1);
    CHECK(starts.front() == 0);
    CHECK(starts.back() == source.units());
    CHECK(std::is_sorted(starts.begin(), starts.end()));
    // Each part holds at least its share of the work up to one unit (bisection on the first
    // unit reaching p W / parts).
    const double total = source.work_before(source.units());
    for (int p = 1; p < parts; ++p) {
      const auto k = starts[static_cast<std::size_t>(p)];
      CHECK(source.work_before(k) >= total * p / parts);
      if (k > 0) CHECK(source.work_before(k - 1) < total * p / parts);
    }
  }
}

}  // namespace

TEST_CASE("The ER source gives the threaded generator's network [N=1..3000, q=0..1]",
          "[edge_source][erdos_renyi]") {
  for (const auto& params : {ErdosRenyiParameters{1, 0.5, 1}, ErdosRenyiParameters{400, 0.0, 2},
                             ErdosRenyiParameters{200, 1.0, 3}, ErdosRenyiParameters{3000, 0.01, 4},
                             ErdosRenyiParameters{3000, 0.2, 5}}) {
    INFO("N = " << params.n << ", q = " << params.q);
    const auto source = erdos_renyi_source(params);
    CHECK(same_network(network_from_source(*source), erdos_renyi(params)));
    check_source(*source);
  }
  CHECK_THROWS_AS(erdos_renyi_source({0, 0.5, 1}), ParameterError);
  CHECK_THROWS_AS(erdos_renyi_source({10, 1.5, 1}), ParameterError);
}

TEST_CASE("Chung-Lu and two-block SBM sources do not depend on the order of their units",
          "[edge_source][chung_lu][stochastic_block]") {
  const PowerLaw law{2.5, power_law_d_min_for_mean(2.5, 20.0)};
  for (const auto link :
       {LinkProbability::capped, LinkProbability::poisson, LinkProbability::odds}) {
    check_source(*chung_lu_source(power_law_targets(3000, law, 9), link, 9));
  }
  check_source(*two_block_sbm_source({300, 0.05, 0.005, 6}));
  check_source(*two_block_sbm_source({1, 1.0, 1.0, 6}));
  CHECK_THROWS_AS(chung_lu_source({}, LinkProbability::capped, 1), ParameterError);
  CHECK_THROWS_AS(two_block_sbm_source({0, 0.5, 0.5, 1}), ParameterError);
}
