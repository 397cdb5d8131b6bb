// Per-component largest eigenvalues (spectral/component_radii.hpp) against closed forms and the
// dense solver, including a bipartite component (whose -lambda_c the shift must defeat).
#include <catch2/catch.hpp>
#include <utility>
#include <vector>

#include "network/erdos_renyi.hpp"
#include "network/stochastic_block.hpp"
#include "network/structure.hpp"
#include "spectral/component_radii.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;

TEST_CASE("Component radii of two cliques are their sizes minus one [K_4 and K_7]",
          "[component_radii]") {
  const Network net = test::two_cliques(4, 7);
  const Components c = connected_components(net);
  const ComponentRadii r = component_radii(net, c);
  REQUIRE(r.converged);
  REQUIRE(r.lambda.size() == 2);
  CHECK(r.lambda[0] == Approx(3.0).epsilon(test::k_eigenvalue_rel));
  CHECK(r.lambda[1] == Approx(6.0).epsilon(test::k_eigenvalue_rel));
}

TEST_CASE("Component radii: a star beside a clique and an isolated node [S_10, K_5, K_1]",
          "[component_radii]") {
  // Star on nodes 0..9 (bipartite: lambda_c = 3 and -3), K_5 on 10..14, node 15 isolated.
  std::vector<std::pair<NodeIndex, NodeIndex>> e;
  for (NodeIndex i = 1; i < 10; ++i) e.emplace_back(0, i);
  for (NodeIndex i = 10; i < 15; ++i)
    for (NodeIndex j = i + 1; j < 15; ++j) e.emplace_back(i, j);
  const Network net = Network::from_undirected_edges(16, e);
  const ComponentRadii r = component_radii(net, connected_components(net));
  REQUIRE(r.converged);
  CHECK(r.lambda[0] == Approx(3.0).epsilon(test::k_eigenvalue_rel));
  CHECK(r.lambda[1] == Approx(4.0).epsilon(test::k_eigenvalue_rel));
  CHECK(r.lambda[2] == 0.0);
}

TEST_CASE("Component radii of two ER communities match the dense solver [2 x 300]",
          "[component_radii]") {
  const Network net = two_block_sbm({300, 0.08, 0.0, 3});
  const ComponentRadii r = component_radii(net, connected_components(net));
  REQUIRE(r.converged);
  REQUIRE(r.lambda.size() == 2);
  const test::DenseSpectrum dense = test::dense_spectrum(net);
  // The two largest eigenvalues of a block-diagonal A are the blocks' lambda_c.
  const double top = dense.eigenvalues.back(),
               second = dense.eigenvalues[dense.eigenvalues.size() - 2];
  CHECK(std::max(r.lambda[0], r.lambda[1]) == Approx(top).epsilon(test::k_eigenvalue_rel));
  CHECK(std::min(r.lambda[0], r.lambda[1]) == Approx(second).epsilon(test::k_eigenvalue_rel));
}
