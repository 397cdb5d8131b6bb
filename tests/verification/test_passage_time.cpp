// The relaxation-time rule of qss_lifetime and near_onset_gap
// (verification/support/passage_time.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "support/passage_time.hpp"

using namespace hmfnet::verification;

TEST_CASE("replica_mean averages the chosen columns of a slice", "[passage_time]") {
  // 3 records x 2 replicas, row-major.
  const std::vector<double> R{1.0, 3.0, 2.0, 4.0, 5.0, 7.0};
  const ReplicaSeries s{&R, 2, 1, 3};
  CHECK(replica_mean(s, {0, 1}) == std::vector<double>{3.0, 6.0});
  CHECK(replica_mean(s, {1, 1}) == std::vector<double>{4.0, 7.0});
  CHECK(window_mean(std::vector<double>{1.0, 2.0, 6.0}, 1, 3) == 4.0);
}

TEST_CASE("half_way_passage finds a step's centre, either way, and NaN without one",
          "[passage_time]") {
  // Records at t = 1, 2, ..., 100 (t0 = 0, dt = 1): 0 up to t = 40, then 1.
  std::vector<double> up(100, 0.0);
  for (std::size_t i = 40; i < up.size(); ++i) up[i] = 1.0;
  // A running mean over 10 records reaches 0.5 when 5 of its 10 records are ones: the window
  // of records t = 36 .. 45, reported at t = 45 - 10 / 2 = 40 (the step is between 40 and 41).
  CHECK(half_way_passage(up, 0.0, 1.0, 10, 1.0) == 40.0);
  std::vector<double> down(up.size());
  for (std::size_t i = 0; i < up.size(); ++i) down[i] = 1.0 - up[i];
  CHECK(half_way_passage(down, 0.0, 1.0, 10, 0.0) == 40.0);
  // Shifted time axis and spacing.
  CHECK(half_way_passage(up, 100.0, 0.5, 10, 1.0) == 120.0);
  // The target is never reached half way: 0 -> 1 aimed at 3 needs 1.5.
  CHECK(std::isnan(half_way_passage(up, 0.0, 1.0, 10, 3.0)));
  CHECK(std::isnan(half_way_passage(up, 0.0, 1.0, 100, 1.0)));  // no room for a window
}

TEST_CASE("bootstrap_passage: identical replicas give no spread, distinct ones do, seeded",
          "[passage_time]") {
  // 4 replicas stepping at t = 20, 30, 40, 50 (records t = 1 .. 100).
  const std::size_t records = 100, B = 4;
  std::vector<double> R(records * B, 0.0), same(records * B, 0.0);
  for (std::size_t i = 0; i < records; ++i) {
    for (std::size_t b = 0; b < B; ++b) {
      R[i * B + b] = i >= 20 + 10 * b ? 1.0 : 0.0;
      same[i * B + b] = i >= 30 ? 1.0 : 0.0;
    }
  }
  const auto rule = [](const std::vector<double>& mean) {
    return half_way_passage(mean, 0.0, 1.0, 4, 1.0);
  };
  const Passage fixed = bootstrap_passage({&same, B, 0, records}, rule, 50, 7);
  CHECK(fixed.time == 30.0);
  CHECK(fixed.se == 0.0);
  CHECK(fixed.passed == 50);
  const Passage spread = bootstrap_passage({&R, B, 0, records}, rule, 200, 7);
  CHECK(spread.time > 30.0);
  CHECK(spread.time < 40.0);
  CHECK(spread.se > 2.0);  // resamples range from all-early (t = 20) to all-late (t = 50)
  CHECK(spread.se < 15.0);
  const Passage again = bootstrap_passage({&R, B, 0, records}, rule, 200, 7);
  CHECK(again.se == spread.se);
}

TEST_CASE("power_law_fit recovers an exponent and skips unusable points", "[passage_time]") {
  const std::vector<double> x{100, 200, 400, 800};
  std::vector<double> y, se;
  for (const double n : x) {
    y.push_back(3.0 * std::pow(n, 1.7));
    se.push_back(0.1 * y.back());
  }
  PowerLaw fit = power_law_fit(x, y, se);
  CHECK(std::abs(fit.slope - 1.7) < 1e-12);
  CHECK(std::abs(fit.at(300.0) / (3.0 * std::pow(300.0, 1.7)) - 1.0) < 1e-12);
  // sigma(ln y) = 0.1 everywhere: the slope's se is 0.1 / sqrt(sum (ln x - mean)^2).
  double mean = 0.0, ss = 0.0;
  for (const double n : x) mean += std::log(n) / 4.0;
  for (const double n : x) ss += std::pow(std::log(n) - mean, 2);
  CHECK(std::abs(fit.slope_se - 0.1 / std::sqrt(ss)) < 1e-12);
  y[3] = NAN;
  fit = power_law_fit(x, y, se);
  CHECK(std::abs(fit.slope - 1.7) < 1e-12);
  CHECK(std::isnan(power_law_fit({100}, {5}, {1}).slope));
}
