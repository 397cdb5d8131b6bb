#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "theory/onset_amplitude.hpp"

using namespace hmfnet;

TEST_CASE("G = sqrt(2/5) for a regular graph (constant u / lambda = ||d||)", "[theory]") {
  const std::vector<double> u(1000, 0.03);
  REQUIRE_THAT(onset_amplitude(7.0, 7.0, u), Catch::Matchers::WithinRel(std::sqrt(0.4), 1e-14));
}

TEST_CASE("G does not depend on the normalisation of u / even at extreme scales", "[theory]") {
  std::vector<double> u;
  for (int k = 1; k <= 500; ++k) u.push_back(1.0 + 0.01 * k);
  const double g = onset_amplitude(10.0, 9.0, u);
  for (const double s : {1e-200, 1e-3, 1e150}) {
    std::vector<double> scaled = u;
    for (auto& x : scaled) x *= s;
    REQUIRE_THAT(onset_amplitude(10.0, 9.0, scaled), Catch::Matchers::WithinRel(g, 1e-13));
  }
}

TEST_CASE("G decreases as u becomes heterogeneous (two-valued u)", "[theory]") {
  // u = 1 on half the nodes, a on the other half: closed form
  // m1 = (1+a)/2, m2 = (1+a^2)/2, m4 = (1+a^4)/2.
  for (const double a : {1.0, 2.0, 5.0}) {
    std::vector<double> u(200, 1.0);
    for (std::size_t k = 100; k < 200; ++k) u[k] = a;
    const double m1 = (1 + a) / 2, m2 = (1 + a * a) / 2, m4 = (1 + a * a * a * a) / 2;
    const double expected = std::sqrt(2 * m2 * m1 * m1 / (m4 + 4 * m2 * m2));
    REQUIRE_THAT(onset_amplitude(1.0, 1.0, u), Catch::Matchers::WithinRel(expected, 1e-14));
  }
  std::vector<double> flat(200, 1.0), skewed(200, 1.0);
  skewed[0] = 50.0;
  REQUIRE(onset_amplitude(1.0, 1.0, skewed) < onset_amplitude(1.0, 1.0, flat));
}

TEST_CASE("Near-onset R = G sqrt(K/K_c - 1) above K_c and 0 below", "[theory]") {
  REQUIRE(onset_order_parameter(0.6, 0.5) == 0.0);
  REQUIRE(onset_order_parameter(0.6, 1.21) == Approx(0.6 * std::sqrt(0.21)));
}

TEST_CASE("G refuses an empty or zero Perron vector", "[theory]") {
  REQUIRE_THROWS(onset_amplitude(1.0, 1.0, {}));
  REQUIRE_THROWS(onset_amplitude(1.0, 1.0, {0.0, 0.0}));
}
