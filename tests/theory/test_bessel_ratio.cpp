// v(x) = I1(x)/I0(x) (eq:BesselRatio) against an independent evaluation, across the switch to the
// asymptotic series, and where I0 and I1 themselves overflow.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "support/tolerances.hpp"
#include "theory/bessel_ratio.hpp"

using namespace hmfnet;

namespace {

// Gauss's continued fraction I1/I0 = 1 / (2/x + 1 / (4/x + 1 / (6/x + ...))), evaluated bottom-up
// in long double from depth 2x + 200 (the tail is negligible once 2k/x >> 1). It shares nothing
// with the implementation (Boost's Bessel functions, Hankel's series).
double continued_fraction_ratio(double x) {
  const long double lx = x;
  const int depth = static_cast<int>(2.0 * x) + 200;
  long double t = 0.0L;
  for (int k = depth; k >= 1; --k) t = 1.0L / (2.0L * k / lx + t);
  return static_cast<double>(t);
}

std::vector<double> sample_points() {
  std::vector<double> x;
  for (double a = 1e-6; a < 1e4; a *= 1.37) x.push_back(a);
  for (double a = 45.0; a <= 55.0; a += 0.25) x.push_back(a);
  return x;
}

}  // namespace

TEST_CASE("v matches Gauss's continued fraction in long double [1e-6 <= x <= 1e4]", "[theory]") {
  double worst = 0.0, where = 0.0;
  for (const double x : sample_points()) {
    const double reference = continued_fraction_ratio(x);
    const double rel = std::abs(bessel_ratio(x) - reference) / reference;
    if (rel > worst) {
      worst = rel;
      where = x;
    }
  }
  INFO("largest relative difference " << worst << " at x = " << where);
  REQUIRE(worst <= test::k_special_function_rel);
}

TEST_CASE("v is continuous and increasing across the switch to the asymptotic series [x = 50]",
          "[theory]") {
  const double below = std::nextafter(k_bessel_ratio_switch, 0.0);
  const double above = std::nextafter(k_bessel_ratio_switch, 100.0);
  INFO("v(50-) = " << bessel_ratio(below) << ", v(50+) = " << bessel_ratio(above));
  // The true jump over two ulps of x is v'(50) * 1.4e-14 = 3e-18: anything visible is the switch.
  REQUIRE(std::abs(bessel_ratio(above) - bessel_ratio(below)) <=
          test::k_special_function_rel * bessel_ratio(above));
  double previous = bessel_ratio(49.0);
  for (double x = 49.0; x <= 51.0; x += 1.0 / 64.0) {
    const double v = bessel_ratio(x);
    REQUIRE(v >= previous);
    previous = v;
  }
}

TEST_CASE("v is odd with v(0) = 0 and the small-x slope 1/2 [x = 0 and tiny x]", "[theory]") {
  REQUIRE(bessel_ratio(0.0) == 0.0);
  REQUIRE_THAT(bessel_ratio(1e-300), Catch::Matchers::WithinRel(5e-301, 1e-15));
  REQUIRE_THAT(bessel_ratio(1e-5), Catch::Matchers::WithinRel(5e-6 - 1e-15 / 16, 1e-15));
  for (const double x : sample_points()) REQUIRE(bessel_ratio(-x) == -bessel_ratio(x));
}

TEST_CASE("v stays finite and follows its asymptotic series where I0 overflows [x >= 713]",
          "[theory]") {
  // v = 1 - 1/(2x) - 1/(8x^2) - 1/(8x^3) - 25/(128x^4) - ...: the first four terms leave
  // an error below 25/(128 x^4) <= 8e-13 for x >= 700.
  for (const double x : {713.0, 800.0, 1e4, 1e8, 1e300}) {
    const double expected = 1.0 - 1.0 / (2 * x) - 1.0 / (8 * x * x) - 1.0 / (8 * x * x * x);
    INFO("x = " << x);
    REQUIRE_THAT(bessel_ratio(x), Catch::Matchers::WithinAbs(expected, 1e-12));
  }
  REQUIRE(bessel_ratio(std::numeric_limits<double>::infinity()) == 1.0);
  REQUIRE(bessel_ratio(-std::numeric_limits<double>::infinity()) == -1.0);
  REQUIRE(std::isnan(bessel_ratio(std::nan(""))));
}

TEST_CASE("v satisfies v' = 1 - v/x - v^2 [central differences 0.1 <= x <= 300]", "[theory]") {
  // The identity follows from I0' = I1 and I1' = I0 - I1/x. A central difference with step
  // h = 1e-4 x has truncation error ~h^2 v''' and round-off ~eps/h: 1e-6 relative covers both.
  for (double x = 0.1; x <= 300.0; x *= 1.5) {
    const double h = 1e-4 * x;
    const double fd = (bessel_ratio(x + h) - bessel_ratio(x - h)) / (2.0 * h);
    const double v = bessel_ratio(x);
    INFO("x = " << x);
    REQUIRE_THAT(fd, Catch::Matchers::WithinRel(1.0 - v / x - v * v, 1e-6));
  }
}
