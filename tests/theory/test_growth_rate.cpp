// eq:gammaKKc: erfcx against 50-digit arithmetic, the root against the equation, and the limits
// K -> K_c+ (gamma -> 0 linearly) and K -> infinity (gamma -> sigma0 sqrt(K/K_c)).
#include <boost/math/special_functions/erf.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "support/tolerances.hpp"
#include "theory/growth_rate.hpp"

using namespace hmfnet;
using Catch::Matchers::WithinRel;
using Big = boost::multiprecision::cpp_bin_float_50;

namespace {

Big big_erfcx(double y) {
  const Big by = y;
  return boost::multiprecision::exp(by * by) * boost::math::erfc(by);
}

// 1 - sqrt(pi) y erfcx(y) in 50 digits; beyond y = 1e3 (where exp(y^2) leaves even this
// format's range) its asymptotic series 1/(2y^2) - 3/(4y^4) + 15/(8y^6), exact to 1e-23 there.
double big_deficit(double y) {
  if (y > 1e3) {
    const double z = 1.0 / (y * y);
    return 0.5 * z - 0.75 * z * z + 1.875 * z * z * z;
  }
  const Big sqrt_pi = boost::multiprecision::sqrt(boost::math::constants::pi<Big>());
  return static_cast<double>(1 - sqrt_pi * Big(y) * big_erfcx(y));
}

}  // namespace

TEST_CASE("erfcx matches 50-digit arithmetic on both sides of its switch [0 <= y <= 1e4]",
          "[theory]") {
  for (const double y :
       {0.0, 1e-8, 0.1, 0.5, 1.0, 1.999, 2.0, 2.001, 3.0, 5.0, 10.0, 26.0, 27.0, 100.0, 1e3}) {
    INFO("y = " << y);
    REQUIRE_THAT(scaled_erfc(y),
                 WithinRel(static_cast<double>(big_erfcx(y)), test::k_special_function_rel));
  }
  REQUIRE(scaled_erfc(std::numeric_limits<double>::infinity()) == 0.0);
  REQUIRE_THROWS_AS(scaled_erfc(-1.0), ParameterError);
}

TEST_CASE("The deficit 1 - sqrt(pi) y erfcx(y) keeps full relative accuracy [y up to 1e6]",
          "[theory]") {
  // For y = 1e6 the deficit is 5e-13: formed as 1 - f it would keep 3 digits.
  for (const double y : {0.01, 1.0, 2.0, 2.5, 10.0, 1e3, 1e6}) {
    INFO("y = " << y);
    REQUIRE_THAT(growth_rate_deficit(y), WithinRel(big_deficit(y), test::k_special_function_rel));
  }
}

TEST_CASE("gamma solves eq:gammaKKc in 50-digit arithmetic [1.0001 <= K/K_c <= 1e12]", "[theory]") {
  const double sigma0 = 0.35;
  for (const double kappa : {1.0001, 1.01, 1.5, 2.0, 10.0, 1e3, 1e6, 1e12}) {
    const double y = growth_rate(kappa, sigma0) / (std::sqrt(2.0) * sigma0);
    INFO("K/K_c = " << kappa << ", y = " << y);
    // The deficit equation 1 - f(y) = K_c/K, each side to full precision.
    REQUIRE_THAT(big_deficit(y), WithinRel(1.0 / kappa, test::k_root_rel));
  }
}

TEST_CASE("gamma vanishes linearly as K -> K_c+ [K/K_c - 1 from 1e-2 to 1e-6]", "[theory]") {
  // Below 1e-6 the input itself limits the accuracy: 1 - K_c/K is known to eps / (K/K_c - 1).
  REQUIRE(growth_rate(1.0, 0.35) == 0.0);
  for (const double delta : {1e-2, 1e-4, 1e-6}) {
    const double kappa = 1.0 + delta;
    const double ratio = growth_rate(kappa, 0.35) / growth_rate_near_onset(kappa, 0.35);
    // f(y) = sqrt(pi) y - 2 y^2 + ...: the relative correction is (2/pi)(1 - K_c/K) < delta.
    INFO("K/K_c - 1 = " << delta << ", gamma / near-onset form = " << ratio);
    REQUIRE(std::abs(ratio - 1.0) <= delta);
  }
}

TEST_CASE("gamma approaches sigma0 sqrt(K/K_c) with the correction -3 K_c/(2K) [K/K_c to 1e8]",
          "[theory]") {
  for (const double kappa : {1e2, 1e4, 1e8}) {
    const double gamma = growth_rate(kappa, 0.35);
    const double leading = growth_rate_large_k(kappa, 0.35);
    const double corrected = growth_rate_large_k(kappa, 0.35, true);
    INFO("K/K_c = " << kappa << ": (gamma/leading - 1) K/K_c = " << (gamma / leading - 1) * kappa
                    << ", (gamma/corrected - 1) (K/K_c)^2 = "
                    << (gamma / corrected - 1) * kappa * kappa);
    // The leading form misses by -1.5 K_c/K; the corrected one by O((K_c/K)^2).
    REQUIRE_THAT((gamma / leading - 1.0) * kappa, Catch::Matchers::WithinAbs(-1.5, 10.0 / kappa));
    REQUIRE(std::abs(gamma / corrected - 1.0) * kappa * kappa <= 10.0);
  }
}

TEST_CASE("gamma scales with sigma0 and depends on the network only through K/K_c [any sigma0]",
          "[theory]") {
  for (const double kappa : {1.1, 3.0, 50.0}) {
    const double unit = growth_rate(kappa, 1.0);
    for (const double sigma0 : {0.01, 0.35, 7.0}) {
      REQUIRE_THAT(growth_rate(kappa, sigma0), WithinRel(sigma0 * unit, 1e-14));
    }
  }
}

TEST_CASE("gamma refuses K below K_c and a non-positive sigma0 [bad input]", "[theory]") {
  REQUIRE_THROWS_AS(growth_rate(0.99, 0.35), ParameterError);
  REQUIRE_THROWS_AS(growth_rate(2.0, 0.0), ParameterError);
  REQUIRE_THROWS_AS(growth_rate(std::nan(""), 0.35), ParameterError);
  REQUIRE_THROWS_AS(growth_rate(std::numeric_limits<double>::infinity(), 0.35), ParameterError);
}
