// The numerical dispersion path for any even g against the closed forms of both distributions,
// to 1e-10 (eq:gDashPSGammaPlusOmega; the Gaussian's is eq:gammaKKc).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/growth_rate.hpp"
#include "theory/linear_stability.hpp"

using namespace hmfnet;

namespace {

// eq:gammaKKc in terms of J: J(gamma) sigma0^2 = K_c / K = 1 - f(y), y = gamma / (sqrt2 sigma0).
double gaussian_J(double gamma, double sigma0) {
  return growth_rate_deficit(gamma / (std::sqrt(2.0) * sigma0)) / (sigma0 * sigma0);
}

double waterbag_J(double gamma, double sigma0) {
  const double D = waterbag_half_width(sigma0);
  return 1.0 / (gamma * gamma + D * D);
}

}  // namespace

TEST_CASE("J(gamma) of the numerical path equals both closed forms to 1e-10", "[theory]") {
  for (const double sigma0 : {0.35, 1.0, 3.0}) {
    const EvenDensity gauss = even_density(MomentumDistribution::gaussian, sigma0);
    const EvenDensity bag = even_density(MomentumDistribution::waterbag, sigma0);
    for (const double r : {0.0, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 20.0}) {
      const double gamma = r * sigma0;
      INFO("sigma0 " << sigma0 << ", gamma " << gamma);
      REQUIRE(dispersion_integral(gauss, gamma) ==
              Approx(gaussian_J(gamma, sigma0)).epsilon(1e-10));
      REQUIRE(dispersion_integral(bag, gamma) == Approx(waterbag_J(gamma, sigma0)).epsilon(1e-10));
    }
  }
}

TEST_CASE("Thresholds and growth rates of the numerical path equal the closed forms to 1e-10",
          "[theory]") {
  const double sigma0 = 0.35, n = 1e4, lambda = 101.0;
  for (const auto g : {MomentumDistribution::gaussian, MomentumDistribution::waterbag}) {
    const EvenDensity d = even_density(g, sigma0);
    INFO(name_of(g));
    REQUIRE(linear_threshold(d, n, lambda) ==
            Approx(critical_coupling(g, sigma0, n, lambda)).epsilon(1e-10));
    REQUIRE(linear_growth_rate(d, 1.0) == 0.0);
    for (const double kappa : {1.001, 1.01, 1.1, 1.5, 2.0, 4.0, 10.0, 100.0}) {
      INFO("K/K_c " << kappa);
      REQUIRE(linear_growth_rate(d, kappa) == Approx(growth_rate(g, kappa, sigma0)).epsilon(1e-10));
    }
    REQUIRE_THROWS_AS(linear_growth_rate(d, 0.9), ParameterError);
    REQUIRE_THROWS_AS(growth_rate(g, 0.9, sigma0), ParameterError);
  }
}

TEST_CASE("Any even g: a Gaussian / water-bag mixture is the mixture of their J", "[theory]") {
  // Smooth part and jumps together: J is linear in g.
  const double sigma0 = 0.7, w = 0.3;
  const EvenDensity gauss = even_density(MomentumDistribution::gaussian, sigma0);
  const EvenDensity bag = even_density(MomentumDistribution::waterbag, sigma0);
  EvenDensity mix;
  mix.minus_slope_over_x = [&](double x) { return w * gauss.minus_slope_over_x(x); };
  mix.jumps = {{bag.jumps[0].first, (1.0 - w) * bag.jumps[0].second}};
  for (const double gamma : {0.0, 0.05, 0.4, 2.0}) {
    REQUIRE(dispersion_integral(mix, gamma) ==
            Approx(w * gaussian_J(gamma, sigma0) + (1.0 - w) * waterbag_J(gamma, sigma0))
                .epsilon(1e-10));
  }
  const double kappa = 2.5, gamma = linear_growth_rate(mix, kappa);
  REQUIRE(dispersion_integral(mix, gamma) ==
          Approx(dispersion_integral(mix, 0.0) / kappa).epsilon(1e-12));
}

TEST_CASE("A density with J(0) <= 0 is refused naming the reason", "[theory]") {
  EvenDensity hollow;  // mass at the edges only, growing outward: -g'(x)/x < 0
  hollow.minus_slope_over_x = [](double) { return 0.0; };
  hollow.support = 1.0;
  hollow.jumps = {{1.0, 0.5}};
  REQUIRE_THROWS_WITH(linear_threshold(hollow, 100, 10), Catch::Contains("J(0)"));
  REQUIRE_THROWS_WITH(linear_growth_rate(hollow, 2.0), Catch::Contains("peaked at its centre"));
}
