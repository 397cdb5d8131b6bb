#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "theory/critical_coupling.hpp"
#include "theory/momentum_distribution.hpp"

using namespace hmfnet;

TEST_CASE("Momentum distributions are named both ways, and an unknown name is refused",
          "[theory]") {
  for (const auto g : {MomentumDistribution::gaussian, MomentumDistribution::waterbag})
    REQUIRE(parse_momentum_distribution(name_of(g)) == g);
  REQUIRE_THROWS_WITH(parse_momentum_distribution("lorentz", "--momenta"),
                      Catch::Contains("--momenta") && Catch::Contains("gaussian, waterbag"));
}

TEST_CASE("Water-bag threshold: 2N / (K lambda) = 1 / D^2, i.e. 6 sigma0^2 N / lambda",
          "[theory]") {
  const double sigma0 = 0.35, n = 1e4, lambda = 101.0;
  const double D = waterbag_half_width(sigma0);
  REQUIRE(D * D == Approx(3.0 * sigma0 * sigma0).epsilon(1e-15));
  // -g' of the water-bag is 1 / 2D at Omega - D and -1 / 2D at Omega + D (as deltas), so
  // integral -g'(p) / (p - Omega) dp = (1 / 2D)(1 / D) + (1 / 2D)(1 / D) = 1 / D^2.
  const double integral = 1.0 / (2.0 * D) * (1.0 / D) + 1.0 / (2.0 * D) * (1.0 / D);
  const double Kc = critical_coupling(MomentumDistribution::waterbag, sigma0, n, lambda);
  REQUIRE(2.0 * n / (Kc * lambda) == Approx(integral).epsilon(1e-14));
  REQUIRE(Kc == Approx(3.0 * critical_coupling(sigma0, n, lambda)).epsilon(1e-14));
  REQUIRE(critical_coupling(MomentumDistribution::gaussian, sigma0, n, lambda) ==
          critical_coupling(sigma0, n, lambda));
  REQUIRE_THROWS_AS(critical_coupling(MomentumDistribution::waterbag, 0.0, n, lambda),
                    ParameterError);
}
