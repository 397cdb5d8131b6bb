// eq:KtoInfinity, the degree approximation eq:rd and its continuum form.
#include <boost/math/tools/toms748_solve.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "network/erdos_renyi.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/theory_support.hpp"
#include "support/tolerances.hpp"
#include "theory/all_to_all.hpp"
#include "theory/large_k_limit.hpp"
#include "theory/self_consistent.hpp"

using namespace hmfnet;
using Catch::Matchers::WithinRel;

namespace {

SelfConsistentOptions tight() {
  SelfConsistentOptions o;
  o.tolerance = 1e-12;
  return o;
}

}  // namespace

TEST_CASE(
    "eq:KtoInfinity and eq:rd give R_hat = v(1/R_hat) on a regular graph "
    "[circulant N=300 d=12]",
    "[theory]") {
  const Network net = test::circulant(300, 6);
  const LargeKLimit limit = solve_large_k_limit(net, tight());
  const double expected = all_to_all_large_k_order_parameter();
  REQUIRE(limit.status == SolveStatus::converged);
  REQUIRE_THAT(limit.R_hat, WithinRel(expected, test::k_self_consistent_rel));
  REQUIRE_THAT(degree_approximation_R_hat(net.degrees()), WithinRel(expected, test::k_root_rel));
}

TEST_CASE("eq:rd is exact for a rank-one network [A = a a^T N=120]", "[theory]") {
  // r_n = (1/N) a_n sum_m a_m v(.) is proportional to a_n, and d_n = a_n sum_m a_m: r ~ d.
  std::vector<double> a(120);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 1.0 + 3.0 * static_cast<double>(i % 7) / 7.0;
  const Network net = test::rank_one(a);
  const LargeKLimit limit = solve_large_k_limit(net, tight());
  REQUIRE(limit.status == SolveStatus::converged);
  REQUIRE_THAT(limit.R_hat,
               WithinRel(degree_approximation_R_hat(net.degrees()), test::k_self_consistent_rel));
}

TEST_CASE("eq:KtoInfinity is the K -> infinity limit of eq:rSigmaBesselMain [ER N=500]",
          "[theory]") {
  // At finite K the variance equation carries sigma0^2 / K: R(K) - R_hat = O(K_c / K).
  const Network net = erdos_renyi({500, 0.04, 21});
  const test::DenseSpectrum spectrum = test::dense_spectrum(net);
  const double lambda = spectrum.eigenvalues.back();
  const LargeKLimit limit = solve_large_k_limit(net, tight());
  REQUIRE(limit.status == SolveStatus::converged);
  const SelfConsistentSystem system(net, lambda, 1.0, 0.0, spectrum.perron);
  double previous_gap = 1.0;
  for (const double kappa : {1e2, 1e3, 1e4, 1e5}) {
    const SelfConsistentSolution s = system.solve(kappa * 2.0 * 500 / lambda, tight());
    const double gap = std::abs(s.R - limit.R_hat);
    INFO("K/K_c = " << kappa << ": R = " << s.R << ", R_hat = " << limit.R_hat);
    REQUIRE(s.status == SolveStatus::converged);
    REQUIRE(gap <= 1.0 / kappa);
    REQUIRE(gap < previous_gap);
    previous_gap = gap;
  }
}

TEST_CASE("The paper's relaxed iteration reaches the same R_hat more slowly [ER N=500 beta=0.5]",
          "[theory]") {
  const Network net = erdos_renyi({500, 0.04, 22});
  SelfConsistentOptions relaxed = tight();
  relaxed.anderson_memory = 0;  // r <- (1 - beta) g(r) + beta r with beta = 1 - damping
  relaxed.damping = 0.5;
  relaxed.max_iterations = 5000;
  const LargeKLimit slow = solve_large_k_limit(net, relaxed);
  const LargeKLimit fast = solve_large_k_limit(net, tight());
  INFO("relaxed: " << slow.iterations << " iterations, accelerated: " << fast.iterations);
  REQUIRE(slow.status == SolveStatus::converged);
  REQUIRE(fast.status == SolveStatus::converged);
  REQUIRE_THAT(fast.R_hat, WithinRel(slow.R_hat, 1e-10));
  REQUIRE(fast.iterations < slow.iterations);
}

TEST_CASE(
    "The continuum eq:rd matches the degree sum over a quantile sample "
    "[power law alpha 2.5 to 3.8 cutoff 10 d_min]",
    "[theory]") {
  // Degrees k_i = k(u_i) at u_i = (i + 1/2)/M are the midpoint rule of the continuum integral
  // over the survival function u. With a cutoff the integrand is smooth, but it varies on the
  // scale c = (cutoff/d_min)^(1-alpha) near u = 0; with cutoff 10 d_min, c >= 1.6e-3 >> 1/M and
  // the midpoint error is O((M c)^-2) <= 4e-8 for M = 10^5.
  for (const double alpha : {2.5, 3.1, 3.8}) {
    const PowerLaw law{alpha, 33.0, 330.0};
    const double c = std::pow(law.cutoff / law.d_min, 1.0 - alpha);
    std::vector<double> degrees(100000);
    for (std::size_t i = 0; i < degrees.size(); ++i) {
      const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(degrees.size());
      degrees[i] = law.d_min * std::pow(c + u * (1.0 - c), -1.0 / (alpha - 1.0));
    }
    const double continuum = degree_approximation_R_hat(law);
    INFO("alpha = " << alpha << ": continuum " << continuum);
    REQUIRE_THAT(degree_approximation_R_hat(degrees), WithinRel(continuum, 1e-7));
    // The equation is scale free: only alpha and cutoff / d_min matter.
    REQUIRE_THAT(degree_approximation_R_hat(PowerLaw{alpha, 1.0, 10.0}),
                 WithinRel(continuum, test::k_quadrature_rel));
  }
}

TEST_CASE("The continuum eq:rd without cutoff is the limit of large cutoffs [alpha = 2.8]",
          "[theory]") {
  const double open = degree_approximation_R_hat(PowerLaw{2.8, 44.0});
  const double far = degree_approximation_R_hat(PowerLaw{2.8, 44.0, 44.0 * 1e12});
  REQUIRE_THAT(far, WithinRel(open, 1e-8));
  REQUIRE(open > 0.0);
  REQUIRE(open < 1.0);
}

TEST_CASE("The degree approximation refuses empty or negative degrees [bad input]", "[theory]") {
  REQUIRE_THROWS_AS(degree_approximation_R_hat(std::vector<double>{}), ParameterError);
  REQUIRE_THROWS_AS(degree_approximation_R_hat(std::vector<double>{1.0, -1.0}), ParameterError);
  REQUIRE_THROWS_AS(degree_approximation_R_hat(std::vector<double>{0.0, 0.0}), ParameterError);
  REQUIRE_THROWS_AS(degree_approximation_R_hat(PowerLaw{1.9, 10.0}), ParameterError);
}
