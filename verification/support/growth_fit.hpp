#pragma once
// The growth-rate fit of the drivers that measure how R(t) leaves the incoherent state
// (growth_rate: Gaussian momenta, Fig. growthRate; waterbag_threshold: water-bag momenta), and
// the reference rate of one replica's own momentum sample. The window rule is stated and argued
// in verification/growth_rate.cpp's header.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "dynamics/rotor_state.hpp"
#include "theory/dispersion_relation.hpp"

namespace hmfnet::verification {

struct Fit {
  double slope = 0.0, intercept = 0.0, t1 = 0.0, t2 = 0.0;
  double efolds = 0.0;  ///< gamma (t2 - t1): e-folds of the theory's growth inside the window
  bool usable = false;
};

/// Least squares of log R on records [a, b].
inline Fit least_squares(const std::vector<double>& t, const std::vector<double>& R, std::size_t a,
                         std::size_t b) {
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double m = static_cast<double>(b - a + 1);
  for (std::size_t i = a; i <= b; ++i) {
    const double y = std::log(R[i]);
    st += t[i];
    sy += y;
    stt += t[i] * t[i];
    sty += t[i] * y;
  }
  Fit f;
  f.slope = (m * sty - st * sy) / (m * stt - st * st);
  f.intercept = (sy - f.slope * st) / m;
  f.t1 = t[a];
  f.t2 = t[b];
  return f;
}

/// The stated window rule: log of the excess over the finite-size floor R(0), from the excess
/// reaching the floor (and t >= t_min) to R reaching half its saturated level (the mean of the
/// last 30%). t_min: where the growing mode is seeded by the floor itself (water-bag momenta: no
/// Landau damping, R ~ R(0) cosh(gamma t) in the linear regime) the excess grows as
/// sinh(gamma t), whose log-slope gamma coth(gamma t) exceeds gamma by 42% where the excess
/// reaches the floor (gamma t = 0.88) and by 0.5% from gamma t = 3: such callers pass 3 / gamma.
inline Fit fit_growth(const std::vector<double>& t, const std::vector<double>& R, double gamma,
                      double t_min = 0.0) {
  const std::size_t n = R.size(), tail = n - (3 * n) / 10;
  double sat = 0.0;
  for (std::size_t i = tail; i < n; ++i) sat += R[i] / static_cast<double>(n - tail);
  const double floor = R[0];
  std::vector<double> excess(n);
  for (std::size_t i = 0; i < n; ++i) {
    excess[i] = std::sqrt(std::max(R[i] * R[i] - floor * floor, 1e-6 * floor * floor));
  }
  std::size_t begin = 0, end = 0;
  while (begin < n && (excess[begin] < floor || t[begin] < t_min)) ++begin;
  while (end < n && R[end] < 0.5 * sat) ++end;
  Fit f;
  if (end > begin + 2) {
    f = least_squares(t, excess, begin, end - 1);
    f.usable = true;
  }
  f.efolds = f.usable ? gamma * (f.t2 - f.t1) : 0.0;
  return f;
}

/// gamma of eq:lambdaHat for one replica's own initial momenta (any distribution), on a network
/// of n nodes with largest eigenvalue lambda; NaN if the root is not found.
inline double sample_growth_rate(NodeIndex n, double K, double lambda, const InitialCondition& ic,
                                 double gamma_guess) {
  const RotorState s = initial_state(0, n, {ic});
  const DispersionRoot root = solve_independent_dispersion(K, lambda, s.p, {gamma_guess, ic.omega});
  return root.converged ? root.s.real() : NAN;
}

}  // namespace hmfnet::verification
