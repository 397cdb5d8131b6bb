#include "theory/onset_amplitude.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace hmfnet {

double onset_amplitude(double lambda, double mean_degree, const std::vector<double>& u) {
  if (u.empty()) {
    throw ParameterError("onset amplitude G: Perron vector", "empty", "one entry per node");
  }
  if (!(mean_degree > 0.0)) {
    throw ParameterError("onset amplitude G: mean degree", std::to_string(mean_degree), "> 0");
  }
  // Scale by max|u| first so u^4 neither overflows nor underflows; G is scale invariant.
  double largest = 0.0;
  for (const double x : u) largest = std::max(largest, std::abs(x));
  if (largest == 0.0) {
    throw ParameterError("onset amplitude G: Perron vector", "all zero", "a nonzero vector");
  }
  double m1 = 0.0, m2 = 0.0, m4 = 0.0;
  for (const double x : u) {
    const double y = x / largest;
    m1 += y;
    m2 += y * y;
    m4 += y * y * y * y;
  }
  const double n = static_cast<double>(u.size());
  m1 /= n;
  m2 /= n;
  m4 /= n;
  return lambda / mean_degree * std::sqrt(2.0 * m2 * m1 * m1 / (m4 + 4.0 * m2 * m2));
}

double onset_order_parameter(double G, double K_over_Kc) {
  return K_over_Kc <= 1.0 ? 0.0 : G * std::sqrt(K_over_Kc - 1.0);
}

}  // namespace hmfnet
