#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "theory/critical_coupling.hpp"

using namespace hmfnet;

TEST_CASE("K_c = 2 sigma0^2 N / lambda (eq:criticalKFirstOrder)", "[theory]") {
  // All-to-all with self-loops: lambda = N, so K_c = 2 sigma0^2 = 2 T (canonical HMF, T_c = 1/2
  // at K = 1 corresponds to sigma0^2 = 1/2).
  REQUIRE(critical_coupling(std::sqrt(0.5), 1000, 1000) == Approx(1.0).epsilon(1e-15));
  // Paper, Fig. Assumptions1: ER N = 10^4, lambda ~ 101, sigma0^2 = 1 gives K_c ~ 198 (K = 600 =
  // 3 K_c up to the paper's rounding).
  REQUIRE(critical_coupling(1.0, 1e4, 101.0) == Approx(198.02).epsilon(1e-4));
  REQUIRE_THROWS_AS(critical_coupling(0.0, 10, 1), ParameterError);
  REQUIRE_THROWS_AS(critical_coupling(1.0, 10, 0), ParameterError);
}
