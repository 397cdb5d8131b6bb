// The dispersion relation of the incoherent state: eq:dispersion (full), eq:lambdaHat
// (independence approximation eq:bkApprox) and the N -> infinity integral behind eq:gammaKKc.
#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "network/erdos_renyi.hpp"
#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"
#include "support/tolerances.hpp"
#include "theory/dispersion_relation.hpp"
#include "theory/growth_rate.hpp"

using namespace hmfnet;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double k_omega = 6.0;  // the paper's mean momentum

// Stratified Gaussian sample: the quantiles at (n + 1/2)/N in a seeded random order, so that the
// momenta are independent of the network (the hypothesis of eq:bkApprox).
std::vector<double> quantile_momenta(std::size_t n, double sigma0, unsigned seed) {
  const boost::math::normal_distribution<double> g(k_omega, sigma0);
  std::vector<double> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = boost::math::quantile(g, (static_cast<double>(i) + 0.5) / static_cast<double>(n));
  }
  std::shuffle(p.begin(), p.end(), std::mt19937_64(seed));
  return p;
}

// K for K/K_c = kappa with sigma0^2 the sample variance (the K_c the sample itself sees).
double coupling(double kappa, double sigma0, double n, double lambda) {
  return kappa * 2.0 * sigma0 * sigma0 * n / lambda;
}

}  // namespace

TEST_CASE(
    "gamma of eq:gammaKKc solves the dispersion relation integrated numerically "
    "[Gaussian momenta K/K_c = 1.05 to 100]",
    "[theory]") {
  // 2N/(K lambda) = int g(p) dp / (s - i p)^2 at s = gamma + i Omega, i.e. K_c / (K sigma0^2).
  const double sigma0 = 0.35;
  for (const double kappa : {1.05, 1.5, 3.0, 100.0}) {
    const double gamma = growth_rate(kappa, sigma0);
    const std::complex<double> I = gaussian_dispersion_integral({gamma, k_omega}, k_omega, sigma0);
    const double target = 1.0 / (kappa * sigma0 * sigma0);
    INFO("K/K_c = " << kappa << ": gamma = " << gamma << ", I = " << I << ", target " << target);
    REQUIRE_THAT(I.real(), WithinRel(target, test::k_quadrature_rel));
    REQUIRE_THAT(I.imag(), WithinAbs(0.0, test::k_quadrature_rel * target));
    // And the root of the quadrature itself, found without eq:gammaKKc.
    auto f = [&](double g) {
      return gaussian_dispersion_integral({g, k_omega}, k_omega, sigma0).real() - target;
    };
    std::uintmax_t iterations = 100;
    const auto root = boost::math::tools::toms748_solve(
        f, 1e-3 * gamma, 10.0 * gamma, boost::math::tools::eps_tolerance<double>(40), iterations);
    REQUIRE_THAT(0.5 * (root.first + root.second), WithinRel(gamma, 1e-8));
  }
}

TEST_CASE(
    "The independence approximation is exact on the complete graph with self-loops "
    "[N=300 random momenta]",
    "[theory]") {
  // A = all ones: A diag(w) has the single nonzero eigenvalue sum_n w_n = lambda ||w||.
  const Network net = test::complete(300, true);
  std::mt19937_64 engine(5);
  std::normal_distribution<double> normal(k_omega, 0.35);
  std::vector<double> p(300);
  for (auto& x : p) x = normal(engine);
  const double K = coupling(2.0, 0.35, 300, 300.0);
  const std::complex<double> s0(growth_rate(2.0, 0.35), k_omega);
  const DispersionRoot full = solve_dispersion(net, K, p);
  const DispersionRoot independent = solve_independent_dispersion(K, 300.0, p, s0);
  INFO("full s = " << full.s << " (" << full.iterations << " steps), independent "
                   << independent.s);
  REQUIRE(full.converged);
  REQUIRE(independent.converged);
  REQUIRE(std::abs(full.s - independent.s) <= 1e-10 * std::abs(full.s));
}

