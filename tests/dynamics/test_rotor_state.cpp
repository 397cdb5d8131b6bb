// The initial state: Gaussian or water-bag momenta with the stated mean and spread, seeded, and
// the same whatever the split of the rows over ranks.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "dynamics/rotor_state.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

constexpr double k_omega = 6.0, k_sigma0 = 0.35;

InitialCondition waterbag(std::uint64_t seed) {
  return {k_omega, k_sigma0, seed, MomentumDistribution::waterbag};
}

}  // namespace

TEST_CASE("Water-bag momenta: inside omega +- sqrt(3) sigma0, mean omega, sd sigma0",
          "[rotor_state]") {
  const NodeIndex n = 200000;
  const RotorState s = initial_state(0, n, {waterbag(3)});
  const double D = std::sqrt(3.0) * k_sigma0;
  double sum = 0.0, lo = INFINITY, hi = -INFINITY;
  for (const double p : s.p) {
    sum += p;
    lo = std::min(lo, p);
    hi = std::max(hi, p);
  }
  const double mean = sum / n;
  double var = 0.0;
  for (const double p : s.p) var += (p - mean) * (p - mean) / (n - 1);
  REQUIRE(lo >= k_omega - D);
  REQUIRE(hi < k_omega + D);
  // Filled to the edges: the gap to each edge is of order D / N.
  REQUIRE(lo < k_omega - D + 1e-3);
  REQUIRE(hi > k_omega + D - 1e-3);
  // Tolerances: 4 standard errors. Mean: sigma0 / sqrt(N). Sample variance of a uniform:
  // sqrt((mu4 - sigma^4) / N) with mu4 = 9 sigma^4 / 5, i.e. sigma0^2 sqrt(0.8 / N).
  REQUIRE(std::abs(mean - k_omega) < 4.0 * k_sigma0 / std::sqrt(double(n)));
  REQUIRE(std::abs(var - k_sigma0 * k_sigma0) < 4.0 * k_sigma0 * k_sigma0 * std::sqrt(0.8 / n));
}

TEST_CASE("Initial states are seeded and independent of the row split [both distributions]",
          "[rotor_state]") {
  const NodeIndex n = 1000, cut = 377;
  for (const auto g : {MomentumDistribution::gaussian, MomentumDistribution::waterbag}) {
    const InitialCondition a{k_omega, k_sigma0, 11, g}, b{k_omega, k_sigma0, 12, g};
    const RotorState whole = initial_state(0, n, {a, b});
    REQUIRE(test::bit_difference(initial_state(0, n, {a, b}).p, whole.p) == "");
    REQUIRE(initial_state(0, n, {b}).p != initial_state(0, n, {a}).p);
    const RotorState first = initial_state(0, cut, {a, b});
    const RotorState second = initial_state(cut, n - cut, {a, b});
    std::vector<double> theta = first.theta, p = first.p;
    theta.insert(theta.end(), second.theta.begin(), second.theta.end());
    p.insert(p.end(), second.p.begin(), second.p.end());
    REQUIRE(test::bit_difference(theta, whole.theta) == "");
    REQUIRE(test::bit_difference(p, whole.p) == "");
  }
  // The phases do not depend on the momentum distribution (theta is drawn first).
  REQUIRE(initial_state(0, n, {waterbag(5)}).theta ==
          initial_state(0, n, {{k_omega, k_sigma0, 5}}).theta);
}

TEST_CASE("A water-bag of zero width is refused naming sigma0", "[rotor_state]") {
  REQUIRE_THROWS_WITH(initial_state(0, 10, {{k_omega, 0.0, 1, MomentumDistribution::waterbag}}),
                      Catch::Contains("sigma0") && Catch::Contains("water-bag"));
}
