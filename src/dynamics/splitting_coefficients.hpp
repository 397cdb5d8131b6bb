#pragma once
// The coefficient tables of the kick-drift splittings (integrator.hpp: KickDriftSplitting),
// written once for the CPU integrators and the CUDA steppers (dynamics/cuda), which apply the
// same table: kick b_0 h, drift a_0 h, kick b_1 h, ..., drift a_{s-1} h, kick b_s h.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace hmfnet {

struct SplittingCoefficients {
  std::vector<double> kicks;   ///< b_0 .. b_s (one more than drifts)
  std::vector<double> drifts;  ///< a_0 .. a_{s-1}
};

/// Leap-frog (Verlet): half kick, drift, half kick.
inline SplittingCoefficients leap_frog_coefficients() { return {{0.5, 0.5}, {1.0}}; }

/// Yoshida's triple jump: leap-frog(w1 h) o leap-frog(w0 h) o leap-frog(w1 h), adjacent half
/// kicks merged (H. Yoshida, Phys. Lett. A 150, 262 (1990)).
inline SplittingCoefficients yoshida4_coefficients() {
  const double cube_root_2 = std::cbrt(2.0);
  const double w1 = 1.0 / (2.0 - cube_root_2);
  const double w0 = -cube_root_2 / (2.0 - cube_root_2);
  return {{0.5 * w1, 0.5 * (w1 + w0), 0.5 * (w0 + w1), 0.5 * w1}, {w1, w0, w1}};
}

/// Blanes & Moan, J. Comput. Appl. Math. 142, 313 (2002), Table 3, SRKN_6^b (b_i: kicks, a_i:
/// drifts).
inline SplittingCoefficients blanes_moan4_coefficients() {
  const double b1 = 0.0829844064174052;
  const double b2 = 0.396309801498368;
  const double b3 = -0.0390563049223486;
  const double b4 = 1.0 - 2.0 * (b1 + b2 + b3);
  const double a1 = 0.245298957184271;
  const double a2 = 0.604872665711080;
  const double a3 = 0.5 - (a1 + a2);
  return {{b1, b2, b3, b4, b3, b2, b1}, {a1, a2, a3, a3, a2, a1}};
}

/// The table of an integrator by its name (make_integrator's names): leapfrog, yoshida4,
/// blanes_moan; none for a method that is not a kick-drift splitting (rk4).
inline std::optional<SplittingCoefficients> splitting_coefficients(const std::string& name) {
  if (name == "leapfrog") return leap_frog_coefficients();
  if (name == "yoshida4") return yoshida4_coefficients();
  if (name == "blanes_moan") return blanes_moan4_coefficients();
  return std::nullopt;
}

}  // namespace hmfnet
