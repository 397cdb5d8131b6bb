// The refinement rule of the onset sweep's K grid (verification/support/onset_grid.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "support/onset_grid.hpp"

using namespace hmfnet::verification;

TEST_CASE("excess removes the floor in quadrature and is zero below it", "[onset_grid]") {
  CHECK(excess(0.5, 0.3) == 0.4);
  CHECK(excess(0.2, 0.3) == 0.0);
  CHECK(in_window(k_window_low));
  CHECK(in_window(k_window_high));
  CHECK_FALSE(in_window(0.099));
  CHECK_FALSE(in_window(0.351));
}

TEST_CASE("refinement adds midpoints exactly where the window lies between grid points",
          "[onset_grid]") {
  // The full-scale ER <d> = 10 sweep: only x = 1.35 and 1.5 had their excess in the window.
  const std::vector<double> x{0.0, 0.5, 0.9, 1.1, 1.2, 1.35, 1.5, 2.0, 3.0};
  const std::vector<double> E{0.0, 0.0, 0.03, 0.05, 0.08, 0.15, 0.30, 0.50, 0.70};
  const std::vector<double> added = refinement_points(x, E);
  REQUIRE(added.size() == 3);
  CHECK(std::abs(added[0] - 1.275) < 1e-15);  // [0.08, 0.15] overlaps the window
  CHECK(std::abs(added[1] - 1.425) < 1e-15);  // [0.15, 0.30] inside it
  CHECK(std::abs(added[2] - 1.75) < 1e-15);   // [0.30, 0.50] overlaps it
  // The refined sweep runs up to 2.0, the first original point above every midpoint.
  const std::vector<double> grid = refined_prefix(x, added);
  const std::vector<double> expected{0.0, 0.5, 0.9, 1.1, 1.2, 1.275, 1.35, 1.425, 1.5, 1.75, 2.0};
  CHECK(grid == expected);
}

TEST_CASE("refinement adds no midpoint at or below the threshold or away from the window",
          "[onset_grid]") {
  // A floor fluctuation crossing the window below x = 1: no growing mode there, no midpoint.
  const std::vector<double> x{0.0, 0.9, 1.1, 3.0};
  const std::vector<double> E{0.0, 0.12, 0.02, 0.8};
  const std::vector<double> added = refinement_points(x, E);
  REQUIRE(added.size() == 1);
  CHECK(added[0] == 2.05);
  // Excess never reaches the window (no onset in the grid): nothing to add.
  CHECK(refinement_points({0.0, 1.2, 1.5}, {0.0, 0.02, 0.05}).empty());
  // Non-monotone excess (noise) still brackets by min and max.
  CHECK(refinement_points({1.2, 1.4}, {0.5, 0.05}).size() == 1);
  CHECK(refined_prefix({0.0, 1.0}, {}).size() == 2);
}
