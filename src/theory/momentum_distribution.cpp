#include "theory/momentum_distribution.hpp"

#include <cmath>

#include "core/error.hpp"

namespace hmfnet {

MomentumDistribution parse_momentum_distribution(const std::string& name,
                                                 const std::string& option) {
  if (name == "gaussian") return MomentumDistribution::gaussian;
  if (name == "waterbag") return MomentumDistribution::waterbag;
  throw ParameterError(option, name, "gaussian, waterbag");
}

const char* name_of(MomentumDistribution g) {
  return g == MomentumDistribution::waterbag ? "waterbag" : "gaussian";
}

double waterbag_half_width(double sigma0) { return std::sqrt(3.0) * sigma0; }

}  // namespace hmfnet
