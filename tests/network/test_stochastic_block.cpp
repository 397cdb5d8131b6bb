// The two-block stochastic block model (network/stochastic_block.hpp): link counts inside and
// between the communities are binomial, and the limits p_out = 0 and p_in = 0 give exactly the
// disconnected and the bipartite networks.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "network/stochastic_block.hpp"
#include "network/structure.hpp"
#include "support/bit_difference.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

namespace {

struct Counts {
  double inside = 0, between = 0;
};

Counts count_links(const Network& net, NodeIndex half) {
  Counts c;
  for (NodeIndex i = 0; i < net.size(); ++i)
    for (EdgeOffset k = net.row_begin(i); k < net.row_end(i); ++k) {
      const NodeIndex j = net.col(k);
      if (j <= i) continue;
      ((i < half) == (j < half) ? c.inside : c.between) += 1;
    }
  return c;
}

}  // namespace

TEST_CASE("Two-block SBM link counts are binomial within 4 sigma [half=800]",
          "[stochastic_block]") {
  const NodeIndex half = 800;
  const double pairs_in = 2.0 * 0.5 * half * (half - 1.0), pairs_out = double(half) * half;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Network net = two_block_sbm({half, 0.05, 0.004, seed});
    REQUIRE(Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights()).empty());
    const Counts c = count_links(net, half);
    const double sd_in = std::sqrt(pairs_in * 0.05 * 0.95);
    const double sd_out = std::sqrt(pairs_out * 0.004 * 0.996);
    INFO("seed " << seed << ": inside " << c.inside << " (" << pairs_in * 0.05 << "), between "
                 << c.between << " (" << pairs_out * 0.004 << ")");
    CHECK(std::abs(c.inside - pairs_in * 0.05) <= test::k_sigmas * sd_in);
    CHECK(std::abs(c.between - pairs_out * 0.004) <= test::k_sigmas * sd_out);
  }
}

TEST_CASE("Two-block SBM limits: disconnected for p_out = 0, bipartite for p_in = 0",
          "[stochastic_block]") {
  const Network apart = two_block_sbm({300, 0.1, 0.0, 2});
  CHECK(connected_components(apart).count == 2);
  CHECK(count_links(apart, 300).between == 0);
  const Network bipartite = two_block_sbm({300, 0.0, 0.1, 2});
  CHECK(is_bipartite(bipartite));
  CHECK(count_links(bipartite, 300).inside == 0);
}

TEST_CASE("Two-block SBM is a function of its seed and refuses bad parameters",
          "[stochastic_block]") {
  CHECK(test::bit_difference(two_block_sbm({200, 0.1, 0.01, 4}).cols(),
                             two_block_sbm({200, 0.1, 0.01, 4}).cols()) == "");
  CHECK(two_block_sbm({200, 0.1, 0.01, 4}).cols() != two_block_sbm({200, 0.1, 0.01, 5}).cols());
  CHECK_THROWS_AS(two_block_sbm({0, 0.1, 0.01, 1}), ParameterError);
  CHECK_THROWS_AS(two_block_sbm({10, 1.5, 0.01, 1}), ParameterError);
  CHECK_THROWS_AS(two_block_sbm({10, 0.1, std::nan(""), 1}), ParameterError);
}
