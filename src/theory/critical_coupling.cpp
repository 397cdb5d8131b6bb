#include "theory/critical_coupling.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace hmfnet {

double critical_coupling(double sigma0, double n, double lambda) {
  if (!(sigma0 > 0.0) || !std::isfinite(sigma0)) {
    throw ParameterError("sigma0", std::to_string(sigma0), "sigma0 > 0");
  }
  if (!(n >= 1.0)) throw ParameterError("N", std::to_string(n), "N >= 1");
  if (!(lambda > 0.0) || !std::isfinite(lambda)) {
    throw ParameterError("lambda", std::to_string(lambda), "lambda > 0 (a network with edges)");
  }
  return 2.0 * sigma0 * sigma0 * n / lambda;
}

double critical_coupling(MomentumDistribution g, double sigma0, double n, double lambda) {
  const double gaussian = critical_coupling(sigma0, n, lambda);
  if (g == MomentumDistribution::gaussian) return gaussian;
  const double D = waterbag_half_width(sigma0);
  return 2.0 * D * D * n / lambda;
}

}  // namespace hmfnet
