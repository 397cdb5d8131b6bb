#pragma once
// The integrator and step of the paper pipeline at paper scale (--scale full), per grid point
// x = K / K_c: the cheapest method whose error in <R>_t stayed within half the statistical floor
// of the paper's averaging window in the full-scale work-precision run (verification/
// work_precision.cpp; paper/full/REPORT.md "Step per figure"; docs/choosing_a_method.md). That run
// measured ER N = 10^4, <d> = 100, sigma0 = 0.35 at x = 0.5, 1.5, 3 and SF alpha 2.8 at x = 3:
//   x <= 0.5        leapfrog    h = 0.32   (scene ER 0.5 K_c; leap-frog h = 0.01 costs 32x more)
//   0.5 < x <= 1.5  leapfrog    h = 0.16   (scene ER 1.5 K_c; the near-critical points between
//                                           the two scenes take the more demanding neighbour)
//   1.5 < x <= 3    blanes_moan h = 0.16   (scene ER 3 K_c: leap-frog needs h = 0.01 there)
//   3 < x <= 6      blanes_moan h = 0.08   (not measured: the error of a 4th-order method goes
//                                           as (h omega_max)^4, omega_max^2 = K max_n R_n
//                                           (simulation.cpp), which grows by at most
//                                           (x / 3)(R(x) / R(3)) <~ 2.4 up to x = 6, i.e. the
//                                           error by <~ 5.8 < 2^4 gained by halving h)
// Scale-free networks (capped Chung-Lu, as the scene): leap-frog 0.32 sufficed at 3 K_c; below,
// omega_max is smaller and the floor larger, so x <= 3 keeps it; 3 < x <= 6 halves it (leap-frog's
// error goes as (h omega_max)^2: x 2.4 at most, against 4). Measured near onset too, where <R>_t
// decides x_on (docs/scripts/sf_step_near_onset.sh: alpha 2.8, N = 10^4, the onset sweep's
// segments, 48 replicas per step): <R>_t averaged over x = 1.1-1.5 differs between h = 0.32 and
// 0.16 by -0.0010 +- 0.0022, i.e. x_on by <~ 0.02 (2 se). Networks of other kinds (rewired,
// communities) take ER's rule, the more demanding of the two.
// sigma0: K_c scales with sigma0^2 and R does not (eq:criticalKFirstOrder), so omega_max scales
// with sigma0 / 0.35: above 0.35 the step shrinks by that factor (halvings), below it is kept.
// Every step is then rounded down so that T and T1 are whole numbers of steps.
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "dynamics/step_choice.hpp"

namespace hmfnet::verification {

/// sigma0 of the work-precision scenes.
constexpr double k_scene_sigma0 = 0.35;

/// The largest h' <= h with duration / h' and transient / h' whole numbers, when both are whole
/// numbers of time units (h unchanged otherwise).
inline double whole_steps(double h, double duration, double transient) {
  const long long T = std::llround(duration), T1 = std::llround(transient);
  if (static_cast<double>(T) != duration || static_cast<double>(T1) != transient || T <= 0)
    return h;
  const double unit = static_cast<double>(std::gcd(T, T1));
  return unit / std::ceil(unit / h - 1e-9);
}

/// Which measured scene a network resembles.
enum class SceneFamily { erdos_renyi, scale_free };

/// The pipeline's method at x = K / K_c for the initial momentum spread sigma0.
inline StepChoice pipeline_step(double x, double sigma0, double duration, double transient,
                                SceneFamily family = SceneFamily::erdos_renyi) {
  if (!(x >= 0.0) || x > 6.0 || !(sigma0 > 0.0)) {
    throw std::invalid_argument("pipeline_step: x = " + std::to_string(x) + ", sigma0 = " +
                                std::to_string(sigma0) + " outside 0 <= x <= 6, sigma0 > 0");
  }
  StepChoice s;
  if (family == SceneFamily::scale_free) {
    s = x <= 3.0 ? StepChoice{"leapfrog", 0.32} : StepChoice{"leapfrog", 0.16};
  } else {
    s = x <= 0.5   ? StepChoice{"leapfrog", 0.32}
        : x <= 1.5 ? StepChoice{"leapfrog", 0.16}
        : x <= 3.0 ? StepChoice{"blanes_moan", 0.16}
                   : StepChoice{"blanes_moan", 0.08};
  }
  for (double f = sigma0 / k_scene_sigma0; f > 1.0 + 1e-12; f /= 2.0) s.h /= 2.0;
  s.h = whole_steps(s.h, duration, transient);
  return s;
}

/// The rule as JSON, for the drivers' notes (what produced their numbers).
inline std::string pipeline_step_note() {
  return R"({"rule": "verification/support/pipeline_step.hpp", "x <= 0.5": "leapfrog 0.32", )"
         R"("0.5 < x <= 1.5": "leapfrog 0.16", "1.5 < x <= 3": "blanes_moan 0.16", )"
         R"("3 < x <= 6": "blanes_moan 0.08", "scale-free": "leapfrog 0.32 to x = 3, )"
         R"(0.16 to x = 6", "sigma0 > 0.35": "halved per factor 2 of )"
         R"(sigma0 / 0.35", "rounding": "down to whole steps per T and T1"})";
}

}  // namespace hmfnet::verification
