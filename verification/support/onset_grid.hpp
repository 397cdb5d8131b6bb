#pragma once
// The K grid of an onset sweep and its one refinement (onset_sweep.hpp): pure functions of the
// measured points, so the rule is unit-tested (tests/verification/test_onset_grid.cpp).
//
// Why refine: the onset fit needs >= 3 equilibrated points whose excess E = sqrt(<R>^2 - R0^2)
// lies in [k_window_low, k_window_high]. Where the finite-size floor R0 is high (small mean degree:
// R0 = 0.20 and 0.28 for ER <d> = 20 and 10 at N = 10^4, full scale) the window is reached only
// at x ~ 1.3-1.6, and a grid fixed in advance for every network (1.2, 1.35, 1.5, 2) can put only
// two points in it (measured: ER <d> = 10, 20 and SF alpha 3.8 at full scale). A grid fine
// enough for every network everywhere would cost ~4 min per point per network at N = 10^4.
// Rule (stated, not by eye): after the sweep, every pair of adjacent grid points (x_a, x_b)
// whose excess interval [min(E_a, E_b), max(E_a, E_b)] overlaps the window and whose midpoint
// lies above 1 (points at x <= 1 have no growing mode and are never equilibrated) gets its
// midpoint; done once, only when the first sweep left fewer than 3 points in the window.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace hmfnet::verification {

constexpr double k_window_low = 0.1;
constexpr double k_window_high = 0.35;
constexpr int k_minimum_fit_points = 3;

/// E = sqrt(max(<R>^2 - R0^2, 0)): the floor removed in quadrature (onset_sweep.hpp).
inline double excess(double R, double R0) { return std::sqrt(std::max(R * R - R0 * R0, 0.0)); }

inline bool in_window(double E) { return E >= k_window_low && E <= k_window_high; }

/// The midpoints the refinement rule adds to the increasing grid x with excesses E (sorted).
inline std::vector<double> refinement_points(const std::vector<double>& x,
                                             const std::vector<double>& E) {
  std::vector<double> added;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double mid = 0.5 * (x[k] + x[k + 1]);
    const double lo = std::min(E[k], E[k + 1]), hi = std::max(E[k], E[k + 1]);
    if (mid > 1.0 && hi >= k_window_low && lo <= k_window_high) added.push_back(mid);
  }
  return added;
}

/// The grid of the refinement sweep: the original points up to and including the first one
/// above every added midpoint (the sweep continues the state, so it must pass through them),
/// merged with the midpoints (x itself when there are none). The original points beyond it are
/// kept from the first sweep.
inline std::vector<double> refined_prefix(const std::vector<double>& x,
                                          const std::vector<double>& added) {
  if (added.empty()) return x;
  std::vector<double> grid;
  const double last = added.back();
  for (const double v : x) {
    grid.push_back(v);
    if (v > last) break;
  }
  grid.insert(grid.end(), added.begin(), added.end());
  std::sort(grid.begin(), grid.end());
  return grid;
}

}  // namespace hmfnet::verification
