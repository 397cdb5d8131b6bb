// Lanczos bounds on lambda_2 (spectral/second_eigenvalue_bound.hpp) against Eigen's dense
// spectrum: the lower bound never exceeds lambda_2, the upper bound is not below it (a failure
// would have probability <= 1e-6 over the seeded start), a run to breakdown gives lambda_2 itself,
// and perron_eigenpair converges lambda_2 exactly when the bounds cannot settle the 1.1 ratio.
// Collective: run at 1, 2 and 3 ranks (label mpi).
#include <catch2/catch.hpp>
#include <cmath>

#include "network/chung_lu.hpp"
#include "network/erdos_renyi.hpp"
#include "network/stochastic_block.hpp"
#include "parallel/distributed_network.hpp"
#include "spectral/perron.hpp"
#include "spectral/second_eigenvalue_bound.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"

using namespace hmfnet;
using Catch::Matchers::WithinAbs;

namespace {

double dense_lambda2(const Network& net) {
  const auto e = test::dense_spectrum(net).eigenvalues;
  return e[e.size() - 2];
}

// Round-off allowance of a Ritz value of a k-step Lanczos run: a few eps ||A|| per step
// (Paige 1980), ||A|| <= lambda for a non-negative A.
double ritz_slack(double lambda, int steps) { return 1e-13 * lambda * steps; }

}  // namespace

TEST_CASE("Lanczos bounds bracket lambda_2 at every step count [ER, SF, SBM N=600]",
          "[perron][lambda2_bound]") {
  const PowerLaw law{2.5, power_law_d_min_for_mean(2.5, 12.0)};
  const Network networks[] = {erdos_renyi({600, 0.03, 5}),
                              chung_lu(power_law_targets(600, law, 6), LinkProbability::capped, 6),
                              two_block_sbm({300, 0.1, 0.003, 5})};
  for (const Network& net : networks) {
    const DistributedNetwork d(net);
    const PerronResult perron = perron_eigenpair(d);
    const double exact = dense_lambda2(net);
    for (const int steps : {5, 20, 60}) {
      const SecondEigenvalueBound b = bound_second_eigenvalue(
          d, perron.u, perron.lambda, [](double, double) { return false; }, steps);
      INFO("lambda " << perron.lambda << ", dense lambda_2 " << exact << ", after " << b.steps
                     << " steps: [" << b.lower << ", " << b.upper << "]");
      CHECK(b.steps == steps);
      CHECK(b.lower <= exact + ritz_slack(perron.lambda, steps));
      CHECK(b.upper >= exact - ritz_slack(perron.lambda, steps));
      // At 5 steps eps_k >= 1 (no upper bound yet, +inf); from 20 steps on it is finite
      // (N = 600: eps_20 = 0.38, eps_60 = 0.048), so the bracket above is not vacuous.
      CHECK(std::isfinite(b.upper) == (steps >= 20));
    }
  }
}

TEST_CASE("Lanczos run to breakdown gives lambda_2 itself [ring, star, K_ab, N=80 ER]",
          "[perron][lambda2_bound]") {
  const Network networks[] = {test::circulant(101, 2), test::star(200),
                              test::complete_bipartite(30, 50), erdos_renyi({80, 0.2, 3})};
  for (const Network& net : networks) {
    const DistributedNetwork d(net);
    const PerronResult perron = perron_eigenpair(d);
    const SecondEigenvalueBound b = bound_second_eigenvalue(
        d, perron.u, perron.lambda, [](double, double) { return false; }, net.size());
    const double exact = dense_lambda2(net);
    INFO("N = " << net.size() << ", dense lambda_2 " << exact << ", " << b.steps << " steps");
    CHECK(b.exact);
    // The ring's lambda_2 is a degenerate cosine pair; Lanczos without reorthogonalisation finds
    // it to round-off amplified by its copies (Paige): 1e-8 relative to lambda.
    CHECK_THAT(b.lower, WithinAbs(exact, 1e-8 * perron.lambda));
    CHECK(b.upper == b.lower);
  }
}

TEST_CASE("perron_eigenpair bounds lambda_2 when that settles the ratio, converges it otherwise",
          "[perron][lambda2_bound]") {
  PerronOptions bounded;
  bounded.second_eigenvalue = true;
  bounded.bound_lambda2_first = true;
  PerronOptions converged = bounded;
  converged.bound_lambda2_first = false;

  // ER degree 30: lambda / lambda_2 ~ 31 / 11, settled by the bounds alone.
  const Network er = erdos_renyi({1500, 0.02, 8});
  const DistributedNetwork d_er(er);
  const PerronResult b = perron_eigenpair(d_er, bounded);
  const PerronResult c = perron_eigenpair(d_er, converged);
  INFO("bounds [" << b.lambda2_lower << ", " << b.lambda2_upper << "], converged " << c.lambda2);
  CHECK(std::isnan(b.lambda2));
  CHECK(b.lambda2_upper < b.lambda / bounded.gap_ratio);
  CHECK(b.lambda2_lower <= c.lambda2 + ritz_slack(b.lambda, b.lambda2_bound_steps));
  CHECK(b.lambda2_upper >= c.lambda2);
  CHECK(b.lambda2_bound_failure == 1e-6);
  CHECK(b.lambda == c.lambda);

  // Two weakly linked communities: lambda / lambda_2 ~ 1.06, so lambda_2 is converged and equals
  // the one converged directly.
  const Network sbm = two_block_sbm({300, 0.1, 0.003, 5});
  const DistributedNetwork d_sbm(sbm);
  const PerronResult near = perron_eigenpair(d_sbm, bounded);
  const double exact = dense_lambda2(sbm);
  INFO("near-degenerate: lambda_2 " << near.lambda2 << ", dense " << exact);
  CHECK(near.lambda2_lower >= near.lambda / bounded.gap_ratio);
  CHECK(near.lambda2 == Approx(exact).epsilon(test::k_eigenvalue_rel));
}
