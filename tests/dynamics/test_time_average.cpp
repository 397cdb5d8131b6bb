#include <catch2/catch.hpp>
#include <cmath>

#include "core/random.hpp"
#include "dynamics/time_average.hpp"

using namespace hmfnet;

TEST_CASE("Batch means give the iid standard error within 4 sigma of its estimate [n=1e5]",
          "[time_average]") {
  const std::int64_t n = 100000;
  BatchMeans bm(n, 50, 1);
  Rng rng(4);
  for (std::int64_t k = 0; k < n; ++k) bm.add({rng.normal()});
  const double sem = bm.standard_error()[0], expected = 1.0 / std::sqrt(double(n));
  INFO("SEM " << sem << " expected " << expected);
  // The SEM from B = 50 batch means has relative sd 1/sqrt(2 (B-1)) = 0.10.
  REQUIRE(std::abs(sem / expected - 1.0) < 4 * 0.101);
  REQUIRE(std::abs(bm.mean()[0]) < 4 * expected);
}

TEST_CASE("Batch means widen the error for correlated samples [AR(1) phi=0.9]", "[time_average]") {
  // AR(1) x_k = phi x_{k-1} + e_k with unit-variance e: the SEM of the mean is
  // sqrt((1+phi)/(1-phi) / (1-phi^2) / n) for long series.
  const std::int64_t n = 200000;
  const double phi = 0.9;
  BatchMeans bm(n, 50, 1);
  Rng rng(5);
  double x = 0.0;
  for (std::int64_t k = 0; k < n; ++k) {
    x = phi * x + rng.normal();
    bm.add({x});
  }
  const double expected = std::sqrt((1 + phi) / (1 - phi) / (1 - phi * phi) / double(n));
  INFO("SEM " << bm.standard_error()[0] << " expected " << expected);
  REQUIRE(std::abs(bm.standard_error()[0] / expected - 1.0) < 4 * 0.101);
}

TEST_CASE("Batch means sizes cover every sample once [uneven split]", "[time_average]") {
  BatchMeans bm(103, 10, 2);
  for (int k = 0; k < 103; ++k) bm.add({1.0, double(k)});
  REQUIRE(bm.mean()[0] == 1.0);
  REQUIRE(bm.mean()[1] == Approx(51.0));
  REQUIRE(bm.standard_error()[0] == 0.0);
  REQUIRE_THROWS(bm.add({1.0, 1.0}));
}
