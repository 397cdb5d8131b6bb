#pragma once
// The distribution g(p) of the initial momenta. The paper draws them Gaussian; its dispersion
// relation (eq:gDashPSGammaPlusOmega) holds for any g, and the all-to-all HMF literature starts
// from the water-bag, uniform on [Omega - D, Omega + D]. D = sqrt(3) sigma0, so that sigma0 is
// the standard deviation of both and the energy of the incoherent start is the same.
#include <string>

namespace hmfnet {

enum class MomentumDistribution { gaussian, waterbag };

/// "gaussian" or "waterbag"; throws ParameterError naming `option` and the allowed names.
MomentumDistribution parse_momentum_distribution(const std::string& name,
                                                 const std::string& option = "momenta");

/// The name parse_momentum_distribution reads.
const char* name_of(MomentumDistribution g);

/// Half-width D of the water-bag of standard deviation sigma0: sqrt(3) sigma0.
double waterbag_half_width(double sigma0);

}  // namespace hmfnet
