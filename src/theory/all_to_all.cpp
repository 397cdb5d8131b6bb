#include "theory/all_to_all.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "theory/bessel_ratio.hpp"

namespace hmfnet {

namespace {

template <class F>
double bracketed_root(F f, double lo, double hi) {
  std::uintmax_t max_iter = 200;
  const auto root = boost::math::tools::toms748_solve(
      f, lo, hi, boost::math::tools::eps_tolerance<double>(52), max_iter);
  return 0.5 * (root.first + root.second);
}

}  // namespace

double all_to_all_order_parameter(double K_over_Kc) {
  if (!(K_over_Kc >= 0.0) || !std::isfinite(K_over_Kc)) {
    throw ParameterError("K/K_c", std::to_string(K_over_Kc), "0 <= K/K_c < inf");
  }
  if (K_over_Kc <= 1.0) return 0.0;
  const double kappa = K_over_Kc;
  // phi(R) = v(x(R)) - R is positive between 0 and the root (slope kappa - 1 at 0) and negative
  // at R = 1 (v < 1): start the bracket at the near-onset estimate sqrt(2/5) sqrt(kappa - 1) / 2
  // (eq:globalOrderRInDeltaK, G = sqrt(2/5)) and halve until phi > 0.
  auto phi = [kappa](double R) {
    return bessel_ratio(2.0 * kappa * R / (1.0 + 2.0 * kappa * R * R)) - R;
  };
  double lo = std::min(0.5, 0.5 * std::sqrt(0.4 * (kappa - 1.0)));
  for (int k = 0; k < 200 && !(phi(lo) > 0.0); ++k) lo *= 0.5;
  if (!(phi(lo) > 0.0)) return 0.0;  // kappa - 1 below double resolution of phi
  return bracketed_root(phi, lo, 1.0);
}

double all_to_all_variance_ratio(double K_over_Kc) {
  const double R = all_to_all_order_parameter(K_over_Kc);
  return 1.0 + 2.0 * K_over_Kc * R * R;
}

double all_to_all_large_k_order_parameter() {
  // v(1/R) - R falls from ~1 at R -> 0 to v(1) - 1 < 0 at R = 1.
  return bracketed_root([](double R) { return bessel_ratio(1.0 / R) - R; }, 1e-3, 1.0);
}

}  // namespace hmfnet
