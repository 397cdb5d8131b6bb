// The all-to-all / d-regular curve R(K/K_c) and its K -> infinity limit (all_to_all.hpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "support/tolerances.hpp"
#include "theory/all_to_all.hpp"
#include "theory/bessel_ratio.hpp"

using namespace hmfnet;

TEST_CASE("The all-to-all R solves R = v(2kR/(1+2kR^2)) and rises with K [1.001 <= K/K_c <= 1e6]",
          "[theory]") {
  double previous = 0.0;
  for (const double kappa : {1.001, 1.01, 1.1, 2.0, 10.0, 1e3, 1e6}) {
    const double R = all_to_all_order_parameter(kappa);
    const double x = 2.0 * kappa * R / (1.0 + 2.0 * kappa * R * R);
    INFO("K/K_c = " << kappa << ", R = " << R);
    REQUIRE(R > previous);
    REQUIRE(R < 1.0);
    REQUIRE_THAT(bessel_ratio(x), Catch::Matchers::WithinRel(R, test::k_root_rel));
    REQUIRE_THAT(all_to_all_variance_ratio(kappa),
                 Catch::Matchers::WithinRel(1.0 + 2.0 * kappa * R * R, 1e-15));
    previous = R;
  }
}

TEST_CASE("The all-to-all R is zero up to K_c [0 <= K/K_c <= 1]", "[theory]") {
  for (const double kappa : {0.0, 0.5, 1.0}) REQUIRE(all_to_all_order_parameter(kappa) == 0.0);
  REQUIRE_THROWS_AS(all_to_all_order_parameter(-1.0), ParameterError);
}

TEST_CASE("Near onset the all-to-all R / sqrt(K/K_c - 1) tends to G = sqrt(2/5) [K -> K_c+]",
          "[theory]") {
  // eq:globalOrderRInDeltaK for a regular graph; the next term is O(K/K_c - 1) relative.
  for (const double delta : {1e-2, 1e-4, 1e-6}) {
    const double ratio = all_to_all_order_parameter(1.0 + delta) / std::sqrt(delta);
    INFO("K/K_c - 1 = " << delta << ", R / sqrt(dK/K_c) = " << ratio);
    REQUIRE(std::abs(ratio / std::sqrt(0.4) - 1.0) <= 2.0 * delta);
  }
}

TEST_CASE("The large-K limit solves R = v(1/R) and is where the curve ends [K/K_c = 1e8]",
          "[theory]") {
  const double R_hat = all_to_all_large_k_order_parameter();
  REQUIRE_THAT(bessel_ratio(1.0 / R_hat), Catch::Matchers::WithinRel(R_hat, test::k_root_rel));
  // The curve approaches its limit as 1/K: R(1e8 K_c) differs by ~1e-8.
  REQUIRE_THAT(all_to_all_order_parameter(1e8), Catch::Matchers::WithinRel(R_hat, 1e-7));
}
