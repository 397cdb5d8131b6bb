#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/random.hpp"
#include "support/tolerances.hpp"

using hmfnet::Rng;

TEST_CASE("Rng streams are reproducible and distinct [seed / stream]", "[random]") {
  Rng a(42, 7), b(42, 7), c(42, 8), d(43, 7);
  int same_c = 0, same_d = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto x = a.next();
    REQUIRE(x == b.next());
    same_c += x == c.next();
    same_d += x == d.next();
  }
  REQUIRE(same_c == 0);
  REQUIRE(same_d == 0);
}

TEST_CASE("Rng uniform has mean 1/2 and variance 1/12 within 4 sigma [n=1e6]", "[random]") {
  Rng rng(1);
  const int n = 1000000;
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double u = rng.uniform();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    sum += u;
    sum2 += u * u;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  INFO("mean " << mean << " var " << var);
  // sd of the mean: sqrt(1/12 / n); sd of the variance estimate: sqrt((1/80 - 1/144) / n).
  REQUIRE(std::abs(mean - 0.5) < hmfnet::test::k_sigmas * std::sqrt(1.0 / 12.0 / n));
  REQUIRE(std::abs(var - 1.0 / 12.0) <
          hmfnet::test::k_sigmas * std::sqrt((1.0 / 80.0 - 1.0 / 144.0) / n));
}

TEST_CASE("Rng normal has mean 0 / variance 1 / kurtosis 3 within 4 sigma [n=1e6]", "[random]") {
  Rng rng(2);
  const int n = 1000000;
  double m1 = 0.0, m2 = 0.0, m4 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double z = rng.normal();
    m1 += z;
    m2 += z * z;
    m4 += z * z * z * z;
  }
  m1 /= n;
  m2 /= n;
  m4 /= n;
  INFO("m1 " << m1 << " m2 " << m2 << " m4 " << m4);
  const double s = hmfnet::test::k_sigmas;
  REQUIRE(std::abs(m1) < s * std::sqrt(1.0 / n));
  REQUIRE(std::abs(m2 - 1.0) < s * std::sqrt(2.0 / n));   // Var(z^2) = 2
  REQUIRE(std::abs(m4 - 3.0) < s * std::sqrt(96.0 / n));  // Var(z^4) = 105 - 9
}

TEST_CASE("Rng below is uniform on 0..bound-1 by a chi-square test [bound=10]", "[random]") {
  Rng rng(3);
  std::vector<int> count(10, 0);
  const int n = 100000;
  for (int k = 0; k < n; ++k) ++count[static_cast<std::size_t>(rng.below(10))];
  double chi2 = 0.0;
  for (const int c : count) chi2 += (c - n / 10.0) * (c - n / 10.0) / (n / 10.0);
  INFO("chi2 " << chi2);
  REQUIRE(chi2 < 27.88);  // chi-square, 9 degrees of freedom, p = 0.001
}