TEST_CASE(
    "eq:lambdaHat approaches eq:gammaKKc for quantile samples of Gaussian momenta "
    "[N = 1000 to 100000]",
    "[theory]") {
  // The sample of N quantiles has variance sigma0^2 (1 - O(log N / N)); its gamma approaches the
  // population value at that rate. We require the error to fall below 2% at N = 1000 and to
  // shrink at least 5-fold per factor 10 in N.
  const double sigma0 = 0.35, kappa = 2.0, lambda = 1.0;
  const double gamma = growth_rate(kappa, sigma0);
  double previous = 1.0;
  for (const std::size_t n : {1000u, 10000u, 100000u}) {
    const std::vector<double> p = quantile_momenta(n, sigma0, 1);
    const double K = coupling(kappa, sigma0, static_cast<double>(n), lambda);
    const DispersionRoot root =
        solve_independent_dispersion(K, lambda, p, {0.8 * gamma, k_omega + 0.1});
    const double error = std::abs(root.s.real() - gamma) / gamma;
    INFO("N = " << n << ": s = " << root.s << ", gamma = " << gamma << ", error " << error);
    REQUIRE(root.converged);
    REQUIRE_THAT(root.s.imag(), WithinAbs(k_omega, 1e-6));
    REQUIRE(error < 0.02);
    REQUIRE(error < previous / 5.0);
    previous = error;
  }
}

TEST_CASE(
    "On finite ER networks the full dispersion relation departs from the independence "
    "approximation by an amount that falls with the degree [N=250 d=20 and 160]",
    "[theory]") {
  // eq:bkApprox replaces sum_n A_kn b_n w_n by ||w|| sum_n A_kn b_n; on a node of degree d the
  // neglected fluctuation is ~ sd(w) / (|w| sqrt(d)), and w = (s - i p)^-2 spreads widely
  // (sd/|mean| ~ 3 at K = 2 K_c), so the mode b departs from u and gamma moves. Measured over
  // seeds 1-8 (docs/theory.md): |s_full - s_independent| / gamma = 0.31 on average (0.09-0.78)
  // for d = 20 and 0.046 (0.02-0.10) for d = 160, at N = 250 as at N = 1000. The bounds below
  // (seeds 1-4) are those measurements with room; they fail if the solver leaves the Perron branch.
  const double sigma0 = 0.35;
  double mean_gap[2] = {0.0, 0.0};
  const double degrees[2] = {20.0, 160.0};
  for (int k = 0; k < 2; ++k) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const Network net = erdos_renyi({250, degrees[k] / 249.0, seed});
      const double lambda = test::dense_spectrum(net).eigenvalues.back();
      const std::vector<double> p = quantile_momenta(250, sigma0, seed + 10);
      const double K = coupling(2.0, sigma0, 250, lambda);
      const DispersionRoot full = solve_dispersion(net, K, p);
      const DispersionRoot independent =
          solve_independent_dispersion(K, lambda, p, {growth_rate(2.0, sigma0), k_omega});
      INFO("d = " << degrees[k] << ", seed " << seed << ": full s = " << full.s << " ("
                  << full.iterations << " Newton steps), independent s = " << independent.s);
      REQUIRE(full.converged);
      REQUIRE(independent.converged);
      REQUIRE(full.s.real() > 0.0);
      mean_gap[k] += std::abs(full.s - independent.s) / independent.s.real() / 4.0;
    }
  }
  INFO("mean gap / gamma: d = 20: " << mean_gap[0] << ", d = 160: " << mean_gap[1]);
  REQUIRE(mean_gap[1] < 0.15);
  REQUIRE(mean_gap[1] < 0.5 * mean_gap[0]);
}

TEST_CASE("The dispersion solvers refuse bad input [N > 2000 or Re s0 <= 0]", "[theory]") {
  const Network big = test::circulant(2001, 1);
  REQUIRE_THROWS_AS(solve_dispersion(big, 1.0, std::vector<double>(2001, 6.0)), ParameterError);
  const Network small = test::circulant(10, 1);
  REQUIRE_THROWS_AS(solve_dispersion(small, 1.0, std::vector<double>(9, 6.0)), ParameterError);
  REQUIRE_THROWS_AS(solve_independent_dispersion(1.0, 2.0, {6.0}, {-1.0, 6.0}), ParameterError);
  REQUIRE_THROWS_AS(solve_independent_dispersion(1.0, 2.0, {}, {1.0, 6.0}), ParameterError);
  REQUIRE_THROWS_AS(gaussian_dispersion_integral({0.0, 6.0}, 6.0, 0.35), ParameterError);
}
